#include "andros/base/text_file.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <utility>

#include "andros/base/error.hpp"

namespace andros {
namespace {

constexpr std::size_t kChunk = 64 * kKiB;
/// How often a read that waits on a pipe asks whether to stop.
constexpr int kStopPollMs = 100;

std::string with_article(std::string_view kind) {
  const bool vowel = !kind.empty() && std::string_view("aeiou").find(kind.front()) != std::string_view::npos;
  return std::string(vowel ? "an " : "a ") + std::string(kind);
}

/// A file's type as messages say it; fd (-1: not open) tells a terminal from other character devices.
std::string file_kind(const struct stat& st, int fd) {
  if (S_ISREG(st.st_mode)) return "a regular file";
  if (S_ISDIR(st.st_mode)) return "a directory";
  if (S_ISFIFO(st.st_mode)) return "a pipe";
  if (S_ISSOCK(st.st_mode)) return "a socket";
  if (S_ISCHR(st.st_mode)) return fd >= 0 && ::isatty(fd) == 1 ? "a terminal" : "a character device";
  if (S_ISBLK(st.st_mode)) return "a block device";
  return "not a regular file";
}

[[noreturn]] void fail_not_regular(const std::string& path, const std::string& kind) {
  throw InputError(SourcePos{path}, "is " + kind + ", not a regular file");
}

}  // namespace

std::string path_kind(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return {};
  // A pipe that has a name: a FIFO (mkfifo).
  return S_ISFIFO(st.st_mode) ? "a FIFO" : file_kind(st, -1);
}

std::string format_size(std::size_t bytes) {
  if (bytes != 0 && bytes % kMiB == 0) return std::to_string(bytes / kMiB) + " MiB";
  if (bytes != 0 && bytes % kKiB == 0) return std::to_string(bytes / kKiB) + " KiB";
  return std::to_string(bytes) + (bytes == 1 ? " byte" : " bytes");
}

TextReader TextReader::open(const std::string& path, const TextLimits& limits, StopCheck stop) {
  // Non-blocking, so that opening a FIFO does not wait for a writer (nor a
  // serial device for its carrier) where no stop request could end the wait.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
  if (fd < 0) {
    throw InputError(SourcePos{path}, "cannot read the " + std::string(limits.kind) + ": " + std::strerror(errno));
  }
  return TextReader(fd, true, path, limits, std::move(stop));
}

TextReader TextReader::open_regular(const std::string& path, const TextLimits& limits) {
  struct stat st {};
  // stat() follows a symbolic link, as open() does; a path that is missing is left to open() to report.
  if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) fail_not_regular(path, file_kind(st, -1));
  TextReader reader = open(path, limits);
  if (!reader.regular_) fail_not_regular(path, reader.kind_);
  return reader;
}

TextReader TextReader::standard_input(const TextLimits& limits, StopCheck stop) {
  return TextReader(STDIN_FILENO, false, "<stdin>", limits, std::move(stop));
}

TextReader::TextReader(std::string text, std::string name, const TextLimits& limits)
    : name_(std::move(name)), limits_(limits), buf_(std::move(text)), eof_(true) {}

TextReader::TextReader(int fd, bool owned, std::string name, const TextLimits& limits, StopCheck stop)
    : fd_(fd), owned_(owned), name_(std::move(name)), limits_(limits), stop_(std::move(stop)) {
  struct stat st {};
  if (::fstat(fd_, &st) != 0) {
    const int err = errno;
    if (owned_) ::close(fd_);
    throw InputError(SourcePos{name_}, "cannot read the " + std::string(limits.kind) + ": " + std::strerror(err));
  }
  if (S_ISDIR(st.st_mode)) {
    if (owned_) ::close(fd_);
    throw InputError(SourcePos{name_}, "is a directory, not " + with_article(limits.kind));
  }
  regular_ = S_ISREG(st.st_mode);
  kind_ = file_kind(st, fd_);
  if (regular_) start_offset_ = ::lseek(fd_, 0, SEEK_CUR);
}

TextReader::~TextReader() {
  if (owned_ && fd_ >= 0) ::close(fd_);
}

TextReader::TextReader(TextReader&& other) noexcept { *this = std::move(other); }

