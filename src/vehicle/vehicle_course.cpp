// The vehicle model on a course (course.hpp): each short step of motion
// checked against what stands on the ground. What is modelled, and the
// figures it uses, are in docs/trainer.md ("Courses").
#include <algorithm>
#include <cmath>

#include "andros/vehicle/vehicle_model.hpp"
#include "angles.hpp"

namespace andros::vehicle {
namespace {

/// A closed gripper holds what it closed on; open past this, it lets go.
constexpr double kGripClosed = 0.2;
constexpr double kGripOpen = 0.5;
constexpr double kDoorThickness = 0.05;
constexpr double kHandleStandOff = 0.1;

struct Point3 {
  double x = 0, y = 0, z = 0;
};

double distance(Point3 a, Point3 b) { return std::hypot(a.x - b.x, a.y - b.y, a.z - b.z); }

/// The arm's points in the world: the shoulder, elbow, wrist and the
/// gripper's tip. The arm works in a vertical plane of the body turned by
/// the torso about the shoulder, as the page draws it; the body pitched with
/// the slope under it.
struct ArmPoints {
  Point3 shoulder, elbow, wrist, tip;
  double forward = 0;  ///< the tip's reach along the vehicle's length, from its centre (the body's frame)
  double up = 0;       ///< the tip's height above the ground under the centre (the body's frame)
};

ArmPoints arm_points(const RobotFigures& f, const Pose& pose, double ground, double body_pitch, const ArmPose& a) {
  const double h = radians(pose.heading);
  const double cp = std::cos(radians(body_pitch));
  const double sp = std::sin(radians(body_pitch));
  // A point of the body's frame (forward along its length, left, up from the
  // ground under its centre), the body pitched, to the world.
  const auto world = [&](double fwd, double left, double up) {
    const double along = fwd * cp - up * sp;
    return Point3{pose.x + along * std::cos(h) - left * std::sin(h), pose.y + along * std::sin(h) + left * std::cos(h),
                  ground + fwd * sp + up * cp};
  };
  const double shoulder_fwd = f.length_m.value * 0.15;
  const double torso = radians(a.torso);
  // From the shoulder along the torso's plane (reach, rise), in the body's frame.
  const auto at = [&](double reach, double rise) {
    return world(shoulder_fwd + reach * std::cos(torso), reach * std::sin(torso), f.height_m.value + rise);
  };
  const double a1 = a.shoulder;
  const double a2 = a1 + 180 - a.elbow;
  const double a3 = a2 + a.wrist;
  const double e_f = f.upper_arm_m.value * std::cos(radians(a1));
  const double e_u = f.upper_arm_m.value * std::sin(radians(a1));
  const double w_f = e_f + f.forearm_m.value * std::cos(radians(a2));
  const double w_u = e_u + f.forearm_m.value * std::sin(radians(a2));
  const double g = f.gripper_m.value + a.wrist_extension;
  const double t_f = w_f + g * std::cos(radians(a3));
  const double t_u = w_u + g * std::sin(radians(a3));
  ArmPoints out;
  out.shoulder = at(0, 0);
  out.elbow = at(e_f, e_u);
  out.wrist = at(w_f, w_u);
  out.tip = at(t_f, t_u);
  out.forward = shoulder_fwd + t_f * std::cos(torso);
  out.up = f.height_m.value + t_u;
  return out;
}

Area door_leaf(const Door& d, double angle) {
  const double h = radians(d.closed_heading + angle);
  const Point mid{d.hinge.x + std::cos(h) * d.width / 2, d.hinge.y + std::sin(h) * d.width / 2};
  return {mid, d.width, kDoorThickness, d.closed_heading + angle};
}

/// The handle: near the leaf's free edge, standing off it on the side the door swings to (where it is pulled from).
Point3 door_handle(const Door& d, double angle) {
  const double h = radians(d.closed_heading + angle);
  const double r = d.width * 0.9;
  const double off = radians(d.closed_heading + angle + (d.opens < 0 ? -90 : 90));
  return {d.hinge.x + std::cos(h) * r + std::cos(off) * kHandleStandOff,
          d.hinge.y + std::sin(h) * r + std::sin(off) * kHandleStandOff, d.handle_height};
}

/// The bearing of p from the door's hinge, degrees.
double bearing(const Door& d, Point3 p) { return degrees(std::atan2(p.y - d.hinge.y, p.x - d.hinge.x)); }

/// Whether a point of the arm is inside something solid: a block below its
/// top, the door's leaf, the ground.
bool solid_at(const Course& c, double door_angle, Point3 p) {
  const Point q{p.x, p.y};
  if (p.z < c.elevation(q)) return true;
  for (const auto& b : c.blocks) {
    if (p.z < b.height && b.area.contains(q)) return true;
  }
  if (c.door && p.z < c.door->height && door_leaf(*c.door, door_angle).contains(q)) return true;
  return false;
}

/// Whether the body's footprint at pose meets a block, the door's leaf or the ground's edge.
bool body_blocked(const Course& c, const RobotFigures& f, const Pose& pose, double door_angle) {
  const Area body{{pose.x, pose.y}, f.length_m.value, f.width_m.value, pose.heading};
  for (const auto& b : c.blocks) {
    if (overlaps(body, b.area)) return true;
  }
  if (c.door && overlaps(body, door_leaf(*c.door, door_angle))) return true;
  const double reach = std::hypot(f.length_m.value, f.width_m.value) / 2;
  return pose.x - reach < c.min_x || pose.x + reach > c.max_x || pose.y - reach < c.min_y || pose.y + reach > c.max_y;
}

bool arm_blocked(const Course& c, double door_angle, const ArmPoints& a) {
  return solid_at(c, door_angle, a.elbow) || solid_at(c, door_angle, a.wrist) || solid_at(c, door_angle, a.tip);
}

/// A contact counted once, when it begins.
void touch(CourseState& s, bool& touching, bool now) {
  if (now && !touching) ++s.contacts;
  touching = now;
}

/// The ground under the vehicle as its tracks rest on it: the height under
/// its centre and its pitch (degrees, nose up), from the ground's height
/// under its nose and its tail.
struct Rest {
  double z = 0;
  double pitch = 0;
};

Rest rest_at(const Course& c, const RobotFigures& f, const Pose& pose) {
  const double h = radians(pose.heading);
  const double half = f.length_m.value / 2;
  const double nose = c.elevation({pose.x + std::cos(h) * half, pose.y + std::sin(h) * half});
  const double tail = c.elevation({pose.x - std::cos(h) * half, pose.y - std::sin(h) * half});
  return {(nose + tail) / 2, degrees(std::atan2(nose - tail, f.length_m.value))};
}

}  // namespace

bool VehicleModel::course_done() const {
  if (!course_) return false;
  const auto& c = *course_;
  const auto& s = state_.course;
  return !s.tipped && s.gates == c.gates.size() && (!c.package || !c.package->drop || s.package_delivered) &&
         (!c.finish || s.in_finish) && (!c.target || s.hits > 0);
}

void VehicleModel::step_on_course(double seconds) {
  auto& s = state_.course;
  if (s.tipped) {
    // On its side: nothing it is told moves it any more.
    state_.speed = 0;
    state_.turn_rate = 0;
    return;
  }
  double v = 0;
  double w = 0;
  const Pose next = drive(state_.pose, seconds, v, w);
  state_.speed = v;
  state_.turn_rate = w;
  if (v != 0 || w != 0) course_pose(next);
  const ArmPose before = state_.arm;
  const double opening = state_.arm.gripper_opening;
  move_joints(seconds);
  course_arm(before);
  course_grip(opening);
  course_balance();
  course_laser();
  const auto& c = *course_;
  if (c.finish) {
    const auto& fin = *c.finish;
    s.in_finish = fin.area.contains({state_.pose.x, state_.pose.y}) &&
                  (!fin.heading || std::abs(wrap_degrees(state_.pose.heading - *fin.heading)) <= fin.tolerance);
  }
}

void VehicleModel::course_pose(const Pose& next) {
  const auto& c = *course_;
  const auto& f = figures_;
  auto& s = state_.course;
  const Point from{state_.pose.x, state_.pose.y};
  const Point to{next.x, next.y};
  const double z0 = s.elevation;
  const Rest rest = rest_at(c, f, next);
  const double z1 = rest.z;
  const auto stop = [&] {
    state_.speed = 0;
    state_.turn_rate = 0;
  };
  if (body_blocked(c, f, next, s.door_angle) ||
      arm_blocked(c, s.door_angle, arm_points(f, next, z1, rest.pitch, state_.arm)) || z1 - z0 > f.max_step_m.value) {
    touch(s, s.body_touching, true);
    stop();
    return;
  }
  // Up a slope where the tracks' front meets it: no steeper than it
  // climbs, and a flight only with the front flippers up to mount it.
  const double h = radians(next.heading);
  const Point nose{to.x + std::cos(h) * f.length_m.value / 2, to.y + std::sin(h) * f.length_m.value / 2};
  if (const Slope* slope = c.slope_at(nose); slope != nullptr && c.elevation(nose) > z1) {
    const double along = std::cos(radians(next.heading - slope->area.heading));
    const double pitch = degrees(std::atan(std::tan(radians(slope->angle)) * along));
    const bool mounting = slope->stairs && z0 <= 0 && state_.front_flipper < f.stairs_flipper_deg.value;
    if (pitch > f.max_climb_deg.value || mounting) {
      if (!s.climb_blocked) ++s.climbs_refused;
      s.climb_blocked = true;
      stop();
      return;
    }
  }
  s.climb_blocked = false;
  touch(s, s.body_touching, false);
  if (s.gates < c.gates.size() && c.gates[s.gates].crossed(from, to)) ++s.gates;
  state_.pose = next;
  s.elevation = z1;
  add_trail_point();
  if (z0 - z1 > f.max_drop_m.value) s.tipped = true;  // driven off an edge
}

void VehicleModel::course_arm(const ArmPose& before) {
  auto& s = state_.course;
  const auto& a = state_.arm;
  const bool moved = a.torso != before.torso || a.shoulder != before.shoulder || a.elbow != before.elbow ||
                     a.wrist != before.wrist || a.wrist_extension != before.wrist_extension;
  if (!moved) return;
  if (arm_blocked(*course_, s.door_angle, arm_points(figures_, state_.pose, s.elevation, s.pitch, a))) {
    // The arm stops where it meets the wall; the gripper may still open, close and turn.
    const double opening = a.gripper_opening;
    const double rotation = a.gripper_rotation;
    state_.arm = before;
    state_.arm.gripper_opening = opening;
    state_.arm.gripper_rotation = rotation;
    touch(s, s.arm_touching, true);
    return;
  }
  touch(s, s.arm_touching, false);
}

void VehicleModel::course_grip(double opening_before) {
  const auto& c = *course_;
  const auto& f = figures_;
  auto& s = state_.course;
  const double opening = state_.arm.gripper_opening;
  const auto tip = arm_points(f, state_.pose, s.elevation, s.pitch, state_.arm).tip;
  const bool closing = opening_before > kGripClosed && opening <= kGripClosed;
  const bool opened = opening >= kGripOpen;
  if (c.package) {
    const auto& pkg = *c.package;
    if (s.package_held && opened) {
      // Let go: it drops to what is under it.
      s.package_held = false;
      s.package_z = c.elevation(s.package);
      for (const auto& b : c.blocks) {
        if (b.area.contains(s.package) && b.height <= tip.z) s.package_z = std::max(s.package_z, b.height);
      }
      s.package_delivered = pkg.drop && pkg.drop->contains(s.package) && s.package_z <= c.elevation(s.package);
    } else if (!s.package_held && closing) {
      const Point3 centre{s.package.x, s.package.y, s.package_z + pkg.size / 2};
      if (distance(tip, centre) <= pkg.size / 2 + f.grip_reach_m.value) {
        s.package_held = true;
        s.package_delivered = false;
      }
    }
    if (s.package_held) {
      s.package = {tip.x, tip.y};
      s.package_z = tip.z - pkg.size / 2;
      if (s.package_z > pkg.z + pkg.size) s.package_lifted = true;
    }
  }
  if (c.door) {
    const auto& d = *c.door;
    if (s.door_held && opened) s.door_held = false;
    if (!s.door_held && closing && distance(tip, door_handle(d, s.door_angle)) <= f.grip_reach_m.value) {
      s.door_held = true;
      s.door_grip_bearing = wrap_degrees(bearing(d, tip) - s.door_angle);
    }
    if (s.door_held) {
      // Held, the door turns with the gripper round its hinge, within its swing.
      const double angle = wrap_degrees(bearing(d, tip) - s.door_grip_bearing);
      s.door_angle = std::clamp(angle, std::min(0.0, d.opens), std::max(0.0, d.opens));
    }
  }
}

void VehicleModel::course_balance() {
  const auto& c = *course_;
  const auto& f = figures_;
  auto& s = state_.course;
  s.pitch = rest_at(c, f, state_.pose).pitch;
  // The centre of mass in the body's frame, along it from its centre and up:
  // the body's, the arm's at the middle of its reach, the package's at the tip.
  const auto arm = arm_points(f, state_.pose, 0, 0, state_.arm);
  const double body = f.mass_kg.value - f.arm_mass_kg.value;
  double m = body;
  double x = 0;
  double z = body * f.body_cog_m.value;
  const double arm_x = (f.length_m.value * 0.15 + arm.forward) / 2;
  x += f.arm_mass_kg.value * arm_x;
  z += f.arm_mass_kg.value * (f.height_m.value + arm.up) / 2;
  m += f.arm_mass_kg.value;
  if (s.package_held) {
    const double pm = c.package->mass;
    x += pm * arm.forward;
    z += pm * std::max(arm.up, 0.0);
    m += pm;
  }
  x /= m;
  z /= m;
  // Where gravity carries it onto the slope's plane: nose up, backwards.
  const double over = x - z * std::tan(radians(s.pitch));
  // The flippers lying along the ground (within 10 degrees) lengthen what it stands on.
  const auto reach = [&](double flipper) {
    return f.length_m.value / 2 + (flipper <= 10 ? f.flipper_m.value * std::cos(radians(flipper)) : 0.0);
  };
  s.tip_margin = std::min(reach(state_.front_flipper) - over, reach(state_.rear_flipper) + over);
  const bool warn = s.tip_margin < f.tip_warning_m.value;
  if (warn && !s.tip_warning) ++s.tip_warnings;
  s.tip_warning = warn;
  if (s.tip_margin < 0) s.tipped = true;
}

void VehicleModel::course_laser() {
  auto& s = state_.course;
  s.laser_on_target = false;
  if (!course_->target || !state_.laser) return;
  // The laser is assumed to lie along the gripper: its ray from the tip.
  const auto& t = *course_->target;
  const auto a = arm_points(figures_, state_.pose, s.elevation, s.pitch, state_.arm);
  const double g = distance(a.wrist, a.tip);
  const Point3 d{(a.tip.x - a.wrist.x) / g, (a.tip.y - a.wrist.y) / g, (a.tip.z - a.wrist.z) / g};
  const Point3 to{t.at.x - a.tip.x, t.at.y - a.tip.y, t.z - a.tip.z};
  const double along = to.x * d.x + to.y * d.y + to.z * d.z;
  if (along <= 0) return;
  const Point3 nearest{a.tip.x + d.x * along, a.tip.y + d.y * along, a.tip.z + d.z * along};
  s.laser_on_target = distance(nearest, Point3{t.at.x, t.at.y, t.z}) <= t.radius;
}

void VehicleModel::course_fired() {
  auto& s = state_.course;
  if (s.laser_on_target) {
    ++s.hits;
  } else {
    ++s.fired_off_target;
  }
}

}  // namespace andros::vehicle
