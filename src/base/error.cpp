#include "andros/base/error.hpp"

#include "andros/base/text.hpp"

namespace andros {

std::string quote(std::string_view text) {
  std::string out = "'" + printable_text(text.substr(0, kMaxQuoted)) + "'";
  if (text.size() > kMaxQuoted) out += "... (" + std::to_string(text.size()) + " bytes)";
  return out;
}

std::string quote_name(std::string_view name) { return "'" + printable_text(name) + "'"; }

std::string format_error(const SourcePos& pos, const std::string& message, std::string_view severity) {
  std::string out;
  if (!pos.file.empty()) {
    out += printable_line(pos.file);
    if (pos.line > 0) {
      out += ':' + std::to_string(pos.line);
      if (pos.column > 0) out += ':' + std::to_string(pos.column);
    }
    out += ": ";
  }
  out += severity;
  out += ": ";
  out += printable_line(message);
  return out;
}

InputError::InputError(SourcePos pos, const std::string& message)
    : std::runtime_error(format_error(pos, message)), pos_(std::move(pos)), message_(message) {}

}  // namespace andros
