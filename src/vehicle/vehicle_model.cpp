#include "andros/vehicle/vehicle_model.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "andros/protocol/frame.hpp"
#include "andros/protocol/signals.hpp"
#include "angles.hpp"

namespace andros::vehicle {
namespace {

using protocol::signal_id;

constexpr std::array<protocol::SignalId, kWeaponCount> kWeapons = {
    signal_id("weapon_1"), signal_id("weapon_2"), signal_id("weapon_3"), signal_id("weapon_4"),
    signal_id("weapon_5"), signal_id("weapon_6"), signal_id("shotgun")};

constexpr double kNsPerSecond = 1e9;
constexpr double kKmhPerMps = 3.6;
constexpr double kByteMax = 255.0;

/// A centred byte as -1 .. 1 (128 still, within the deadband too).
double centred(std::uint8_t byte, double deadband) {
  const double d = static_cast<double>(byte) - protocol::kNeutralCentre;
  if (std::abs(d) <= deadband) return 0;
  return d > 0 ? d / (kByteMax - protocol::kNeutralCentre) : d / protocol::kNeutralCentre;
}

/// +1, -1 or 0 from a pair of opposing bits (both: neither moves, as the
/// safety layer would have sent).
int pair(const protocol::ControlState& s, protocol::SignalId plus, protocol::SignalId minus) {
  return (s[plus] != 0 ? 1 : 0) - (s[minus] != 0 ? 1 : 0);
}

/// A joint moved at direction * rate * share for seconds, within its limits.
double step(double value, int direction, double share, const JointFigure& j, double seconds) {
  if (direction == 0) return value;
  return std::clamp(value + direction * j.rate.value * share * seconds, j.min.value, j.max.value);
}

/// The same for a joint that turns without end (the PTZ's pan, the gripper's rotation).
double turn(double value, int direction, double share, const JointFigure& j, double seconds) {
  if (direction == 0) return value;
  return wrap_degrees(value + direction * j.rate.value * share * seconds);
}

Camera main_camera(const protocol::ControlState& s) {
  if (s[signal_id("main_video_4")] != 0) return Camera::kRearDrive;
  if (s[signal_id("main_video_3")] != 0) return Camera::kPtz;
  if (s[signal_id("main_video_2")] != 0) return Camera::kGripper;
  return Camera::kFrontDrive;
}

Camera inset_camera(const protocol::ControlState& s) {
  if (s[signal_id("inset_4")] != 0) return Camera::kRearDrive;
  if (s[signal_id("inset_3")] != 0) return Camera::kPtz;
  if (s[signal_id("inset_video_2")] != 0) return Camera::kGripper;
  if (s[signal_id("inset_video_1")] != 0) return Camera::kFrontDrive;
  return Camera::kNone;
}

}  // namespace

std::string_view weapon_name(std::size_t index) { return protocol::info(kWeapons.at(index)).name; }

VehicleModel::VehicleModel(const RobotFigures& figures, std::optional<Course> course)
    : figures_(figures), course_(std::move(course)) {
  state_.cameras.zoom = figures_.zoom.min.value;
  if (course_) {
    state_.pose = {course_->start.x, course_->start.y, wrap_degrees(course_->start_heading)};
    // Where it starts, it rests level: a course's start is on flat ground or on one slope.
    // Where it starts, it rests level: a course's start is on flat ground or on one slope.
    state_.course.elevation = course_->elevation(course_->start);
    if (course_->package) {
      state_.course.package = course_->package->at;
      state_.course.package_z = course_->package->z;
    }
  }
  trail_.push_back(state_.pose);
}

void VehicleModel::on_frame(const protocol::DecodedFrame& frame, std::int64_t now_ns) {
  if (!state_.started) {
    // The first frame starts the vehicle's clock: nothing moved before it.
    state_.started = true;
    state_.time_ns = now_ns;
    state_.start_ns = now_ns;
    last_valid_ns_ = now_ns;
  }
  advance(now_ns);
  if (!frame.valid) {
    ++state_.ignored;
    return;
  }
  ++state_.frames;
  last_valid_ns_ = std::max(now_ns, state_.time_ns);
  state_.watchdog = false;
  take(frame.data);
}

void VehicleModel::advance(std::int64_t now_ns) {
  if (!state_.started || now_ns <= state_.time_ns) return;
  integrate(now_ns);
}

void VehicleModel::integrate(std::int64_t until_ns) {
  const auto deadline = last_valid_ns_ + static_cast<std::int64_t>(figures_.watchdog_ms.value * 1e6);
  const auto end = std::min(until_ns, deadline);
  if (end > state_.time_ns) move(static_cast<double>(end - state_.time_ns) / kNsPerSecond);
  if (until_ns > deadline && !state_.watchdog) {
    // No valid frame for the watchdog's time: everything stops, as if the
    // next frame were neutral; the next valid frame is obeyed again.
    state_.watchdog = true;
    command_ = Command{};
    state_.speed = 0;
    state_.turn_rate = 0;
    state_.laser = false;
  }
  state_.time_ns = until_ns;
}

void VehicleModel::commanded_rates() { (void)drive(state_.pose, 0, state_.speed, state_.turn_rate); }

void VehicleModel::move(double seconds) {
  if (course_) {
    // Each short step checked against the course: a wall stops the vehicle where it meets it.
    const auto steps = static_cast<int>(std::ceil(seconds / kCourseStep));
    for (int i = 0; i < steps; ++i) step_on_course(seconds / steps);
    return;
  }
  double v = 0;
  double w = 0;
  state_.pose = drive(state_.pose, seconds, v, w);
  state_.speed = v;
  state_.turn_rate = w;
  add_trail_point();
  move_joints(seconds);
}

Pose VehicleModel::drive(const Pose& from, double seconds, double& v, double& w) const {
  const auto& c = command_;
  const auto& f = figures_;
  // Skid steer, integrated as an arc (exact for a command held constant).
  const double top = f.top_speed_kmh.value / kKmhPerMps * c.speed_scale;
  v = top * (c.left + c.right) / 2;
  w = f.turn_rate_dps.value * c.speed_scale * (c.right - c.left) / 2;
  Pose p = from;
  const double h0 = radians(p.heading);
  if (w == 0) {
    p.x += v * seconds * std::cos(h0);
    p.y += v * seconds * std::sin(h0);
  } else {
    const double h1 = h0 + radians(w * seconds);
    const double r = v / radians(w);
    p.x += r * (std::sin(h1) - std::sin(h0));
    p.y -= r * (std::cos(h1) - std::cos(h0));
    p.heading = wrap_degrees(p.heading + w * seconds);
  }
  return p;
}

void VehicleModel::move_joints(double seconds) {
  const auto& c = command_;
  const auto& f = figures_;
  state_.front_flipper = step(state_.front_flipper, c.front_flipper, 1, f.front_flipper, seconds);
  state_.rear_flipper = step(state_.rear_flipper, c.rear_flipper, 1, f.rear_flipper, seconds);
  auto& a = state_.arm;
  const double share = c.arm_rate;
  a.torso = step(a.torso, c.torso, share, f.torso, seconds);
  a.shoulder = step(a.shoulder, c.shoulder, share, f.shoulder, seconds);
  a.elbow = step(a.elbow, c.elbow, share, f.elbow, seconds);
  a.wrist = step(a.wrist, c.wrist, share, f.wrist, seconds);
  a.wrist_extension = step(a.wrist_extension, c.wrist_extension, share, f.wrist_extension, seconds);
  a.gripper_rotation = turn(a.gripper_rotation, c.gripper_rotation, share, f.gripper_rotation, seconds);
  a.gripper_opening = step(a.gripper_opening, c.gripper, share, f.gripper_opening, seconds);
  auto& cam = state_.cameras;
  cam.pan = turn(cam.pan, c.pan, 1, f.pan, seconds);
  cam.tilt = step(cam.tilt, c.tilt, 1, f.tilt, seconds);
  cam.zoom = step(cam.zoom, c.zoom, 1, f.zoom, seconds);
  cam.focus = step(cam.focus, c.focus, 1, f.focus, seconds);
  cam.iris = step(cam.iris, c.iris, 1, f.iris, seconds);
  cam.extender = step(cam.extender, c.extender, 1, f.extender, seconds);
}

/// A joint's command and the pair of bits that drive it (plus first).
struct JointBits {
  int VehicleModel::Command::*direction;
  protocol::SignalId plus;
  protocol::SignalId minus;
};

/// What moves only with the safety bit: the articulation and the arm.
constexpr std::array<JointBits, 9> kSafetyJoints = {{
    {&VehicleModel::Command::front_flipper, signal_id("front_art_up"), signal_id("front_art_down")},
    {&VehicleModel::Command::rear_flipper, signal_id("rear_art_up"), signal_id("rear_art_down")},
    {&VehicleModel::Command::torso, signal_id("torso_left"), signal_id("torso_right")},
    {&VehicleModel::Command::shoulder, signal_id("shoulder_ccw"), signal_id("shoulder_cw")},
    {&VehicleModel::Command::elbow, signal_id("elbow_ccw"), signal_id("elbow_cw")},
    {&VehicleModel::Command::wrist, signal_id("wrist_ccw"), signal_id("wrist_cw")},
    {&VehicleModel::Command::wrist_extension, signal_id("wrist_extend_right"), signal_id("wrist_extend_left")},
    {&VehicleModel::Command::gripper_rotation, signal_id("gripper_rot_ccw"), signal_id("gripper_rot_cw")},
    {&VehicleModel::Command::gripper, signal_id("gripper_open"), signal_id("gripper_close")},
}};

/// The cameras: whatever the safety bit.
constexpr std::array<JointBits, 6> kCameraJoints = {{
    {&VehicleModel::Command::pan, signal_id("pt_left"), signal_id("pt_right")},
    {&VehicleModel::Command::tilt, signal_id("pt_up"), signal_id("pt_down")},
    {&VehicleModel::Command::zoom, signal_id("zoom_up"), signal_id("zoom_down")},
    {&VehicleModel::Command::focus, signal_id("focus_up"), signal_id("focus_down")},
    {&VehicleModel::Command::iris, signal_id("iris_up"), signal_id("iris_down")},
    {&VehicleModel::Command::extender, signal_id("pt_extend_up"), signal_id("pt_extend_down")},
}};

void VehicleModel::take(const protocol::DataBytes& data) {
  const auto s = protocol::read_signals(data);
  const auto& f = figures_;
  const bool safety = s[signal_id("safety")] != 0;
  const bool drive = safety && s[signal_id("drive_brake")] != 0;
  state_.safety = safety;
  state_.drive = drive;

  Command c;
  if (drive) {
    const double d = centred(s[signal_id("drive")], f.deadband_counts.value);
    // Pivot above 128 turns right (clockwise), as the shipped mappings send it (docs/robots.md).
    const double t = centred(s[signal_id("pivot")], f.deadband_counts.value);
    c.left = std::clamp(d + t, -1.0, 1.0);
    c.right = std::clamp(d - t, -1.0, 1.0);
    const bool high = s[signal_id("speed_high")] != 0;
    const bool low = s[signal_id("speed_low")] != 0;
    c.speed_scale = low ? f.low_speed_scale.value : high ? 1.0 : f.medium_speed_scale.value;
  }
  // The ICD's note: the safety bit must be on to move the arm and the articulation.
  if (safety) {
    for (const auto& j : kSafetyJoints) c.*j.direction = pair(s, j.plus, j.minus);
    c.arm_rate = s[signal_id("arm_speed")] / kByteMax;
  }
  for (const auto& j : kCameraJoints) c.*j.direction = pair(s, j.plus, j.minus);
  command_ = c;
  // No inertia: the tracks take the new speed as the frame arrives. On a
  // course, the speed is what the last step made of it (0 at a wall), so
  // that a vehicle held by a wall never shows the speed it is refused.
  if (!course_) commanded_rates();

  state_.cameras.main = main_camera(s);
  state_.cameras.inset = inset_camera(s);
  state_.light = s[signal_id("light")] / kByteMax;
  state_.laser = s[signal_id("laser")] != 0;
  if (course_) course_laser();
  state_.tool_on = s[signal_id("tool_on")] != 0;
  state_.enable_key = s[signal_id("enable_key")] != 0;
  for (std::size_t i = 0; i < kWeaponCount; ++i) {
    const bool bit = s[kWeapons[i]] != 0;
    // A weapon fires on the rise of its bit, and only in a frame that
    // allows motion at all (the safety bit on): the frame a mapping sends
    // only while enabled.
    if (bit && !state_.fire_bits[i] && safety) {
      ++state_.fired[i];
      if (course_) course_fired();
    }
    state_.fire_bits[i] = bit;
  }
}

void VehicleModel::add_trail_point() {
  const auto& last = trail_.back();
  const auto& p = state_.pose;
  if (std::hypot(p.x - last.x, p.y - last.y) < kTrailStep) return;
  trail_.push_back(p);
  if (trail_.size() > kTrailPoints) trail_.pop_front();
}

}  // namespace andros::vehicle
