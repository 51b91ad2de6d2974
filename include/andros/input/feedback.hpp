#pragma once
/// What the controller can tell the operator's hands and eyes: a short rumble
/// (one or a few pulses) and the colour of its light, where it has them.

#include <array>
#include <cstdint>
#include <optional>

namespace andros::input {

/// One feedback pattern: `pulses` rumbles of `ms` each, `ms` apart, at the
/// two motors' strengths (0..1; low is the heavy motor, high the light one),
/// and the light set to `led` when given (it keeps that colour afterwards).
struct FeedbackPattern {
  double low = 0.0;
  double high = 0.0;
  int ms = 100;
  int pulses = 1;
  std::optional<std::array<std::uint8_t, 3>> led;  ///< red, green, blue

  bool operator==(const FeedbackPattern&) const = default;
};

inline constexpr int kMaxFeedbackMs = 1000;
inline constexpr int kMaxFeedbackPulses = 5;

}  // namespace andros::input
