#include "andros/base/sink_text.hpp"

#include "andros/base/text.hpp"

namespace andros {

std::string terminal_text(std::string_view field) { return printable_text(field); }

std::string terminal_line(std::string_view line) { return printable_line(line); }

std::string json_text(std::string_view field) { return printable_text(field); }

std::string csv_cell(std::string_view field) {
  const std::string text = printable_line(field);
  std::string cell;
  if (!text.empty() && std::string_view("=+-@\t\r").find(text.front()) != std::string_view::npos) cell = "'";
  cell += text;
  if (cell.find_first_of(",\"\r\n") == std::string::npos) return cell;
  std::string out = "\"";
  for (const char c : cell) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string svg_text(std::string_view text) {
  std::string out;
  for (const char c : printable_line(text)) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace andros
