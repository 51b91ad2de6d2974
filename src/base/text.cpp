#include "andros/base/text.hpp"

#include <algorithm>
#include <charconv>
#include <string>

namespace andros {
namespace {

/// Characters that print nothing or reorder what follows: C1 controls, the
/// soft hyphen, zero-width and bidirectional marks, line and paragraph
/// separators, invisible operators, the BOM, interlinear annotations, tags,
/// and the noncharacters.
bool invisible(char32_t c) {
  return (c >= 0x80 && c <= 0x9F) || c == 0xAD || c == 0x061C || c == 0x180E || (c >= 0x200B && c <= 0x200F) ||
         (c >= 0x2028 && c <= 0x202E) || (c >= 0x2060 && c <= 0x206F) || c == 0xFEFF || (c >= 0xFFF9 && c <= 0xFFFB) ||
         (c >= 0xFDD0 && c <= 0xFDEF) || (c & 0xFFFE) == 0xFFFE || (c >= 0xE0000 && c <= 0xE007F);
}

/// The length of the valid UTF-8 sequence at the start of text (2..4), its
/// code point in c; 0 when it is not one (a stray continuation byte, an
/// overlong form, a surrogate, past U+10FFFF, cut short).
std::size_t utf8_sequence(std::string_view text, char32_t& c) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  const unsigned lead = byte(0);
  std::size_t n = 0;
  char32_t min = 0;
  if (lead >= 0xC2 && lead <= 0xDF) {
    n = 2;
    c = lead & 0x1FU;
    min = 0x80;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    n = 3;
    c = lead & 0x0FU;
    min = 0x800;
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    n = 4;
    c = lead & 0x07U;
    min = 0x10000;
  } else {
    return 0;
  }
  if (text.size() < n) return 0;
  for (std::size_t i = 1; i < n; ++i) {
    if ((byte(i) & 0xC0U) != 0x80U) return 0;
    c = (c << 6U) | (byte(i) & 0x3FU);
  }
  if (c < min || c > 0x10FFFF || (c >= 0xD800 && c <= 0xDFFF)) return 0;
  return n;
}

std::string escape(std::string_view text, bool backslash) {
  // Most text is printable ASCII already (every piece of every line the
  // status view draws, 5 times a second): copied whole.
  const bool as_is = std::all_of(text.begin(), text.end(), [backslash](char c) {
    const auto u = static_cast<unsigned char>(c);
    return u >= 0x20 && u < 0x7F && !(backslash && c == '\\');
  });
  if (as_is) return std::string(text);
  std::string out;
  out.reserve(text.size());
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    const auto u = static_cast<unsigned char>(c);
    if (c == '\\' && backslash) {
      out += "\\\\";
    } else if (u >= 0x20 && u < 0x7F) {
      out += c;
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\r') {
      out += "\\r";
    } else if (c == '\t') {
      out += "\\t";
    } else if (u >= 0x80) {
      char32_t code = 0;
      const std::size_t n = utf8_sequence(text.substr(i), code);
      if (n == 0) {
        out += "\\x" + hex_byte(u);
      } else {
        for (std::size_t k = 0; k < n; ++k) {
          if (invisible(code)) out += "\\x" + hex_byte(static_cast<std::uint8_t>(text[i + k]));
          else out += text[i + k];
        }
        i += n;
        continue;
      }
    } else {
      out += "\\x" + hex_byte(u);
    }
    ++i;
  }
  return out;
}

}  // namespace

std::string printable_text(std::string_view text) { return escape(text, true); }

std::string printable_line(std::string_view text) { return escape(text, false); }

bool is_printable_line(std::string_view text) { return printable_line(text) == text; }

std::string unescape_text(std::string_view text, const SourcePos& pos) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '\\') {
      out += text[i];
      continue;
    }
    const char next = i + 1 < text.size() ? text[i + 1] : '\0';
    if (next == '\\') out += '\\';
    else if (next == 'n') out += '\n';
    else if (next == 'r') out += '\r';
    else if (next == 't') out += '\t';
    else if (next == 'x' && i + 3 < text.size() && hex_value(text[i + 2]) >= 0 && hex_value(text[i + 3]) >= 0) {
      out += static_cast<char>(hex_value(text[i + 2]) * 16 + hex_value(text[i + 3]));
      i += 2;
    } else {
      SourcePos at = pos;
      if (at.column > 0) at.column += static_cast<int>(i);
      throw InputError(
          at, "unknown escape " + quote(text.substr(i, 2)) + " (a backslash starts \\\\, \\n, \\r, \\t or \\xNN)");
    }
    ++i;
  }
  return out;
}

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
    throw InputError(pos, "code " + quote(text) + " is not a byte in hex (one or two hex digits, e.g. 01 or 3C)");
  }
  return static_cast<std::uint8_t>(*value);
}

long long parse_integer(std::string_view text, long long min, long long max, std::string_view what,
                        const SourcePos& pos) {
  const auto value = to_integer(text);
  if (!value) throw InputError(pos, std::string(what) + " " + quote(text) + " is not a whole number");
  if (*value < min || *value > max) {
    throw InputError(pos, std::string(what) + " " + std::to_string(*value) + " is out of range " + std::to_string(min) +
                              ".." + std::to_string(max));
  }
  return *value;
}

}  // namespace andros
