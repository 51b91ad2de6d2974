#pragma once
// Reading a session's lines (andros/record/session.hpp), for verify and read:
// within kMaxSessionLine, checked while reading (a longer line is refused
// before more of it is held), and a last line cut short (a write cut off,
// power lost, a full disk) told from an altered one.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string_view>

#include "andros/base/text_file.hpp"

namespace andros::record {

/// Splits `PAYLOAD HASH` (HASH: 64 hex digits); false when the line is not one.
bool split_record(std::string_view line, std::string_view& payload, std::string_view& hash);

/// The SEQ of a payload, or nullopt.
std::optional<std::uint64_t> seq_of(std::string_view payload);

class SessionLines {
 public:
  /// Opens a regular file (never waits on a FIFO or reads a device). Throws InputError.
  explicit SessionLines(const std::filesystem::path& path);
  /// The next line without its newline (valid until the next call), or
  /// nullopt at the end. Throws InputError at FILE:LINE for a line over kMaxSessionLine.
  std::optional<std::string_view> next();
  [[nodiscard]] int line_no() const { return text_.line_number(); }
  /// Whether `line`, the one next() returned last, which is not a whole
  /// record, is the file's end cut short: no newline after it, or nothing but
  /// NUL bytes to the end (blocks a power loss left unwritten). May read on.
  bool cut_short(std::string_view line);

 private:
  TextReader text_;
};

}  // namespace andros::record
