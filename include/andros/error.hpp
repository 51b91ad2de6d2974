#pragma once
/// Typed errors. Bad input (flags, config, mapping, event script, frame text)
/// is an InputError and exits 2; a failing device or file is a RuntimeError
/// and exits 1.

#include <stdexcept>
#include <string>

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

/// Formats `FILE:LINE:COL: error: WHAT`, leaving out the unknown parts.
std::string format_error(const SourcePos& pos, const std::string& message);

}  // namespace andros
