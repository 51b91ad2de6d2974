#pragma once
/// The frame rate: its default, how it is parsed, and the exact frame times it
/// gives (docs/event-scripts.md: frames at 0, P, 2P, ...).

#include <cstdint>
#include <string>
#include <string_view>

#include "andros/base/clock.hpp"
#include "andros/base/error.hpp"

namespace andros::timing {

inline constexpr std::int64_t kMillihertzPerHz = 1'000;

/// Frame times for a rate given in millihertz, exactly: t_k = floor(k * 1000 / rate)
/// ms, so 25 Hz gives 0, 40, 80, ... and 24 Hz gives 0, 41, 83, 125, ...
class FrameClock {
 public:
  explicit FrameClock(std::int64_t rate_millihertz) : rate_millihertz_(rate_millihertz) {}
  [[nodiscard]] std::int64_t time_of(std::int64_t k) const {
    return k * kMsPerSecond * kMillihertzPerHz / rate_millihertz_;
  }
  [[nodiscard]] std::int64_t rate_millihertz() const { return rate_millihertz_; }

 private:
  std::int64_t rate_millihertz_;
};

inline constexpr std::int64_t kDefaultRateMillihertz = 25'000;
inline constexpr int kBitsPerFrame = 360;  ///< 36 bytes, 10 bits each on the wire (8N1)

/// A frame rate read from text, once: its value, and the text and place it
/// came from, so that a rate the final baud cannot carry is reported where it
/// was set.
struct Rate {
  std::int64_t millihertz = kDefaultRateMillihertz;
  std::string text;  ///< as written; empty for the default
  SourcePos pos;
};

/// Parses a frame rate in Hz ("25", "12.5", at most 3 decimals, at least
/// 1 Hz). Throws InputError at pos.
Rate parse_rate(std::string_view text, const SourcePos& pos);

/// Refuses (InputError at rate.pos) a rate whose frames do not fit on a link
/// of `baud`: rate x 360 bits > baud.
void check_rate_fits(const Rate& rate, int baud);

/// The highest rate a link of `baud` carries, in millihertz.
std::int64_t max_rate_millihertz(int baud);

/// A rate as text parse_rate reads back: "25", "12.5", "26.666".
std::string rate_text(std::int64_t millihertz);

}  // namespace andros::timing
