#pragma once
/// Typed errors. Bad input (flags, config, mapping, event script, frame text)
/// is an InputError and exits 2; a failing device or file is a RuntimeError
/// and exits 1.

#include <stdexcept>
#include <string>
#include <string_view>

namespace andros {

inline constexpr int kExitOk = 0;
inline constexpr int kExitRuntime = 1;
inline constexpr int kExitBadInput = 2;

/// Where in a file bad input was found. line/column are 1-based; 0 = unknown.
struct SourcePos {
  std::string file;
  int line = 0;
  int column = 0;
};

/// Bad input from the user. what() is the one-line message the CLI prints:
/// `FILE:LINE:COL: error: WHAT` (the parts that are known).
class InputError : public std::runtime_error {
 public:
  InputError(SourcePos pos, const std::string& message);
  explicit InputError(const std::string& message) : InputError(SourcePos{}, message) {}

  [[nodiscard]] const SourcePos& pos() const { return pos_; }
  [[nodiscard]] const std::string& message() const { return message_; }

 private:
  SourcePos pos_;
  std::string message_;
};

/// A failure of the machine rather than the input: I/O, a device gone.
class RuntimeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Formats `FILE:LINE:COL: error: WHAT` (or another severity word, such as
/// `warning`), leaving out the unknown parts. The line is made one line of
/// printable text (printable_line() of base/text.hpp: a control byte, ESC, a
/// NUL that would end it, invalid UTF-8 as \xNN), so that it is printed whole
/// and nothing in it reaches the terminal raw.
std::string format_error(const SourcePos& pos, const std::string& message, std::string_view severity = "error");

/// How many bytes of a piece of input quote() shows before it cuts it short.
inline constexpr std::size_t kMaxQuoted = 64;

/// A piece of user input as an error shows it: in single quotes, escaped by
/// printable_text() (base/text.hpp: printable UTF-8 as is, a backslash
/// doubled, a newline as \n, any other control byte or invalid UTF-8 as \xNN,
/// a NUL or a UTF-8 BOM: \xEF\xBB\xBF), and at most kMaxQuoted bytes, then
/// `...` and the length.
std::string quote(std::string_view text);

/// A name (a file's, a serial port's, a controller's, a layer's) as an error
/// shows it: as quote(), but never cut, since the end of a path is the part
/// that tells two apart.
std::string quote_name(std::string_view name);

}  // namespace andros
