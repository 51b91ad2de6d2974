#include "andros/record/record_sink.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "andros/base/error.hpp"
#include "andros/base/write_fully.hpp"

namespace andros::record {

FileRecordSink::FileRecordSink(const std::string& path) {
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_APPEND, 0640);
  if (fd_ < 0) throw RuntimeError(path + ": cannot create: " + std::strerror(errno));
  // Held until the file is closed: the session is being written.
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    ::close(fd_);
    fd_ = -1;
    throw RuntimeError(path + ": cannot lock: " + std::strerror(err));
  }
  if (rlimit limit{}; ::getrlimit(RLIMIT_FSIZE, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
    size_limit_ = limit.rlim_cur;
  }
}

FileRecordSink::~FileRecordSink() {
  if (fd_ >= 0) ::close(fd_);
}

bool FileRecordSink::write(std::string_view text, std::string& error) {
  const std::uint64_t after = whole_ + text.size();
  // Under a small limit, a quarter of it (4 KB allows 1 KB of closing records).
  if (size_limit_ != 0 && after + std::min(kClosingRoom, size_limit_ / 4) > size_limit_) {
    error = std::strerror(EFBIG);  // the limit's own words, before it is reached
    return false;
  }
  // The text's blocks and the room after them, taken before a byte is written.
  if (allocate_ahead_ && ::fallocate(fd_, FALLOC_FL_KEEP_SIZE, static_cast<off_t>(whole_),
                                     static_cast<off_t>(text.size() + kClosingRoom)) != 0) {
    if (errno == EOPNOTSUPP || errno == ENOSYS) {
      allocate_ahead_ = false;
    } else {
      error = std::strerror(errno);
      return false;
    }
  }
  return append(text, error);
}

bool FileRecordSink::write_closing(std::string_view text, std::string& error) { return append(text, error); }

bool FileRecordSink::append(std::string_view text, std::string& error) {
  if (broken_) {
    error = "the session could not be cut back to its last whole record";
    return false;
  }
  const int err = write_fully(fd_, text);
  if (err == 0) {
    whole_ += text.size();
    return true;
  }
  error = std::strerror(err);
  // What went out of a failed write is half a record at most whole: cut back.
  if (::ftruncate(fd_, static_cast<off_t>(whole_)) != 0) broken_ = true;
  return false;
}

bool FileRecordSink::sync(std::string& error) {
  if (::fdatasync(fd_) == 0) return true;
  error = std::strerror(errno);
  return false;
}

}  // namespace andros::record
