#include "andros/base/service_notify.hpp"

#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <charconv>
#include <cstddef>
#include <cstdlib>
#include <cstring>

namespace andros {
namespace {

std::string_view env(const char* name) {
  const char* value = std::getenv(name);
  return value != nullptr ? std::string_view(value) : std::string_view();
}

template <typename T>
bool parse_number(std::string_view text, T& out) {
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), out);
  return error == std::errc() && end == text.data() + text.size() && !text.empty();
}

/// WATCHDOG_USEC in ns, clamped to kMaxWatchdogNs (a number too long for
/// 64 bits too); 0 for anything that is not a number of microseconds.
std::int64_t watchdog_period_ns(std::string_view usec_text) {
  constexpr std::uint64_t kMaxUsec = ServiceNotifier::kMaxWatchdogNs / kNsPerUs;
  std::uint64_t usec = 0;
  const char* const last = usec_text.data() + usec_text.size();
  const auto [end, error] = std::from_chars(usec_text.data(), last, usec);
  if (usec_text.empty() || end != last) return 0;
  if (error == std::errc::result_out_of_range) return ServiceNotifier::kMaxWatchdogNs;
  if (error != std::errc()) return 0;
  return usec >= kMaxUsec ? ServiceNotifier::kMaxWatchdogNs : static_cast<std::int64_t>(usec) * kNsPerUs;
}

}  // namespace

ServiceNotifier ServiceNotifier::from_environment() {
  ServiceNotifier notifier;
  const auto socket_name = env("NOTIFY_SOCKET");
  if (socket_name.size() < 2 || socket_name.size() >= sizeof(sockaddr_un::sun_path) ||
      (socket_name[0] != '/' && socket_name[0] != '@')) {
    return notifier;
  }
  notifier.address_ = std::string(socket_name);
  if (notifier.address_[0] == '@') notifier.address_[0] = '\0';
  notifier.fd_.reset(::socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0));

  // The watchdog is ours only when WATCHDOG_PID, if set, names this process.
  pid_t pid = 0;
  const auto pid_text = env("WATCHDOG_PID");
  if (pid_text.empty() || (parse_number(pid_text, pid) && pid == ::getpid())) {
    notifier.watchdog_ns_ = watchdog_period_ns(env("WATCHDOG_USEC"));
  }
  return notifier;
}

bool ServiceNotifier::send(std::string_view message) const {
  if (!fd_) return false;
  sockaddr_un addr{};
  addr.sun_family = AF_UNIX;
  std::memcpy(addr.sun_path, address_.data(), address_.size());
  const auto length = static_cast<socklen_t>(offsetof(sockaddr_un, sun_path) + address_.size());
  const ssize_t n = ::sendto(fd_.get(), message.data(), message.size(), MSG_NOSIGNAL | MSG_DONTWAIT,
                             reinterpret_cast<const sockaddr*>(&addr), length);
  return n == static_cast<ssize_t>(message.size());
}

void ServiceNotifier::watchdog(std::int64_t now_ns) {
  if (watchdog_ns_ <= 0 || !fd_) return;
  // With now_ns >= last_ping_ns_ >= 0 the difference cannot overflow,
  // whatever now_ns is. A time before the last ping (never on the monotonic
  // clock) pings.
  if (last_ping_ns_ >= 0 && now_ns >= last_ping_ns_ && now_ns - last_ping_ns_ < watchdog_ns_ / 2) return;
  send("WATCHDOG=1");
  last_ping_ns_ = now_ns;
}

bool is_journal_stream(int fd) {
  const auto value = env("JOURNAL_STREAM");
  const auto colon = value.find(':');
  std::uint64_t dev = 0;
  std::uint64_t ino = 0;
  if (colon == std::string_view::npos || !parse_number(value.substr(0, colon), dev) ||
      !parse_number(value.substr(colon + 1), ino)) {
    return false;
  }
  struct stat st {};
  return ::fstat(fd, &st) == 0 && st.st_dev == dev && st.st_ino == ino;
}

}  // namespace andros
