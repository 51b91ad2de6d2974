#include "andros/base/output_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <random>

#include "andros/base/error.hpp"
#include "andros/base/write_fully.hpp"

namespace andros {
namespace {

namespace fs = std::filesystem;

/// Written out once this much is buffered.
constexpr std::size_t kBufferBytes = std::size_t{64} * 1024;
/// Links followed before giving up, as the kernel does (ELOOP).
constexpr int kMaxLinks = 40;
/// How long a FIFO is given to get a reader (one started just after the
/// command, `cat FIFO &`), and how often it is asked.
constexpr int kFifoReaderWaitMs = 5000;
constexpr int kFifoReaderPollMs = 50;

/// A FIFO opened for writing once it has a reader: an open that would block
/// for ever without one (no stop request could end it) is tried without
/// blocking until kFifoReaderWaitMs have passed. -1 and errno, ENXIO: no reader came.
int open_fifo(const std::string& path) {
  for (int waited = 0;; waited += kFifoReaderPollMs) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC | O_NONBLOCK);
    if (fd >= 0) {
      // Written like any other file from here: a reader that is slow is waited for.
      ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
      return fd;
    }
    if (errno != ENXIO || waited >= kFifoReaderWaitMs) return -1;
    ::usleep(kFifoReaderPollMs * 1000);
  }
}

int write_all(int fd, std::string_view text) { return write_fully(fd, text); }

