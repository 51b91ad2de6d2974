#pragma once
/// The frame rate: its default, how it is parsed, and the exact frame times it
/// gives (docs/event-scripts.md: frames at 0, P, 2P, ...).

#include <cstdint>
#include <string_view>

#include "andros/base/error.hpp"

namespace andros::timing {

/// Frame times for a rate given in millihertz, exactly: t_k = floor(k * 1000 / rate)
/// ms, so 25 Hz gives 0, 40, 80, ... and 24 Hz gives 0, 41, 83, 125, ...
class FrameClock {
 public:
  explicit FrameClock(std::int64_t rate_millihertz) : rate_mhz_(rate_millihertz) {}
  [[nodiscard]] std::int64_t time_of(std::int64_t k) const { return k * 1'000'000 / rate_mhz_; }
  [[nodiscard]] std::int64_t rate_millihertz() const { return rate_mhz_; }

 private:
  std::int64_t rate_mhz_;
};

inline constexpr std::int64_t kDefaultRateMillihertz = 25'000;
inline constexpr int kReplayBaud = 9600;
inline constexpr int kBitsPerFrame = 360;  ///< 36 bytes, 10 bits each on the wire (8N1)

/// Parses a frame rate in Hz ("25", "12.5", at most 3 decimals) into
/// millihertz. Refuses a rate below 1 Hz or one whose frames do not fit on a
/// link of `baud` (rate x 360 bits > baud). Throws InputError at pos.
std::int64_t parse_rate(std::string_view text, int baud, const SourcePos& pos);

}  // namespace andros::timing
