#pragma once
/// The arithmetic of the frame clock, apart from any clock: tick k falls at
/// k * 1e9 / rate ns after the start. Times are exact integers, so 25 Hz stays
/// 25 Hz for hours with no accumulated rounding.

#include <cstdint>

namespace andros {

class TickSchedule {
 public:
  /// rate in frames per second (>= 1).
  explicit TickSchedule(int rate) : rate_(rate) {}

  [[nodiscard]] int rate() const { return rate_; }
  /// Tick k's offset from the start, in ns.
  [[nodiscard]] std::int64_t tick_ns(std::int64_t k) const { return k * 1'000'000'000 / rate_; }
  /// Tick k's time in ms as the mapping and event scripts see it (contract
  /// section 3: frames at 0, P, 2P, ...), rounded down.
  [[nodiscard]] std::int64_t tick_ms(std::int64_t k) const { return k * 1000 / rate_; }
  /// The period in ns (rounded down for rates that do not divide 1e9).
  [[nodiscard]] std::int64_t period_ns() const { return 1'000'000'000 / rate_; }

  /// The tick to run after tick `last`, `elapsed_ns` after the start. Normally
  /// last + 1; after a stall, the latest tick already due, so that missed ticks
  /// are skipped rather than sent in a burst of stale frames.
  [[nodiscard]] std::int64_t next_tick(std::int64_t last, std::int64_t elapsed_ns) const {
    const std::int64_t due = elapsed_ns < 0 ? 0 : elapsed_ns * rate_ / 1'000'000'000;
    return due > last + 1 ? due : last + 1;
  }

 private:
  int rate_;
};

}  // namespace andros
