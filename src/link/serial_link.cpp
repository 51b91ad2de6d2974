#include "andros/link/serial_link.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "andros/link/port_holder.hpp"

namespace andros::link {
namespace {

speed_t speed_of(int baud) {
  switch (baud) {
    case 19200: return B19200;
    case 38400: return B38400;
    case 57600: return B57600;
    case 115200: return B115200;
    default: return B9600;  // the config parser lets no other value through
  }
}

/// The holder for a message, with how it holds the port (locked, opened
/// exclusively) when no process can be named.
std::string held_by(const PortHolder& holder, std::string_view how) {
  return holder.pid > 0 ? describe(holder) : describe(holder) + " (" + std::string(how) + ")";
}

/// The start-up refusal of a port another program holds: streaming would
/// wait for it, and take the port the moment that program lets go.
[[noreturn]] void refuse_held_port(const std::string& path, const SourcePos& pos, std::string_view how) {
  const PortHolder holder = find_port_holder(path);
  const char* why = holder.program == kBridgeProgram ? "a second bridge is refused" : "the bridge will not share it";
  throw InputError(pos, "serial port " + quote_name(path) + " is in use by " + held_by(holder, how) + ": " + why);
}

}  // namespace

void check_serial_port(const std::string& path, const SourcePos& pos) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    if (errno == ENOENT) return;  // not plugged in yet: the link waits for it
    throw InputError(pos, "serial port " + quote_name(path) + ": " + std::strerror(errno));
  }
  if (!S_ISCHR(st.st_mode)) {
    const char* what = S_ISDIR(st.st_mode) ? "a directory" : S_ISREG(st.st_mode) ? "a regular file" : "not a device";
    throw InputError(pos, "serial port " + quote_name(path) + " is not a serial device (" + what + ")");
  }
  if (::access(path.c_str(), R_OK | W_OK) != 0 && errno == EACCES) {
    throw InputError(pos, "serial port " + quote_name(path) +
                              ": permission denied (join the dialout group, or install the udev rules: "
                              "docs/running.md)");
  }
  // One that cannot be opened just now (unplugged since the stat) is left to the link, which waits for it.
  const UniqueFd fd(::open(path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC));
  if (!fd) {
    if (errno == EBUSY) refuse_held_port(path, pos, "opened exclusively");  // another's TIOCEXCL (root passes it)
    return;
  }
  // A device that is not a terminal (/dev/null, /dev/zero) never becomes one: it would be retried for ever.
  if (isatty(fd.get()) == 0) {
    throw InputError(
        pos, "serial port " + quote_name(path) + " is not a serial device (a character device that is not a terminal)");
  }
  // Held by another bridge, or another program: waiting for it would hand the
  // port over the moment that program exits. The lock taken here goes with fd.
  if (flock(fd.get(), LOCK_EX | LOCK_NB) != 0 && errno == EWOULDBLOCK) refuse_held_port(path, pos, "locked");
}

bool configure_raw_8n1(int fd, int baud) {
  termios tio{};
  if (tcgetattr(fd, &tio) != 0) return false;
  cfmakeraw(&tio);
  tio.c_cflag &= ~static_cast<tcflag_t>(CSIZE | PARENB | CSTOPB | CRTSCTS);
  tio.c_cflag |= CS8 | CLOCAL | CREAD;
  tio.c_iflag &= ~static_cast<tcflag_t>(IXON | IXOFF | IXANY);
  tio.c_cc[VMIN] = 0;
  tio.c_cc[VTIME] = 0;
  cfsetispeed(&tio, speed_of(baud));
  cfsetospeed(&tio, speed_of(baud));
  return tcsetattr(fd, TCSANOW, &tio) == 0;
}

SerialLink::SerialLink(std::string path, int baud)
    : ReconnectingLink(path + " " + std::to_string(baud) + " 8N1", kSerialRetryMs, kSerialRetryMs),
      path_(std::move(path)),
      baud_(baud) {}

ReconnectingLink::OpenResult SerialLink::open_step(std::int64_t /*now_ns*/, std::string& why) {
  UniqueFd fd(::open(path_.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC));
  if (!fd) {
    why = errno == EBUSY ? "taken by " + held_by(find_port_holder(path_), "opened exclusively") : std::strerror(errno);
    return OpenResult::kFailed;
  }
  // Two writers interleaving frames would corrupt both streams: the port is ours alone.
  if (flock(fd.get(), LOCK_EX | LOCK_NB) != 0) {
    why = errno == EWOULDBLOCK ? "taken by " + held_by(find_port_holder(path_), "locked") : std::strerror(errno);
    return OpenResult::kFailed;
  }
  if (!isatty(fd.get())) {
    why = "not a serial device (not a tty)";
    return OpenResult::kFailed;
  }
  if (ioctl(fd.get(), TIOCEXCL) != 0 || !configure_raw_8n1(fd.get(), baud_)) {
    why = std::strerror(errno);
    return OpenResult::kFailed;
  }
  tcflush(fd.get(), TCIOFLUSH);  // nothing stale from before we owned it
  fd_ = std::move(fd);
  return OpenResult::kOpen;
}

SerialLink::~SerialLink() { close_fd(); }

// TIOCEXCL outlives the last close of a pseudo-terminal (its tty lives as long
// as the master end does) and would then refuse every later open but root's,
// this bridge's own reopen included: given up before closing.
void SerialLink::close_fd() {
  if (fd_) ioctl(fd_.get(), TIOCNXCL);
  fd_.reset();
}

int SerialLink::queued_bytes() const {
  int queued = 0;
  if (ioctl(fd_.get(), TIOCOUTQ, &queued) != 0) return -1;
  return queued;
}

void SerialLink::finish_drain() { tcdrain(fd_.get()); }

}  // namespace andros::link
