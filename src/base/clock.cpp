#include "andros/base/clock.hpp"

#include <time.h>

#include <cerrno>

namespace andros {

std::int64_t monotonic_ns() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * kNsPerSecond + ts.tv_nsec;
}

bool sleep_until_ns(std::int64_t abs_ns) {
  const timespec ts{static_cast<time_t>(abs_ns / kNsPerSecond), static_cast<long>(abs_ns % kNsPerSecond)};
  return clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) != EINTR;
}

void sleep_until_ns_uninterrupted(std::int64_t abs_ns) {
  while (!sleep_until_ns(abs_ns)) {
  }
}

}  // namespace andros