/// Where path's symbolic links lead: the file a rename must replace (the
/// link itself is kept). A dangling link gives the name it points to.
std::string follow_links(std::string path) {
  for (int hops = 0; hops < kMaxLinks; ++hops) {
    struct stat st {};
    if (::lstat(path.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return path;
    std::error_code ec;
    const fs::path to = fs::read_symlink(path, ec);
    if (ec) return path;
    path = to.is_absolute() ? to.string() : (fs::path(path).parent_path() / to).string();
  }
  errno = ELOOP;
  throw std::system_error(ELOOP, std::generic_category());
}

std::string random_suffix() {
  static std::mt19937_64 random{std::random_device{}() ^ static_cast<std::uint64_t>(::getpid())};
  static constexpr char kChars[] = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
  std::string out(6, 'x');
  for (auto& c : out) c = kChars[random() % (sizeof kChars - 1)];
  return out;
}

}  // namespace

OutputFile::OutputFile(std::string path, WriteFn write_fn, NewFile new_file)
    : path_(std::move(path)), write_(write_fn ? write_fn : write_all) {
  if (path_ == "-") {
    fd_ = STDOUT_FILENO;
    return;
  }
  const auto cannot_open = [&](int error) {
    return RuntimeError("cannot open " + quote_name(path_) + " for writing: " + std::strerror(error));
  };
  struct stat st {};
  if (::stat(path_.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) throw cannot_open(EISDIR);
    if (!S_ISREG(st.st_mode)) {
      // A device, FIFO or socket: written where it is, never truncated, removed or replaced.
      fd_ = S_ISFIFO(st.st_mode) ? open_fifo(path_) : ::open(path_.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
      if (fd_ < 0 && errno == ENXIO && S_ISFIFO(st.st_mode)) {
        throw RuntimeError("cannot open " + quote_name(path_) + " for writing: a FIFO that no reader opened in " +
                           std::to_string(kFifoReaderWaitMs / 1000) + " s (start its reader first)");
      }
      if (fd_ < 0) throw cannot_open(errno);
      own_fd_ = true;
      return;
    }
  } else if (errno != ENOENT) {
    throw cannot_open(errno);
  }
  std::string target;
  try {
    target = follow_links(path_);
  } catch (const std::system_error& e) {
    throw cannot_open(e.code().value());
  }
  const bool exists = ::stat(path_.c_str(), &st) == 0;
  if (!exists && new_file == NewFile::kAsWritten) {
    fd_ = ::open(target.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOCTTY | O_CLOEXEC, 0666);
    if (fd_ < 0) throw cannot_open(errno);
    own_fd_ = true;
    return;
  }
  open_temporary(target, exists ? &st : nullptr);
  if (fd_ < 0) throw cannot_open(errno);
}

void OutputFile::open_temporary(const std::string& target, const struct stat* old) {
  const fs::path file(target);
  const fs::path folder = file.has_parent_path() ? file.parent_path() : fs::path(".");
  for (int attempt = 0; attempt < 100; ++attempt) {
    const auto name = (folder / ("." + file.filename().string() + "." + random_suffix())).string();
    // 0666 less the umask, as a new file gets; an old file's mode is given below.
    fd_ = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOCTTY | O_CLOEXEC, 0666);
    if (fd_ >= 0) {
      own_fd_ = true;
      target_ = target;
      temporary_ = name;
      break;
    }
    if (errno != EEXIST) return;
  }
  if (fd_ < 0 || old == nullptr) return;
  // The owner first: a change of owner clears set-user-ID bits the mode then gives back.
  // Both may be refused (not root, not in the group): the file keeps ours, as a new one would.
  if (::fchown(fd_, old->st_uid, old->st_gid) != 0 && ::fchown(fd_, static_cast<uid_t>(-1), old->st_gid) != 0) {
    // (a (void) cast does not silence gcc's warn_unused_result, which _FORTIFY_SOURCE puts on fchown)
  }
  (void)::fchmod(fd_, old->st_mode & 07777);
}

OutputFile::~OutputFile() {
  if (own_fd_ && fd_ >= 0) ::close(fd_);
  if (!temporary_.empty() && !committed_) ::unlink(temporary_.c_str());
}

std::string OutputFile::display() const { return path_ == "-" ? "standard output" : quote_name(path_); }

bool OutputFile::put(std::string_view text) {
  if (error_ != 0) return false;
  pending_.append(text);
  return pending_.size() < kBufferBytes || flush();
}

bool OutputFile::flush() {
  if (error_ != 0) return false;
  if (!pending_.empty()) {
    error_ = write_(fd_, pending_);
    pending_.clear();
  }
  return error_ == 0;
}

void OutputFile::fail_write(int error) const {
  throw RuntimeError("cannot write " + (path_ == "-" ? std::string("to standard output") : quote_name(path_)) + ": " +
                     std::strerror(error));
}

void OutputFile::write(std::string_view text) {
  if (!put(text)) fail_write(error_);
}

void OutputFile::check() const {
  if (error_ != 0) fail_write(error_);
}

void OutputFile::commit() {
  if (!flush()) fail_write(error_);
  if (temporary_.empty()) {
    if (own_fd_) {
      const int fd = fd_;
      fd_ = -1;
      if (::close(fd) != 0 && errno != EINTR) fail_write(errno);
    }
    committed_ = true;
    return;
  }
  if (::fsync(fd_) != 0) fail_write(errno);
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0 && errno != EINTR) fail_write(errno);
  // What was a regular file (or nothing) when opened must still be one: a
  // device node put there since is never renamed over.
  struct stat st {};
  if (::lstat(target_.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
    throw RuntimeError("cannot write " + quote_name(path_) + ": it is no longer a regular file (left as it is)");
  }
  if (::rename(temporary_.c_str(), target_.c_str()) != 0) fail_write(errno);
  committed_ = true;
}

OutputFile::Buffer::int_type OutputFile::Buffer::overflow(int_type c) {
  if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
  const char ch = traits_type::to_char_type(c);
  return file_.put(std::string_view(&ch, 1)) ? c : traits_type::eof();
}

std::streamsize OutputFile::Buffer::xsputn(const char* s, std::streamsize n) {
  return file_.put(std::string_view(s, static_cast<std::size_t>(n))) ? n : 0;
}

int OutputFile::Buffer::sync() { return file_.flush() ? 0 : -1; }

void write_output_file(const std::string& path, std::string_view text, WriteFn write) {
  OutputFile file(path, write);
  file.write(text);
  file.commit();
}

}  // namespace andros
