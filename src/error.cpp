#include "andros/error.hpp"

namespace andros {

std::string format_error(const SourcePos& pos, const std::string& message) {
  std::string out;
  if (!pos.file.empty()) {
    out += pos.file;
    if (pos.line > 0) {
      out += ':' + std::to_string(pos.line);
      if (pos.column > 0) out += ':' + std::to_string(pos.column);
    }
    out += ": ";
  }
  out += "error: ";
  out += message;
  return out;
}

InputError::InputError(SourcePos pos, const std::string& message)
    : std::runtime_error(format_error(pos, message)), pos_(std::move(pos)), message_(message) {}

}  // namespace andros
