#pragma once
/// The live frame clock's schedule: tick k falls at k * 1e12 / rate ns after
/// the start (a TickGrid), rate in millihertz (replay's
/// FrameClock gives its time in ms). Times are exact integers, so 25 Hz stays
/// 25 Hz for hours with no accumulated rounding.

#include <cstdint>

#include "andros/base/clock.hpp"
#include "andros/timing/rate.hpp"

namespace andros::timing {

class TickSchedule {
 public:
  explicit TickSchedule(std::int64_t rate_millihertz)
      : clock_(rate_millihertz), grid_(kNsPerMillihertzCycle, rate_millihertz) {}

  [[nodiscard]] std::int64_t rate_millihertz() const { return clock_.rate_millihertz(); }
  /// Tick k's offset from the start, in ns.
  [[nodiscard]] std::int64_t tick_ns(std::int64_t k) const { return grid_.tick_ns(k); }
  /// Tick k's time in ms as the mapping and event scripts see it: the same
  /// frame times as replay (docs/event-scripts.md: frames at 0, P, 2P, ...).
  [[nodiscard]] std::int64_t tick_ms(std::int64_t k) const { return clock_.time_of(k); }

  /// The tick to run after tick `last`, `elapsed_ns` after the start
  /// (TickGrid::next_tick: after a stall, the latest tick already due).
  [[nodiscard]] std::int64_t next_tick(std::int64_t last, std::int64_t elapsed_ns) const {
    return grid_.next_tick(last, elapsed_ns);
  }

 private:
  /// 1e12 ns: 1000 s, the time in which a rate of R millihertz gives R ticks.
  static constexpr std::int64_t kNsPerMillihertzCycle = kNsPerSecond * kMillihertzPerHz;
  FrameClock clock_;
  TickGrid grid_;
};

}  // namespace andros::timing
