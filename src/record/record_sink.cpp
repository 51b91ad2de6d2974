#include "andros/record/record_sink.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

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
}

FileRecordSink::~FileRecordSink() {
  if (fd_ >= 0) ::close(fd_);
}

bool FileRecordSink::write(std::string_view text, std::string& error) {
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
