#include "andros/timing/frame_timing.hpp"

#include <algorithm>
#include <cmath>

#include "andros/base/clock.hpp"

namespace andros::timing {

void FrameTiming::add(std::int64_t t_ns) { times_[count_++ % kWindow] = t_ns; }

TimingSummary FrameTiming::summary(std::int64_t now_ns) const {
  TimingSummary out;
  out.count = count_;
  const std::size_t n = static_cast<std::size_t>(std::min<std::uint64_t>(count_, kWindow));
  // Oldest to newest.
  const auto at = [&](std::size_t i) { return times_[(count_ - n + i) % kWindow]; };
  if (n < 2) return out;
  double sum = 0;
  for (std::size_t i = 1; i < n; ++i) sum += static_cast<double>(at(i) - at(i - 1));
  const double mean = sum / static_cast<double>(n - 1);
  double sq = 0;
  double worst = 0;
  for (std::size_t i = 1; i < n; ++i) {
    const double d = static_cast<double>(at(i) - at(i - 1)) - mean;
    sq += d * d;
    worst = std::max(worst, std::abs(d));
  }
  out.period_ms = mean / kNsPerMs;
  // Over the whole window, not a count of the last second (which flips
  // between 25 and 26 with the phase); a stream that stopped shows 0.
  const auto quiet = static_cast<double>(now_ns - at(n - 1));
  constexpr auto kSecond = static_cast<double>(kNsPerSecond);
  out.rate_hz = quiet > std::max(kStoppedPeriods * mean, kSecond) ? 0.0 : kSecond / mean;
  out.jitter_ms = std::sqrt(sq / static_cast<double>(n - 1)) / kNsPerMs;
  out.worst_ms = worst / kNsPerMs;
  return out;
}

}  // namespace andros::timing
