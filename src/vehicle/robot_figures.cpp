// The figures per robot type. Published: the HD-1's body, weight and top
// speed (issue 37's seed: 1.209 x 0.66 x 0.635 m stowed, 118 kg, 8.4 km/h,
// neutral turn, stair climbing) and, from the Andros brochure the protocol
// reference quotes, the PTZ camera's continuous pan and 180-degree tilt and
// the gripper's 360-degree rotation. Everything else is an assumption, and
// the other six types have no public figure here at all: they get the
// HD-1's, every one marked assumed.
#include "andros/vehicle/robot_figures.hpp"

#include <array>

#include "andros/protocol/robots.hpp"

namespace andros::vehicle {
namespace {

constexpr Figure assumed(double v) { return {v, Source::kAssumed}; }

constexpr JointFigure joint(double min, double max, double rate) { return {assumed(min), assumed(max), assumed(rate)}; }

/// The HD-1's figures under another type's name; published says whether the
/// HD-1's published ones are that (true only for the HD-1 itself).
constexpr RobotFigures make(std::string_view robot, bool published) {
  const Source p = published ? Source::kPublished : Source::kAssumed;
  RobotFigures f{};
  f.robot = robot;
  f.length_m = {1.209, p};
  f.width_m = {0.66, p};
  f.height_m = {0.635, p};
  f.mass_kg = {118, p};
  f.top_speed_kmh = {8.4, p};
  f.turn_rate_dps = assumed(60);
  f.low_speed_scale = assumed(0.25);
  f.medium_speed_scale = assumed(0.5);
  f.neutral_turn = true;
  f.stair_climbing = true;
  f.front_flipper = joint(-45, 90, 30);
  f.rear_flipper = joint(-45, 90, 30);
  f.flipper_m = assumed(0.45);
  f.torso = joint(-180, 180, 30);
  f.shoulder = joint(-10, 120, 20);
  f.elbow = joint(0, 200, 25);  // 0 folded back along the upper arm, 180 straight
  f.wrist = joint(-90, 90, 40);
  f.wrist_extension = joint(0, 0.3, 0.1);
  // 360 degrees of gripper rotation (brochure), continuous: no limit to hit.
  f.gripper_rotation = {{-180, p}, {180, p}, assumed(60)};
  f.gripper_opening = joint(0, 1, 0.5);
  f.upper_arm_m = assumed(0.75);
  f.forearm_m = assumed(0.7);
  // Continuous pan and 180 degrees of tilt (brochure).
  f.pan = {{-180, p}, {180, p}, assumed(30)};
  f.tilt = {{-90, p}, {90, p}, assumed(20)};
  f.zoom = joint(1, 10, 3);
  f.focus = joint(0, 1, 0.5);
  f.iris = joint(0, 1, 0.5);
  f.extender = joint(0, 0.5, 0.1);
  f.watchdog_ms = assumed(500);
  f.deadband_counts = assumed(2);
  f.gripper_m = assumed(0.22);
  // Stair climbing is published; the steepest flight it climbs is not found
  // (45 degrees: assumed, a steep stair).
  f.max_climb_deg = assumed(45);
  f.stairs_flipper_deg = assumed(15);
  f.max_step_m = assumed(0.15);
  f.max_drop_m = assumed(0.3);
  f.body_cog_m = assumed(0.3);
  f.arm_mass_kg = assumed(25);
  f.tip_warning_m = assumed(0.15);
  f.grip_reach_m = assumed(0.12);
  return f;
}

constexpr auto kFigures = [] {
  std::array<RobotFigures, protocol::kRobotTypes.size()> all{};
  for (std::size_t i = 0; i < all.size(); ++i) {
    all[i] = make(protocol::kRobotTypes[i], protocol::kRobotTypes[i] == "HD1");
  }
  return all;
}();

}  // namespace

const RobotFigures& figures_for(std::string_view robot) {
  for (const auto& f : kFigures) {
    if (f.robot == robot) return f;
  }
  return figures_for(protocol::kDefaultRobot);
}

}  // namespace andros::vehicle
