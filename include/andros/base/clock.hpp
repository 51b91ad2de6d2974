#pragma once
/// The one clock every loop reads: CLOCK_MONOTONIC in ns, and absolute-time
/// sleeps on it (so that a late wake-up never shifts the ticks after it).

#include <cstdint>

namespace andros {

inline constexpr std::int64_t kNsPerMs = 1'000'000;
inline constexpr std::int64_t kNsPerSecond = 1'000'000'000;

/// The monotonic clock in ns.
std::int64_t monotonic_ns();

/// Sleeps until the monotonic clock reads abs_ns. Returns false when a signal
/// handler cut the sleep short (the caller decides whether to sleep again).
bool sleep_until_ns(std::int64_t abs_ns);

/// sleep_until_ns, again after each signal, until abs_ns.
void sleep_until_ns_uninterrupted(std::int64_t abs_ns);

}  // namespace andros
