#pragma once
/// The arithmetic of the live frame clock, apart from any clock: tick k falls
/// at k * 1e12 / rate ns after the start, rate in millihertz (replay's
/// FrameClock gives its time in ms). Times are exact integers, so 25 Hz stays
/// 25 Hz for hours with no accumulated rounding.

#include <cstdint>

#include "andros/timing/rate.hpp"

namespace andros::timing {

class TickSchedule {
 public:
  explicit TickSchedule(std::int64_t rate_millihertz) : clock_(rate_millihertz) {}

  [[nodiscard]] std::int64_t rate_millihertz() const { return clock_.rate_millihertz(); }
  /// Tick k's offset from the start, in ns.
  [[nodiscard]] std::int64_t tick_ns(std::int64_t k) const {
    // Split so that k * 1e12 cannot overflow: exact for years of ticks.
    const std::int64_t mhz = rate_millihertz();
    return k / mhz * kNsPerMillihertzCycle + k % mhz * kNsPerMillihertzCycle / mhz;
  }
  /// Tick k's time in ms as the mapping and event scripts see it: the same
  /// frame times as replay (docs/event-scripts.md: frames at 0, P, 2P, ...).
  [[nodiscard]] std::int64_t tick_ms(std::int64_t k) const { return clock_.time_of(k); }

  /// The tick to run after tick `last`, `elapsed_ns` after the start. Normally
  /// last + 1; after a stall, the latest tick already due, so that missed ticks
  /// are skipped rather than sent in a burst of stale frames.
  [[nodiscard]] std::int64_t next_tick(std::int64_t last, std::int64_t elapsed_ns) const {
    const std::int64_t mhz = rate_millihertz();
    const std::int64_t e = elapsed_ns < 0 ? 0 : elapsed_ns;
    const std::int64_t due = e / kNsPerMillihertzCycle * mhz + e % kNsPerMillihertzCycle * mhz / kNsPerMillihertzCycle;
    return due > last + 1 ? due : last + 1;
  }

 private:
  /// 1e12 ns: 1000 s, the time in which a rate of R millihertz gives R ticks.
  static constexpr std::int64_t kNsPerMillihertzCycle = 1'000'000'000'000;
  FrameClock clock_;
};

}  // namespace andros::timing
