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
  /// Makes what was written durable (called about once a second); false with error set.
  virtual bool sync(std::string& error) = 0;
};

/// A session file, created (never overwritten) with mode 0640, and locked
/// (flock, exclusive) while it is open: rotation leaves a locked session alone.
class FileRecordSink final : public RecordSink {
 public:
  /// Throws RuntimeError when the file cannot be created or locked.
  explicit FileRecordSink(const std::string& path);
  ~FileRecordSink() override;
  FileRecordSink(const FileRecordSink&) = delete;
  FileRecordSink& operator=(const FileRecordSink&) = delete;
  /// A write that fails part way (a full disk, a file-size limit: EFBIG) is
  /// cut back with ftruncate() to the last whole record.
  bool write(std::string_view text, std::string& error) override;
  bool sync(std::string& error) override;

 private:
  int fd_ = -1;
  std::uint64_t whole_ = 0;  ///< the file's length up to its last whole record
  bool broken_ = false;      ///< a failed write could not be cut back: nothing more is appended
};

}  // namespace andros::record
