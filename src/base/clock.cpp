#include "andros/base/clock.hpp"

#include <time.h>

#include <cerrno>

namespace andros {

std::int64_t monotonic_ns() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * kNsPerSecond + ts.tv_nsec;
}

void sleep_until_ns_uninterrupted(std::int64_t abs_ns) {
  const timespec ts{static_cast<time_t>(abs_ns / kNsPerSecond), static_cast<long>(abs_ns % kNsPerSecond)};
  while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) == EINTR) {
  }
}

}  // namespace andros
