#pragma once
/// Small text helpers and value parsers shared by the command line, the config
/// file, the event scripts, the mappings and the protocol, so that every
/// surface accepts (and shows) the same text.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "andros/base/error.hpp"

namespace andros {

/// text without leading and trailing blanks (space, tab, carriage return).
std::string_view trim(std::string_view text);

/// ASCII case conversion; other bytes are left as they are.
char to_lower(char c);
char to_upper(char c);
std::string to_lower(std::string_view text);
std::string to_upper(std::string_view text);

/// The upper-case hex digit of a value 0..15.
char hex_digit(unsigned value);
/// The value of a hex digit of either case, or -1 for any other byte.
int hex_value(char c);
/// A byte as two upper-case hex digits ("0A").
std::string hex_byte(std::uint8_t value);

/// The whole of text as a number in base (10 or 16), as std::from_chars reads
/// it (an optional '-', then digits); nullopt if anything else is there or it
/// does not fit.
std::optional<long long> to_integer(std::string_view text, int base = 10);

/// Text from outside (a controller's name from its USB descriptors, a file
/// name, a mapping's layer name) as one line of printable text, the one way
/// such text is written anywhere (terminal, log, event script, sheet): valid
/// printable UTF-8 as it is; a backslash as \\; newline, carriage return and
/// tab as \n, \r, \t; every other byte of a control character (NUL, ESC,
/// DEL, C1), of an invisible or bidirectional formatting character (U+200B..
/// U+200F, U+202A..U+202E, U+2066..U+2069, U+FEFF...) and of invalid UTF-8
/// as \xNN. unescape_text() gives the bytes back.
std::string printable_text(std::string_view text);

/// As printable_text(), but a backslash stays as it is: for a line made of
/// pieces already escaped (an error message with quoted names in it).
std::string printable_line(std::string_view text);

/// True when printable_line(text) == text: nothing in text would be escaped.
bool is_printable_line(std::string_view text);

/// The bytes printable_text() was made from: \\, \n, \r, \t and \xNN
/// decoded. Throws InputError at pos (its column moved to the backslash) for
/// any other escape.
std::string unescape_text(std::string_view text, const SourcePos& pos);

/// The dip-switch code: one or two hex digits, an optional 0x prefix ("01",
/// "3C", "0x3c"). Throws InputError at pos.
std::uint8_t parse_code(std::string_view text, const SourcePos& pos);

/// A whole decimal number in [min, max]. Throws InputError at pos naming what.
long long parse_integer(std::string_view text, long long min, long long max, std::string_view what,
                        const SourcePos& pos);

}  // namespace andros
