#include "andros/base/text.hpp"

#include <charconv>
#include <string>

namespace andros {

std::string_view trim(std::string_view text) {
  constexpr std::string_view kBlanks = " \t\r";
  const auto first = text.find_first_not_of(kBlanks);
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(kBlanks) - first + 1);
}

char to_lower(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }

char to_upper(char c) { return c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c; }

std::string to_lower(std::string_view text) {
  std::string out(text);
  for (auto& c : out) c = to_lower(c);
  return out;
}

std::string to_upper(std::string_view text) {
  std::string out(text);
  for (auto& c : out) c = to_upper(c);
  return out;
}

char hex_digit(unsigned value) { return "0123456789ABCDEF"[value & 0x0F]; }

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

std::string hex_byte(std::uint8_t value) { return {hex_digit(value >> 4U), hex_digit(value)}; }

std::optional<long long> to_integer(std::string_view text, int base) {
  long long value = 0;
  const auto* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value, base);
  if (text.empty() || ec != std::errc() || ptr != end) return std::nullopt;
  return value;
}

std::uint8_t parse_code(std::string_view text, const SourcePos& pos) {
  std::string_view digits = text;
  if (digits.size() > 2 && digits[0] == '0' && to_lower(digits[1]) == 'x') digits.remove_prefix(2);
  const auto value = to_integer(digits, 16);
  if (digits.size() > 2 || digits.starts_with('-') || !value) {
    throw InputError(pos, "code " + quote(text) +
                              " is not a byte in hex (one or two hex digits, e.g. 01 or 3C)");
  }
  return static_cast<std::uint8_t>(*value);
}

long long parse_integer(std::string_view text, long long min, long long max, std::string_view what,
                        const SourcePos& pos) {
  const auto value = to_integer(text);
  if (!value) throw InputError(pos, std::string(what) + " " + quote(text) + " is not a whole number");
  if (*value < min || *value > max) {
    throw InputError(pos, std::string(what) + " " + std::to_string(*value) + " is out of range " +
                              std::to_string(min) + ".." + std::to_string(max));
  }
  return *value;
}

}  // namespace andros
