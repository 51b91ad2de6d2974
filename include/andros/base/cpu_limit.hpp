#pragma once
/// A CPU-time limit (`ulimit -t`, RLIMIT_CPU, systemd's LimitCPU=) met with
/// neutral frames (docs/running.md, "Signals"). The kernel sends SIGXCPU
/// when a process's CPU time reaches the soft limit and SIGKILL at the hard
/// one; bash's `ulimit -t N` sets both to N, so the process is killed with
/// no warning, mid-drive. run lowers its own soft limit below the hard one:
/// SIGXCPU, which run answers as SIGTERM (the shutdown's neutral frames),
/// then always comes first, with CPU time to spare for the shutdown.

#include <cstdint>
#include <optional>
#include <string>

namespace andros {

/// The CPU seconds kept between the soft limit and the hard one: the
/// shutdown (neutral frames, the link closed, the session closed) takes a
/// few milliseconds of CPU; two seconds is room enough for a loop that spins.
inline constexpr std::uint64_t kCpuLimitMargin = 2;

/// The soft limit to set for a soft and hard limit in seconds (nullopt: no
/// limit, RLIM_INFINITY), or nullopt when it needs no change: the soft limit
/// at most hard - kCpuLimitMargin; with a hard limit under 2 x the margin,
/// half of it (at least 1 s: a hard limit of 1 s leaves no room).
std::optional<std::uint64_t> lowered_cpu_soft_limit(std::optional<std::uint64_t> soft,
                                                    std::optional<std::uint64_t> hard);

/// Lowers this process's soft RLIMIT_CPU as lowered_cpu_soft_limit() says.
/// Returns what was done, for the log ("" when nothing was), or why not.
std::string keep_room_before_cpu_kill();

}  // namespace andros
