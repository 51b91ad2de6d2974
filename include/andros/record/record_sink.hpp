#pragma once
/// Where the flight recorder's writer thread puts its chained lines
/// (docs/recording.md): a session file, or a test's sink that stalls or fails.

#include <cstdint>
#include <string>
#include <string_view>

namespace andros::record {

class RecordSink {
 public:
  virtual ~RecordSink() = default;
  /// Writes all of text (whole records); false with error set when it could
  /// not, and then none of text is left behind: the file ends at the last
  /// whole record written before.
  virtual bool write(std::string_view text, std::string& error) = 0;
  /// As write(), for the session's last word (a `dropped` record saying why
  /// recording stopped, the `end` record): it may use the room kept for it.
  virtual bool write_closing(std::string_view text, std::string& error) { return write(text, error); }
  /// Makes what was written durable (called about once a second); false with error set.
  virtual bool sync(std::string& error) = 0;
};

/// A session file, created (never overwritten) with mode 0640, and locked
/// (flock, exclusive) while it is open: rotation leaves a locked session alone.
///
/// Room for the last word: write() keeps kClosingRoom bytes after the file's
/// end for write_closing(), so that a full disk or a file-size limit never
/// takes the records that say so. On the disk, the room is allocated ahead
/// of the end (fallocate, FALLOC_FL_KEEP_SIZE: the file's length is
/// unchanged) before each write, and a write that would leave none fails as
/// a full disk's would (ENOSPC); under a file-size limit (RLIMIT_FSIZE), a
/// write that would reach into the last kClosingRoom bytes it allows (a
/// quarter of a limit under 16 KB) fails as the limit's would (EFBIG). A file system that cannot allocate ahead
/// (no fallocate) is written as before, without the room on the disk.
class FileRecordSink final : public RecordSink {
 public:
  /// What the session's closing records may take: a `dropped` record when
  /// recording stops, one at the end and the `end` record take about 400.
  static constexpr std::uint64_t kClosingRoom = 4096;

  /// Throws RuntimeError when the file cannot be created or locked.
  explicit FileRecordSink(const std::string& path);
  ~FileRecordSink() override;
  FileRecordSink(const FileRecordSink&) = delete;
  FileRecordSink& operator=(const FileRecordSink&) = delete;
  /// A write that fails part way (a full disk, a file-size limit: EFBIG) is
  /// cut back with ftruncate() to the last whole record.
  bool write(std::string_view text, std::string& error) override;
  bool write_closing(std::string_view text, std::string& error) override;
  bool sync(std::string& error) override;

 private:
  /// Appends text whole, or cuts the file back to its last whole record.
  bool append(std::string_view text, std::string& error);

  int fd_ = -1;
  std::uint64_t size_limit_ = 0;  ///< RLIMIT_FSIZE at creation (0: none)
  bool allocate_ahead_ = true;    ///< the file system allocates ahead (fallocate)
  std::uint64_t whole_ = 0;       ///< the file's length up to its last whole record
  bool broken_ = false;           ///< a failed write could not be cut back: nothing more is appended
};

}  // namespace andros::record
