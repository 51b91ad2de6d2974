#pragma once
/// A training course (docs/trainer.md, "Courses"): the ground and what stands
/// on it, as the vehicle model meets it. The model takes a course as its
/// second input beside the frames: walls and boxes stop the vehicle and the
/// arm, a ramp or a flight of stairs lifts it, a door swings when the
/// gripper pulls its handle, a package goes where the gripper takes it, and
/// gates are passed in order. A course's file is read by trainer/course_file.hpp;
/// here it is geometry only, in the model's axes (REP 103: x and y on the
/// ground in metres, headings in degrees counter-clockwise from +x).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace andros::vehicle {

struct Point {
  double x = 0;
  double y = 0;
};

/// A rectangle on the ground: its centre, its length along heading and its width across.
struct Area {
  Point centre;
  double length = 0;
  double width = 0;
  double heading = 0;  ///< degrees

  [[nodiscard]] bool contains(Point p) const;
  /// p in the area's own axes: x along its heading from its centre, y across (to its left).
  [[nodiscard]] Point to_local(Point p) const;
};

/// A wall or a box: a block standing on the ground up to height.
struct Block {
  Area area;
  double height = 0;
};

/// A ramp or a flight of stairs: rises along its area's heading from the
/// ground at the back edge to rise at the front edge.
struct Slope {
  Area area;
  double angle = 0;  ///< degrees up from the ground
  bool stairs = false;
  [[nodiscard]] double rise() const;
};

/// A raised floor (a landing, the top of a flight): flat at height.
struct Landing {
  Area area;
  double height = 0;
};

/// A door on a hinge: a leaf of width that stands at closed_heading (from
/// the hinge to its free edge) and swings by up to opens degrees (positive:
/// counter-clockwise). Its handle is near the free edge, at handle_height.
struct Door {
  Point hinge;
  double width = 0;
  double closed_heading = 0;
  double opens = 90;
  double handle_height = 1;
  double height = 2;
};

/// A package the gripper can grip and lift, and where it must be set down.
struct Package {
  Point at;
  double z = 0;  ///< its underside's height where it starts (on the ground, or inside a car)
  double size = 0.3;
  double mass = 5;           ///< kg: it adds to the arm's moment while held
  std::optional<Area> drop;  ///< set down inside it: delivered
};

/// A gate: the line of width across heading through at, passed when the
/// vehicle's centre crosses it going along heading.
struct Gate {
  Point at;
  double heading = 0;
  double width = 0;

  /// The vehicle's centre going from `from` to `to` crosses it along its heading.
  [[nodiscard]] bool crossed(Point from, Point to) const;
};

/// Where the vehicle must end: inside area, its heading within tolerance of heading.
struct Finish {
  Area area;
  std::optional<double> heading;
  double tolerance = 15;
};

/// A target for the laser: a disc of radius around at, at height z.
struct Target {
  Point at;
  double z = 0;
  double radius = 0.3;
};

struct Course {
  std::string name;
  /// The ground: [min_x, max_x] x [min_y, max_y]; its edge stops the vehicle as a wall would.
  double min_x = -10, max_x = 10, min_y = -10, max_y = 10;
  Point start;
  double start_heading = 0;
  double time_limit_s = 0;  ///< 0: none
  std::vector<Block> blocks;
  std::vector<Slope> slopes;
  std::vector<Landing> landings;
  std::optional<Door> door;
  std::optional<Package> package;
  std::vector<Gate> gates;
  std::optional<Finish> finish;
  std::optional<Target> target;

  /// The ground's height under p: a landing's, a slope's, or 0.
  [[nodiscard]] double elevation(Point p) const;
  /// The slope under p, if any.
  [[nodiscard]] const Slope* slope_at(Point p) const;
};

/// Two areas overlap (separating axes).
bool overlaps(const Area& a, const Area& b);

}  // namespace andros::vehicle
