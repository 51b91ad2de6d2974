#pragma once
/// The axis arithmetic of docs/mapping.md, once, so that every binding,
/// test and doc agrees to the last unit.

#include <cstdint>

#include "andros/mapping/model.hpp"

namespace andros::mapping {

/// x = v/32767 for v >= 0, v/32768 for v < 0: -32768 maps to exactly -1.
double normalise_axis(std::int16_t value);

/// Invert, then deadzone d (0 when |x| <= d, else sign(x)(|x|-d)/(1-d)), then
/// expo e ((1-e)y + e y^3).
double shape_axis(double x, const AxisShape& shape);

/// Rounds halves away from zero (std::round does; named for docs/mapping.md).
long round_half_away(double value);

/// drive/pivot: c + round(z(255-c)) for z >= 0, c + round(z c) below; clamped.
std::uint8_t centred_byte(double z, int center);

/// A trigger on arm_speed/light: round(255 z), negative values as 0.
std::uint8_t level_byte(double z);

}  // namespace andros::mapping
