#include "andros/base/write_fully.hpp"

#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>

#include "andros/base/clock.hpp"

namespace andros {

int write_fully(int fd, std::string_view text, int timeout_ms) {
  const std::int64_t deadline = monotonic_ns() + std::int64_t{timeout_ms} * kNsPerMs;
  std::size_t done = 0;
  while (done < text.size()) {
    const long n = ::write(fd, text.data() + done, text.size() - done);
    if (n > 0) {
      done += static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK) return errno;
    int wait_ms = -1;
    if (timeout_ms >= 0) {
      const std::int64_t left_ms = (deadline - monotonic_ns()) / kNsPerMs;
      if (left_ms <= 0) return ETIMEDOUT;
      wait_ms = static_cast<int>(left_ms);
    }
    pollfd p{fd, POLLOUT, 0};
    poll(&p, 1, wait_ms);
  }
  return 0;
}

}  // namespace andros
