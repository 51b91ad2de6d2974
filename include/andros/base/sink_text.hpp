#pragma once
/// How each place the program writes to (a sink) shows text from outside: a
/// file name, a session's fields, a mapping's layer names and paths, a
/// controller's name, a link's detail. One function per sink, each built on
/// printable_text() (base/text.hpp), so that a control character, a
/// bidirectional override or invalid UTF-8 is shown as \xNN (a newline as
/// \n) on every sink, never obeyed: no forged table row or log line, no
/// cleared screen, no text reordered, no file a reader refuses.
/// docs/running.md ("Text from outside, on every output") lists the sinks.

#include <string>
#include <string_view>

namespace andros {

/// A field from outside in a command's table or line on a terminal (the
/// sessions table, check's FILE: ok, the controllers table, inputs' header):
/// printable_text(), lossless (a backslash as \\).
std::string terminal_text(std::string_view field);

/// A whole line the program made, for a terminal or the log (a log message,
/// an error's what(), verify's and replay's verdicts, a piece of the status
/// screen): printable_line(). The names in it were quoted (quote(),
/// printable_text()) when it was made, so a backslash stays; any byte still
/// raw (a path in a system error, a layer name logged as it is) is escaped.
std::string terminal_line(std::string_view line);

/// A JSON string from outside (sessions --format jsonl, export --format
/// jsonl, controllers --json): printable_text(), so that the JSON is valid
/// UTF-8 whatever the bytes (nlohmann's dump() throws on invalid UTF-8) and
/// unescape_text() gives the bytes back.
std::string json_text(std::string_view field);

/// A text cell of CSV (export): printable_line() (the cell's fields from
/// outside were made printable_text() when the cell was made: a layer's
/// name, a pad's description; nothing raw gets through either way); then
/// never a formula to a spreadsheet (OWASP's CSV injection: a cell that
/// starts with = + - @, a tab or a carriage return gets a leading
/// apostrophe, so "=1+1" is the text '=1+1); then quoted as RFC 4180 says
/// when it holds , " CR or LF.
std::string csv_cell(std::string_view field);

/// Text of an SVG element or attribute (the plot, the cheat sheet):
/// printable_line(), then & < > " ' as XML entities. Valid UTF-8 stays (an é
/// is an é); XML 1.0 forbids control characters, which are escaped first.
std::string svg_text(std::string_view text);

}  // namespace andros
