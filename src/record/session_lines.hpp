#pragma once
// Reading a session's lines (andros/record/session.hpp), for the one reading
// (read_checked_session): within kMaxSessionLine, checked while reading (a
// longer line is refused before more of it is held), and a last line cut
// short (a write cut off, power lost, a full disk) told from an altered one;
// each line's place in the chain (session_verify.cpp) and its record
// (session_read.cpp).

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "andros/base/error.hpp"
#include "andros/base/text_file.hpp"
#include "andros/record/session.hpp"

namespace andros::record {

/// Splits `PAYLOAD HASH` (HASH: 64 hex digits); false when the line is not one.
bool split_record(std::string_view line, std::string_view& payload, std::string_view& hash);

/// The SEQ of a payload, or nullopt.
std::optional<std::uint64_t> seq_of(std::string_view payload);

class SessionLines {
 public:
  /// Opens a regular file (never waits on a FIFO or reads a device:
  /// require_session_file()). Throws InputError.
  explicit SessionLines(const std::filesystem::path& path);
  /// The next line without its newline (valid until the next call), or
  /// nullopt at the end. Throws InputError at FILE:LINE for a line over kMaxSessionLine.
  std::optional<std::string_view> next();
  [[nodiscard]] int line_no() const { return text_.line_number(); }
  /// Whether the line next() returned last ended with its newline: one
  /// without is never a whole record, whatever it holds.
  [[nodiscard]] bool ended() const { return text_.line_ended(); }
  /// Whether `line`, the one next() returned last, and all after it are NUL
  /// bytes (blocks a power loss left unwritten; a newline among them
  /// aside): their count; nullopt when something else follows. Reads on.
  std::optional<std::uint64_t> nul_tail(std::string_view line);

 private:
  TextReader text_;
};

/// The chain, line after line: verify's half of the one reading.
class ChainCheck {
 public:
  explicit ChainCheck(std::filesystem::path path) : path_(std::move(path)) {}
  /// "" when line (line number at) is the next record, chained to the one
  /// before, and takes it; else the first problem, as verify says it.
  std::string take(std::string_view line, int at);
  [[nodiscard]] std::uint64_t records() const { return records_; }
  [[nodiscard]] const std::string& last_hash() const { return last_hash_; }
  /// The last record taken is an end record.
  [[nodiscard]] bool closed() const { return closed_; }

 private:
  std::filesystem::path path_;
  Sha256Digest prev_{};
  std::uint64_t records_ = 0;
  std::string last_hash_;
  bool closed_ = false;
};

/// A session's records into a Session, one line at a time: read's half of
/// the one reading. Each throws InputError at FILE:LINE for a record it
/// cannot read.
class RecordReader {
 public:
  RecordReader(const std::filesystem::path& path, Keep keep) : keep_(keep) { s_.path = path.string(); }
  void read(std::string_view line, const SourcePos& pos);
  /// The session read. Throws InputError for one without its settings.
  Session finish() &&;

 private:
  /// Keep::kVerdict: what a later record's checks and the verdict need, no more.
  void forget();

  Keep keep_;
  Session s_;
  std::optional<SessionSettings> pending_;  ///< a reload's settings, until its reload record
  bool last_dropped_ = false;               ///< the last record read is a `dropped` one
  bool out_of_room_ = false;                ///< a `dropped` record said the disk or a file-size limit was full
  std::int64_t room_tick_ = -1;             ///< where recording stopped (Session::stopped_for_room)
  std::optional<InputError> spacing_;       ///< Keep::kVerdict: the first frame records too far apart
};

}  // namespace andros::record