TextReader& TextReader::operator=(TextReader&& other) noexcept {
  if (this == &other) return *this;
  if (owned_ && fd_ >= 0) ::close(fd_);
  fd_ = std::exchange(other.fd_, -1);
  owned_ = std::exchange(other.owned_, false);
  regular_ = other.regular_;
  kind_ = std::move(other.kind_);
  start_offset_ = other.start_offset_;
  name_ = std::move(other.name_);
  limits_ = other.limits_;
  stop_ = std::move(other.stop_);
  buf_ = std::move(other.buf_);
  pos_ = other.pos_;
  scan_ = other.scan_;
  eof_ = other.eof_;
  consumed_ = other.consumed_;
  line_no_ = other.line_no_;
  line_ended_ = other.line_ended_;
  return *this;
}

void TextReader::check_stop() const {
  if (stop_ && stop_()) throw ReadStopped(name_);
}

void TextReader::fail_line_too_long(int line) const {
  throw InputError(SourcePos{name_, line}, "line longer than " + format_size(limits_.max_line) + " (the limit for " +
                                               with_article(limits_.kind) + ")");
}

bool TextReader::fill() {
  if (fd_ < 0) return false;
  // Only a partial line (at most max_line bytes) is kept from before.
  buf_.erase(0, pos_);
  scan_ -= pos_;
  pos_ = 0;
  while (true) {
    check_stop();
    if (!regular_) {
      pollfd p{fd_, POLLIN, 0};
      const int ready = ::poll(&p, 1, stop_ ? kStopPollMs : -1);
      if (ready == 0 || (ready < 0 && errno == EINTR)) continue;
      if (ready < 0) throw RuntimeError(name_ + ": cannot read: " + std::strerror(errno));
    }
    const auto old = buf_.size();
    buf_.resize(old + kChunk);
    const auto n = ::read(fd_, buf_.data() + old, kChunk);
    buf_.resize(old + static_cast<std::size_t>(n > 0 ? n : 0));
    if (n > 0) return true;
    if (n == 0) return false;
    if (errno == EAGAIN || errno == EINTR) continue;
    throw RuntimeError(name_ + ": cannot read: " + std::strerror(errno));
  }
}

std::optional<std::string_view> TextReader::next_line() {
  while (true) {
    const auto nl = buf_.find('\n', scan_);
    std::string_view line;
    const bool ended = nl != std::string::npos;
    if (ended) {
      line = std::string_view(buf_).substr(pos_, nl - pos_);
    } else {
      scan_ = buf_.size();
      if (buf_.size() - pos_ > limits_.max_line) fail_line_too_long(line_no_ + 1);
      if (!eof_) {
        eof_ = !fill();
        continue;
      }
      if (pos_ == buf_.size()) return std::nullopt;
      line = std::string_view(buf_).substr(pos_);
    }
    ++line_no_;
    line_ended_ = ended;
    if (line.size() > limits_.max_line) fail_line_too_long(line_no_);
    consumed_ += line.size() + (ended ? 1 : 0);
    if (consumed_ > limits_.max_bytes) {
      throw InputError(SourcePos{name_, line_no_}, "more than " + format_size(limits_.max_bytes) + " (the limit for " +
                                                       with_article(limits_.kind) + ")");
    }
    pos_ += line.size() + (ended ? 1 : 0);
    scan_ = pos_;
    return line;
  }
}

void TextReader::rewind() {
  if (!can_rewind()) throw std::logic_error(name_ + ": a stream cannot be rewound");
  if (fd_ >= 0) {
    if (::lseek(fd_, start_offset_, SEEK_SET) < 0) {
      throw RuntimeError(name_ + ": cannot rewind: " + std::strerror(errno));
    }
    buf_.clear();
    eof_ = false;
  }
  pos_ = 0;
  scan_ = 0;
  consumed_ = 0;
  line_no_ = 0;
}

std::string read_all(TextReader& text) {
  std::string all;
  while (const auto line = text.next_line()) {
    all += *line;
    all += '\n';
  }
  return all;
}

TextReader hold_in_memory(TextReader text) {
  std::string all = read_all(text);
  return TextReader(std::move(all), text.name(), text.limits());
}

std::string read_text_file(const std::string& path, const TextLimits& limits, const StopCheck& stop) {
  auto text = TextReader::open(path, limits, stop);
  return read_all(text);
}

}  // namespace andros
