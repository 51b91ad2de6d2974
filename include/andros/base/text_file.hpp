#pragma once
/// The one way text inputs are read (event scripts, config files, mappings,
/// controller databases): line by line, within a size and a line-length
/// limit, refusing a directory, and waiting on a pipe or FIFO with poll() so
/// that a stop request ends the wait. docs/running.md lists the limits.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace andros {

/// What one kind of text input may hold. A line's length leaves out its newline.
struct TextLimits {
  std::string_view kind;  ///< "event script", for messages
  std::size_t max_bytes;
  std::size_t max_line;
};

inline constexpr std::size_t kKiB = 1024;
inline constexpr std::size_t kMiB = 1024 * kKiB;
inline constexpr std::size_t kMaxLineBytes = 4 * kKiB;

/// 256 MiB holds a day of recording at over 90 events a second (a stick moved
/// without pause on both axes makes 50): the cap is there to stop a runaway stream.
inline constexpr TextLimits kEventScriptLimits{"event script", 256 * kMiB, kMaxLineBytes};
inline constexpr TextLimits kConfigLimits{"config file", 64 * kKiB, kMaxLineBytes};
inline constexpr TextLimits kMappingLimits{"mapping file", 1 * kMiB, kMaxLineBytes};
inline constexpr TextLimits kControllerDbLimits{"controller database", 8 * kMiB, kMaxLineBytes};

/// Asked before each read and while a read waits for input; true abandons the
/// read with ReadStopped. Empty: never.
using StopCheck = std::function<bool()>;

/// A stop request arrived while a text input was being read.
class ReadStopped : public std::runtime_error {
 public:
  explicit ReadStopped(const std::string& file) : std::runtime_error(file + ": reading stopped by request") {}
};

/// Reads lines from a file, standard input or text in memory. Every error is
/// an InputError: FILE when it cannot be opened or is a directory, FILE:LINE
/// for a line over the limit or the line that takes the file over its size.
/// A failing read is a RuntimeError.
class TextReader {
 public:
  /// Opens path without blocking (a FIFO with no writer yet is waited for in next_line()).
  static TextReader open(const std::string& path, const TextLimits& limits, StopCheck stop = {});
  /// Opens path only if it is a regular file, for a read that must never
  /// wait: anything else (a pipe, a terminal, a socket, a device, a
  /// directory) is an InputError, `FILE: error: is a pipe, not a regular
  /// file`. Checked before opening (opening a device can have effects) and
  /// again on the opened descriptor (the path may have been swapped between).
  static TextReader open_regular(const std::string& path, const TextLimits& limits);
  /// Standard input, named "<stdin>"; not closed.
  static TextReader standard_input(const TextLimits& limits, StopCheck stop = {});
  /// Text already in memory, checked against the same limits.
  TextReader(std::string text, std::string name, const TextLimits& limits);

  ~TextReader();
  TextReader(TextReader&& other) noexcept;
  TextReader& operator=(TextReader&& other) noexcept;
  TextReader(const TextReader&) = delete;
  TextReader& operator=(const TextReader&) = delete;

  /// The next line without its newline (valid until the next call), or
  /// nullopt at the end of the input.
  std::optional<std::string_view> next_line();
  /// The number of the line next_line() returned last (1-based; 0 before the first).
  [[nodiscard]] int line_number() const { return line_no_; }
  /// Whether the line next_line() returned last ended with a newline (only
  /// the input's last line may not: a file cut short, or written without one).
  [[nodiscard]] bool line_ended() const { return line_ended_; }
  [[nodiscard]] const std::string& name() const { return name_; }
  [[nodiscard]] const TextLimits& limits() const { return limits_; }

  /// What is read, as messages say it: "a regular file", "a pipe", "a
  /// terminal", "a character device", "a socket", "text in memory"...
  [[nodiscard]] const std::string& kind() const { return kind_; }
  /// True when what is read is a regular file (not text in memory).
  [[nodiscard]] bool regular_file() const { return fd_ >= 0 && regular_; }
  /// True for text in memory and a regular file: rewind() can start over.
  [[nodiscard]] bool can_rewind() const { return fd_ < 0 || regular_; }
  /// Back to the first line. Only when can_rewind().
  void rewind();

 private:
  TextReader(int fd, bool owned, std::string name, const TextLimits& limits, StopCheck stop);
  /// Reads more into buf_; false at the end of the input.
  bool fill();
  void check_stop() const;
  [[noreturn]] void fail_line_too_long(int line) const;

  int fd_ = -1;  ///< -1: the text is all in buf_
  bool owned_ = false;
  bool regular_ = false;
  std::string kind_ = "text in memory";
  std::int64_t start_offset_ = 0;
  std::string name_;
  TextLimits limits_{};
  StopCheck stop_;
  std::string buf_;
  std::size_t pos_ = 0;   ///< first byte not yet returned
  std::size_t scan_ = 0;  ///< buf_ holds no newline in [pos_, scan_)
  bool eof_ = false;
  std::size_t consumed_ = 0;
  int line_no_ = 0;
  bool line_ended_ = true;
};

/// The rest of text's lines, each ended by a newline, checked as they are read.
std::string read_all(TextReader& text);

/// text's remaining lines held in memory, so that it can be rewound.
TextReader hold_in_memory(TextReader text);

/// A whole file within limits, for formats that are parsed as a whole (YAML).
std::string read_text_file(const std::string& path, const TextLimits& limits, const StopCheck& stop = {});

/// What is at path (a link followed), as messages say it: "a regular file",
/// "a directory", "a FIFO", "a socket", "a character device"...; "" when
/// nothing is there. Never opens it.
std::string path_kind(const std::string& path);

/// "64 KiB", "256 MiB", "4096 bytes": a limit as the messages and docs say it.
std::string format_size(std::size_t bytes);

}  // namespace andros
