#include "andros/vehicle/course.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "angles.hpp"

namespace andros::vehicle {
namespace {

std::array<Point, 4> corners(const Area& a) {
  const double h = radians(a.heading);
  const Point u{std::cos(h) * a.length / 2, std::sin(h) * a.length / 2};
  const Point v{-std::sin(h) * a.width / 2, std::cos(h) * a.width / 2};
  const Point c = a.centre;
  return {{{c.x + u.x + v.x, c.y + u.y + v.y},
           {c.x + u.x - v.x, c.y + u.y - v.y},
           {c.x - u.x - v.x, c.y - u.y - v.y},
           {c.x - u.x + v.x, c.y - u.y + v.y}}};
}

/// Whether b's corners all lie beyond one of a's sides (a separating axis of a).
bool separated_by(const Area& a, const Area& b) {
  const auto cs = corners(b);
  const auto side = [&](auto beyond) {
    return std::all_of(cs.begin(), cs.end(), [&](Point p) { return beyond(a.to_local(p)); });
  };
  return side([&](Point l) { return l.x > a.length / 2; }) || side([&](Point l) { return l.x < -a.length / 2; }) ||
         side([&](Point l) { return l.y > a.width / 2; }) || side([&](Point l) { return l.y < -a.width / 2; });
}

}  // namespace

Point Area::to_local(Point p) const {
  const double h = radians(heading);
  const double dx = p.x - centre.x;
  const double dy = p.y - centre.y;
  return {dx * std::cos(h) + dy * std::sin(h), -dx * std::sin(h) + dy * std::cos(h)};
}

bool Area::contains(Point p) const {
  const auto l = to_local(p);
  return std::abs(l.x) <= length / 2 && std::abs(l.y) <= width / 2;
}

double Slope::rise() const { return area.length * std::tan(radians(angle)); }

bool overlaps(const Area& a, const Area& b) { return !separated_by(a, b) && !separated_by(b, a); }

double Course::elevation(Point p) const {
  double z = 0;
  for (const auto& l : landings) {
    if (l.area.contains(p)) z = std::max(z, l.height);
  }
  for (const auto& s : slopes) {
    if (!s.area.contains(p)) continue;
    const double along = s.area.to_local(p).x + s.area.length / 2;
    z = std::max(z, along * std::tan(radians(s.angle)));
  }
  return z;
}

bool Gate::crossed(Point from, Point to) const {
  const Area line{at, 0, width, heading};
  const auto a = line.to_local(from);
  const auto b = line.to_local(to);
  if (!(a.x < 0 && b.x >= 0)) return false;
  const double across = a.y + (b.y - a.y) * (-a.x) / (b.x - a.x);
  return std::abs(across) <= width / 2;
}

const Slope* Course::slope_at(Point p) const {
  for (const auto& s : slopes) {
    if (s.area.contains(p)) return &s;
  }
  return nullptr;
}

}  // namespace andros::vehicle
