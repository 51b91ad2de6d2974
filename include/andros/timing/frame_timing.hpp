#pragma once
/// Arrival-time statistics of a frame stream: the measured rate and the
/// period's jitter, as the operator's view and `monitor` show them.

#include <array>
#include <cstdint>

namespace andros::timing {

struct TimingSummary {
  double rate_hz = 0;       ///< 1 / the mean period; 0 once no frame came for 2 periods (and 1 s)
  double period_ms = 0;     ///< mean period over the recent frames
  double jitter_ms = 0;     ///< standard deviation of the recent periods
  double worst_ms = 0;      ///< largest |period - mean| among them
  std::uint64_t count = 0;  ///< frames ever added
};

class FrameTiming {
 public:
  void add(std::int64_t t_ns);
  [[nodiscard]] TimingSummary summary(std::int64_t now_ns) const;

 private:
  static constexpr std::size_t kWindow = 128;
  static constexpr double kStoppedPeriods = 2.0;
  std::array<std::int64_t, kWindow> times_{};
  std::uint64_t count_ = 0;
};

}  // namespace andros::timing
