#pragma once
/// The one clock every loop reads: CLOCK_MONOTONIC in ns, absolute-time
/// sleeps on it (so that a late wake-up never shifts the ticks after it), and
/// the periodic schedule every periodic loop keeps. What stops a loop is
/// ShutdownRequest (stop.hpp).

#include <algorithm>
#include <chrono>
#include <cstdint>

namespace andros {

using Nanos = std::chrono::nanoseconds;

/// The units of time, named once: a literal 1'000'000 is a count, never a time.
inline constexpr std::int64_t kNsPerUs = 1'000;
inline constexpr std::int64_t kNsPerMs = 1'000'000;
inline constexpr std::int64_t kNsPerSecond = 1'000'000'000;
inline constexpr std::int64_t kMsPerSecond = 1'000;

/// The monotonic clock in ns.
std::int64_t monotonic_ns();

/// Sleeps until the monotonic clock reads abs_ns, whatever interrupts it: the
/// frame clock's sleep, which nothing may shorten. A sleep that a stop request
/// should end is ShutdownRequest::sleep_until.
void sleep_until_ns_uninterrupted(std::int64_t abs_ns);

/// The time a loop reads and sleeps on, injected so that the same loop runs
/// live (RealClock) and in replay and tests (VirtualClock), byte for byte.
class Clock {
 public:
  virtual ~Clock() = default;
  /// Time since an arbitrary epoch; never goes back.
  [[nodiscard]] virtual Nanos now() const = 0;
  /// Returns once now() >= t (at once when it already is). Nothing shortens
  /// it: a stop is answered on the tick that sees it.
  virtual void sleep_until(Nanos t) = 0;
};

/// CLOCK_MONOTONIC, absolute sleeps that a signal does not shorten.
class RealClock final : public Clock {
 public:
  [[nodiscard]] Nanos now() const override { return Nanos(monotonic_ns()); }
  void sleep_until(Nanos t) override { sleep_until_ns_uninterrupted(t.count()); }
};

/// A clock that moves only when slept on: sleep_until(t) sets it to t. A
/// loop on it runs as fast as it computes, through the same ticks as live.
class VirtualClock final : public Clock {
 public:
  [[nodiscard]] Nanos now() const override { return now_; }
  void sleep_until(Nanos t) override { now_ = std::max(now_, t); }
  /// Time passing outside the loop (a stall, a paused process).
  void advance(Nanos d) { now_ += d; }

 private:
  Nanos now_{0};
};

/// A periodic schedule in exact integers: tick k falls floor(k * cycle_ns /
/// ticks_per_cycle) ns after the start, so that no rounding accumulates from
/// tick to tick. Missed ticks are skipped, never sent in a burst: the one
/// place that rule lives.
class TickGrid {
 public:
  /// ticks_per_cycle ticks in every cycle_ns. Keep (ticks_per_cycle - 1) *
  /// cycle_ns within 64 bits (1e12 ns and a million ticks are fine).
  constexpr TickGrid(std::int64_t cycle_ns, std::int64_t ticks_per_cycle)
      : cycle_ns_(cycle_ns), per_cycle_(ticks_per_cycle) {}
  /// A tick every period_ns.
  static constexpr TickGrid every(std::int64_t period_ns) { return TickGrid(period_ns, 1); }

  /// Tick k's offset from the start, in ns.
  [[nodiscard]] constexpr std::int64_t tick_ns(std::int64_t k) const {
    // Split so that k * cycle_ns cannot overflow: exact for years of ticks.
    return k / per_cycle_ * cycle_ns_ + k % per_cycle_ * cycle_ns_ / per_cycle_;
  }
  /// The latest tick whose time has come elapsed_ns after the start.
  [[nodiscard]] constexpr std::int64_t due(std::int64_t elapsed_ns) const {
    const std::int64_t e = elapsed_ns < 0 ? 0 : elapsed_ns;
    return e / cycle_ns_ * per_cycle_ + e % cycle_ns_ * per_cycle_ / cycle_ns_;
  }
  /// The tick to run after tick `last`, `elapsed_ns` after the start. Normally
  /// last + 1; after a stall, the latest tick already due, so that missed ticks
  /// are skipped rather than run in a burst of stale ones.
  [[nodiscard]] constexpr std::int64_t next_tick(std::int64_t last, std::int64_t elapsed_ns) const {
    const std::int64_t d = due(elapsed_ns);
    return d > last + 1 ? d : last + 1;
  }

 private:
  std::int64_t cycle_ns_;
  std::int64_t per_cycle_;
};

}  // namespace andros
