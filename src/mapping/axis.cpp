#include "andros/mapping/axis.hpp"

#include <algorithm>
#include <cmath>

#include "andros/input/input_state.hpp"
#include "andros/protocol/signals.hpp"

namespace andros::mapping {

double normalise_axis(std::int16_t value) {
  return value >= 0 ? value / static_cast<double>(input::kAxisMax) : value / -static_cast<double>(input::kAxisMin);
}

double shape_axis(double x, const AxisShape& shape) {
  if (shape.invert) x = -x;
  const double d = shape.deadzone;
  double y = 0.0;
  if (std::abs(x) > d) y = std::copysign((std::abs(x) - d) / (1.0 - d), x);
  const double e = shape.expo;
  return (1.0 - e) * y + e * y * y * y;
}

long round_half_away(double value) { return std::lround(value); }

std::uint8_t centred_byte(double z, int center) {
  const long out =
      z >= 0 ? center + round_half_away(z * (protocol::kWholeByteMax - center)) : center + round_half_away(z * center);
  return static_cast<std::uint8_t>(std::clamp<long>(out, 0, protocol::kWholeByteMax));
}

std::uint8_t level_byte(double z) {
  return static_cast<std::uint8_t>(
      std::clamp<long>(round_half_away(protocol::kWholeByteMax * z), 0, protocol::kWholeByteMax));
}

}  // namespace andros::mapping
