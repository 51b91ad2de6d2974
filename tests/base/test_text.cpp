#include <gtest/gtest.h>

#include <string>

#include "andros/base/text.hpp"
#include "support/input_error.hpp"

namespace andros {
namespace {

using testing::input_error_text;

TEST(Text, TrimTakesBlanksFromBothEnds) {
  EXPECT_EQ(trim(" \tkey = value\r"), "key = value");
  EXPECT_EQ(trim("word"), "word");
  EXPECT_EQ(trim(" \t\r "), "");
  EXPECT_EQ(trim(""), "");
  EXPECT_EQ(trim("\nx\n"), "\nx\n");  // only space, tab and carriage return
}

TEST(Text, CaseConversionIsAsciiOnly) {
  EXPECT_EQ(to_lower("WolVERine-1"), "wolverine-1");
  EXPECT_EQ(to_upper("hd1 rav"), "HD1 RAV");
  EXPECT_EQ(to_upper("\xC3\xA9"), "\xC3\xA9");  // UTF-8 bytes stay as they are
  EXPECT_EQ(to_lower('Q'), 'q');
  EXPECT_EQ(to_upper('@'), '@');
}

TEST(Text, HexDigitsBothWays) {
  for (unsigned v = 0; v < 16; ++v) {
    EXPECT_EQ(hex_value(hex_digit(v)), static_cast<int>(v));
    EXPECT_EQ(hex_value(to_lower(hex_digit(v))), static_cast<int>(v));
  }
  EXPECT_EQ(hex_digit(0x1A), 'A');  // the low nibble only
  EXPECT_EQ(hex_value('g'), -1);
  EXPECT_EQ(hex_value('/'), -1);
  EXPECT_EQ(hex_byte(0x0A), "0A");
  EXPECT_EQ(hex_byte(0xF1), "F1");
  EXPECT_EQ(hex_byte(0), "00");
}

TEST(Text, ToIntegerTakesTheWholeTextOrNothing) {
  EXPECT_EQ(to_integer("42"), 42);
  EXPECT_EQ(to_integer("-32768"), -32768);
  EXPECT_EQ(to_integer("3c", 16), 0x3C);
  EXPECT_EQ(to_integer("9223372036854775807"), INT64_MAX);
  EXPECT_FALSE(to_integer("9223372036854775808"));  // does not fit
  EXPECT_FALSE(to_integer(""));
  EXPECT_FALSE(to_integer("12a"));
  EXPECT_FALSE(to_integer(" 1"));
  EXPECT_FALSE(to_integer("+1"));
  EXPECT_FALSE(to_integer("3c"));  // decimal unless asked
}

TEST(Text, PrintableTextKeepsPrintableUtf8AndEscapesTheRest) {
  EXPECT_EQ(printable_text("Xbox Wireless Controller"), "Xbox Wireless Controller");
  EXPECT_EQ(printable_text("Manette caf\xC3\xA9 \xE2\x80\x93 \xE6\x97\xA5\xF0\x9F\x8E\xAE"),
            "Manette caf\xC3\xA9 \xE2\x80\x93 \xE6\x97\xA5\xF0\x9F\x8E\xAE");  // é, en dash, a CJK, an emoji
  EXPECT_EQ(printable_text("Gamepad\n500 button a 1\r\t#"), "Gamepad\\n500 button a 1\\r\\t#");
  EXPECT_EQ(printable_text(std::string("a\0b", 3)), "a\\x00b");
  EXPECT_EQ(printable_text("\x1B[2J\x1B]0;title\x07"), "\\x1B[2J\\x1B]0;title\\x07");
  EXPECT_EQ(printable_text("\x7F"), "\\x7F");
  EXPECT_EQ(printable_text("back\\slash"), "back\\\\slash");
  EXPECT_EQ(printable_text("\xC2\x9B"
                           "2J"),
            "\\xC2\\x9B2J");                                           // C1 CSI
  EXPECT_EQ(printable_text("\xEF\xBB\xBFpad"), "\\xEF\\xBB\\xBFpad");  // BOM
  EXPECT_EQ(printable_text("a\xE2\x80\xAE"
                           "z"),
            "a\\xE2\\x80\\xAEz");  // right-to-left override
  EXPECT_EQ(printable_text("a\xE2\x80\xA8"
                           "z"),
            "a\\xE2\\x80\\xA8z");                                                  // line separator
  EXPECT_EQ(printable_text("\xFF\xC3(\xE2\x82"), "\\xFF\\xC3(\\xE2\\x82");         // invalid, cut short
  EXPECT_EQ(printable_text("\xC0\xAF\xED\xA0\x80"), "\\xC0\\xAF\\xED\\xA0\\x80");  // overlong, surrogate
  EXPECT_EQ(printable_line("C:\\pad\n"), "C:\\pad\\n");                            // a backslash kept, the newline not
}

TEST(Text, UnescapeTextGivesBackTheBytes) {
  for (const std::string& raw : {std::string("Gamepad\n500 button leftshoulder 0\n#"), std::string("a\0b\x1B\\", 6),
                                 std::string("\xFF\xEF\xBB\xBFok \xC3\xA9")}) {
    EXPECT_EQ(unescape_text(printable_text(raw), SourcePos{}), raw);
  }
  EXPECT_EQ(unescape_text("\\x41\\x6a", SourcePos{}), "Aj");
  EXPECT_EQ(input_error_text([] {
              unescape_text("ab\\q", SourcePos{"x.events", 3, 10});
            }),
            "x.events:3:12: error: unknown escape '\\\\q' (a backslash starts \\\\, \\n, \\r, \\t or \\xNN)");
  EXPECT_NE(input_error_text([] { unescape_text("\\x4", SourcePos{}); }), "no error");
  EXPECT_NE(input_error_text([] { unescape_text("end\\", SourcePos{}); }), "no error");
}

TEST(Text, QuoteNameNeverCutsWhileQuoteCutsAPieceOfInput) {
  const std::string path = "/dev/serial/by-id/usb-FTDI_FT232R_USB_UART_A50285BI-if00-port0-and-more-to-tell-them-apart";
  EXPECT_EQ(quote_name(path), "'" + path + "'");
  EXPECT_EQ(quote(path), "'" + path.substr(0, kMaxQuoted) + "'... (" + std::to_string(path.size()) + " bytes)");
  EXPECT_EQ(quote_name("a\nb\x1B"), "'a\\nb\\x1B'");
}

TEST(Text, ParseCodeTakesOneOrTwoHexDigits) {
  EXPECT_EQ(parse_code("01", SourcePos{}), 0x01);
  EXPECT_EQ(parse_code("3C", SourcePos{}), 0x3C);
  EXPECT_EQ(parse_code("0x3c", SourcePos{}), 0x3C);
  EXPECT_EQ(parse_code("F", SourcePos{}), 0x0F);
  for (const char* bad : {"", "1FF", "-1", "-0", "0x", "0x100", "G1", "+1"}) {
    EXPECT_EQ(
        input_error_text([&] { parse_code(bad, SourcePos{"--code"}); }),
        "--code: error: code '" + std::string(bad) + "' is not a byte in hex (one or two hex digits, e.g. 01 or 3C)")
        << bad;
  }
}

TEST(Text, ParseIntegerNamesWhatAndWhere) {
  const SourcePos at{"a.events", 3, 14};
  EXPECT_EQ(parse_integer("-5", -10, 10, "axis value", at), -5);
  EXPECT_EQ(input_error_text([&] { parse_integer("40000", -32768, 32767, "axis value", at); }),
            "a.events:3:14: error: axis value 40000 is out of range -32768..32767");
  EXPECT_EQ(input_error_text([&] { parse_integer("4x", 0, 9, "time", at); }),
            "a.events:3:14: error: time '4x' is not a whole number");
  EXPECT_EQ(input_error_text([&] { parse_integer("99999999999999999999", 0, 9, "time", at); }),
            "a.events:3:14: error: time '99999999999999999999' is not a whole number");
}

}  // namespace
}  // namespace andros
