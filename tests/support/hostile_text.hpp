#pragma once
// Issue 34's hostile strings, and what no output may hold of them: the
// oracle of the sinks' tests (base/sink_text.hpp), written from the issue's
// words, apart from base/text.cpp.

#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace andros::testing {

/// Text from outside as an attacker writes it: a newline and a forged
/// sessions row, ESC[2J, U+202E, a byte that is not UTF-8, a UTF-8 lead byte
/// alone, NUL, and spreadsheet formulas.
inline const std::array<std::string, 10> kHostileTexts = {
    std::string("x\n2024-01-01 00:00:00   0:00:01  HD1  226  FIRED  0  0  0  0  intact  forged"),
    std::string("\x1b[2Jcleared"),
    std::string("rtl\xe2\x80\xae"
                "evil"),  // U+202E, then "evil" shown reversed
    std::string("bad\xff"),
    std::string("cut\xc3"),
    std::string("nul\0byte", 8),
    std::string("=HYPERLINK(\"http://x\",\"y\")"),
    std::string("+1"),
    std::string("-1"),
    std::string("@SUM(1)"),
};

/// What in out would be obeyed or refused rather than shown: a control byte
/// (the newline too unless lines_ok), DEL, invalid UTF-8, a C1 control, a
/// bidirectional or invisible formatting character; nullopt when none.
inline std::optional<std::string> raw_text_in(std::string_view out, bool lines_ok = false) {
  const auto at = [&](std::size_t i) { return " at byte " + std::to_string(i) + " of '" + std::string(out) + "'"; };
  for (std::size_t i = 0; i < out.size();) {
    const auto b = static_cast<unsigned char>(out[i]);
    if (b < 0x80) {
      if ((b < 0x20 && !(lines_ok && b == '\n')) || b == 0x7F) return "control byte " + std::to_string(b) + at(i);
      ++i;
      continue;
    }
    const std::size_t n = b >= 0xF0 && b <= 0xF4 ? 4 : b >= 0xE0 ? 3 : b >= 0xC2 && b <= 0xDF ? 2 : 0;
    if (n == 0 || i + n > out.size()) return "invalid UTF-8" + at(i);
    char32_t c = b & (n == 2 ? 0x1F : n == 3 ? 0x0F : 0x07);
    for (std::size_t k = 1; k < n; ++k) {
      const auto next = static_cast<unsigned char>(out[i + k]);
      if ((next & 0xC0) != 0x80) return "invalid UTF-8" + at(i);
      c = (c << 6) | (next & 0x3F);
    }
    const char32_t min = n == 2 ? 0x80 : n == 3 ? 0x800 : 0x10000;
    if (c < min || c > 0x10FFFF || (c >= 0xD800 && c <= 0xDFFF)) return "invalid UTF-8" + at(i);
    if (c <= 0x9F || c == 0x061C || (c >= 0x200B && c <= 0x200F) || (c >= 0x202A && c <= 0x202E) ||
        (c >= 0x2066 && c <= 0x2069) || c == 0xFEFF) {
      return "invisible or bidirectional character" + at(i);
    }
    i += n;
  }
  return std::nullopt;
}

}  // namespace andros::testing
