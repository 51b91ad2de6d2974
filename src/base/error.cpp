#include "andros/base/error.hpp"

#include "andros/base/text.hpp"

namespace andros {
namespace {

bool printable(char c) { return c >= 0x20 && c < 0x7F; }

void append_escaped(std::string& out, unsigned char c) { out += "\\x" + hex_byte(c); }

std::string escaped(std::string_view text) {
  std::string out;
  for (const char c : text) {
    if (printable(c)) out += c;
    else append_escaped(out, static_cast<unsigned char>(c));
  }
  return out;
}

}  // namespace

std::string quote(std::string_view text) {
  std::string out = "'";
  for (const char c : text.substr(0, kMaxQuoted)) {
    if (c == '\\') out += "\\\\";
    else if (printable(c)) out += c;
    else append_escaped(out, static_cast<unsigned char>(c));
  }
  out += '\'';
  if (text.size() > kMaxQuoted) out += "... (" + std::to_string(text.size()) + " bytes)";
  return out;
}

std::string format_error(const SourcePos& pos, const std::string& message, std::string_view severity) {
  std::string out;
  if (!pos.file.empty()) {
    out += escaped(pos.file);
    if (pos.line > 0) {
      out += ':' + std::to_string(pos.line);
      if (pos.column > 0) out += ':' + std::to_string(pos.column);
    }
    out += ": ";
  }
  out += severity;
  out += ": ";
  out += escaped(message);
  return out;
}

InputError::InputError(SourcePos pos, const std::string& message)
    : std::runtime_error(format_error(pos, message)), pos_(std::move(pos)), message_(message) {}

}  // namespace andros
