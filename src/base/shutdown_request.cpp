#include "andros/base/shutdown_request.hpp"

#include <poll.h>
#include <sys/eventfd.h>
#include <sys/signalfd.h>

#include <cerrno>
#include <cstring>
#include <ctime>

#include "andros/base/clock.hpp"
#include "andros/base/error.hpp"

namespace andros {

ShutdownRequest::ShutdownRequest() : wake_(eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK)) {
  if (!wake_) throw RuntimeError(std::string("eventfd: ") + std::strerror(errno));
}

ShutdownRequest::ShutdownRequest(std::initializer_list<int> signals) : ShutdownRequest() {
  signals_.emplace(signals);
  sigset_t set;
  sigemptyset(&set);
  for (const int sig : signals) sigaddset(&set, sig);
  // Only polled, never read: the signal is taken with the blocked set.
  signal_fd_.reset(signalfd(-1, &set, SFD_CLOEXEC | SFD_NONBLOCK));
  if (!signal_fd_) throw RuntimeError(std::string("signalfd: ") + std::strerror(errno));
}

ShutdownRequest::~ShutdownRequest() = default;

void ShutdownRequest::raise() {
  raised_ = true;
  const std::uint64_t one = 1;
  [[maybe_unused]] const auto n = ::write(wake_.get(), &one, sizeof one);  // never read: stays readable
}

bool ShutdownRequest::requested() {
  if (raised_) return true;
  if (!signals_) return false;
  while (const int sig = signals_->take()) {
    if (sig == SIGHUP && hangup_reloads_) {
      reload_pending_ = true;
      continue;
    }
    int none = 0;
    signal_.compare_exchange_strong(none, sig);
    raise();
    break;
  }
  return raised_;
}

bool ShutdownRequest::reload_requested() {
  requested();
  return reload_pending_.exchange(false);
}

bool ShutdownRequest::sleep_until(std::int64_t abs_ns) { return !wait(-1, abs_ns) && !requested(); }

bool ShutdownRequest::wait_readable(int fd, std::int64_t abs_ns) { return wait(fd, abs_ns) && !requested(); }

/// True when fd is ready; false at abs_ns or on a stop request.
bool ShutdownRequest::wait(int fd, std::int64_t abs_ns) {
  pollfd fds[3] = {{wake_.get(), POLLIN, 0}, {signal_fd_.get(), POLLIN, 0}, {fd, POLLIN, 0}};
  while (!requested()) {
    timespec left{};
    timespec* timeout = nullptr;
    if (abs_ns != kNoDeadline) {
      const std::int64_t ns = abs_ns - monotonic_ns();
      if (ns <= 0) return false;
      left = timespec{static_cast<time_t>(ns / kNsPerSecond), static_cast<long>(ns % kNsPerSecond)};
      timeout = &left;
    }
    // A negative fd is left out by poll(): no signals, or no fd to wait on.
    if (::ppoll(fds, 3, timeout, nullptr) < 0 && errno != EINTR) {
      throw RuntimeError(std::string("poll: ") + std::strerror(errno));
    }
    if (fd >= 0 && fds[2].revents != 0) return true;
  }
  return false;
}

}  // namespace andros
