#include "andros/base/cpu_limit.hpp"

#include <sys/resource.h>

#include <cerrno>
#include <cstring>

namespace andros {

std::optional<std::uint64_t> lowered_cpu_soft_limit(std::optional<std::uint64_t> soft,
                                                    std::optional<std::uint64_t> hard) {
  if (!hard) return std::nullopt;
  const std::uint64_t room = *hard >= 2 * kCpuLimitMargin ? kCpuLimitMargin : *hard / 2;
  if (room == 0) return std::nullopt;  // a hard limit of 1 s: no whole second to give
  const std::uint64_t want = *hard - room;
  if (soft && *soft <= want) return std::nullopt;
  return want;
}

std::string keep_room_before_cpu_kill() {
  rlimit limit{};
  if (getrlimit(RLIMIT_CPU, &limit) != 0) return std::string("CPU-time limit not read: ") + std::strerror(errno);
  const auto seconds = [](rlim_t v) -> std::optional<std::uint64_t> {
    if (v == RLIM_INFINITY) return std::nullopt;
    return static_cast<std::uint64_t>(v);
  };
  const auto hard = seconds(limit.rlim_max);
  const auto soft = lowered_cpu_soft_limit(seconds(limit.rlim_cur), hard);
  if (!soft) {
    if (hard && limit.rlim_cur >= limit.rlim_max) {
      return "CPU-time limit " + std::to_string(*hard) +
             " s (soft = hard): too short to lower, SIGKILL comes with no SIGXCPU before it";
    }
    return "";
  }
  const auto before = limit.rlim_cur;
  limit.rlim_cur = static_cast<rlim_t>(*soft);
  if (setrlimit(RLIMIT_CPU, &limit) != 0) return std::string("CPU-time limit not lowered: ") + std::strerror(errno);
  return "CPU-time limit: soft " +
         (before == RLIM_INFINITY ? std::string("unlimited") : std::to_string(before) + " s") + " lowered to " +
         std::to_string(*soft) + " s, under the hard " + std::to_string(*hard) +
         " s: SIGXCPU (a stop: neutral frames) comes before the hard limit's SIGKILL";
}

}  // namespace andros
