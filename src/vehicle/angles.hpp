#pragma once
// Degrees, as the model and its course keep angles, to and from radians.
#include <cmath>
#include <numbers>

namespace andros::vehicle {

inline double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }
inline double degrees(double radians) { return radians * 180.0 / std::numbers::pi; }

/// An angle in (-180, 180].
inline double wrap_degrees(double a) {
  a = std::fmod(a, 360.0);
  if (a <= -180.0) a += 360.0;
  if (a > 180.0) a -= 360.0;
  return a;
}

}  // namespace andros::vehicle
