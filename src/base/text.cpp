#include "andros/base/text.hpp"

#include <charconv>
#include <string>

namespace andros {

std::uint8_t parse_code(std::string_view text, const SourcePos& pos) {
  std::string_view digits = text;
  if (digits.size() > 2 && digits[0] == '0' && (digits[1] == 'x' || digits[1] == 'X')) {
    digits.remove_prefix(2);
  }
  unsigned value = 0;
  const auto* end = digits.data() + digits.size();
  const auto [ptr, ec] = std::from_chars(digits.data(), end, value, 16);
  if (digits.empty() || digits.size() > 2 || ec != std::errc() || ptr != end) {
    throw InputError(pos, "code " + quote(text) +
                              " is not a byte in hex (one or two hex digits, e.g. 01 or 3C)");
  }
  return static_cast<std::uint8_t>(value);
}

long long parse_integer(std::string_view text, long long min, long long max, std::string_view what,
                        const SourcePos& pos) {
  long long value = 0;
  const auto* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value, 10);
  if (text.empty() || ec != std::errc() || ptr != end) {
    throw InputError(pos, std::string(what) + " " + quote(text) + " is not a whole number");
  }
  if (value < min || value > max) {
    throw InputError(pos, std::string(what) + " " + std::to_string(value) + " is out of range " +
                              std::to_string(min) + ".." + std::to_string(max));
  }
  return value;
}

}  // namespace andros
