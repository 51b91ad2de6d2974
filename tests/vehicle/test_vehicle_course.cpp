// The vehicle model on a course against issue 38's limits (docs/trainer.md,
// "Courses"): walls stop the vehicle and the arm and each contact counts;
// no climb past the stated angle; stairs need the flippers; the arm out on a
// slope warns, then tips it over; gates count only in order.
#include <gtest/gtest.h>

#include "andros/protocol/decoder.hpp"
#include "andros/protocol/frame.hpp"
#include "andros/vehicle/vehicle_model.hpp"

namespace andros::vehicle::on_course {
namespace {

using protocol::ControlState;
using protocol::signal_id;

constexpr std::int64_t kPeriodNs = 40'000'000;  // 25 Hz

const RobotFigures& hd1() { return figures_for("HD1"); }

ControlState state_with(std::initializer_list<std::pair<const char*, std::uint8_t>> values) {
  ControlState s;
  s[signal_id("drive")] = protocol::kNeutralCentre;
  s[signal_id("pivot")] = protocol::kNeutralCentre;
  s[signal_id("safety")] = 1;
  s[signal_id("drive_brake")] = 1;
  s[signal_id("arm_speed")] = 255;
  for (const auto& [name, v] : values) s[*protocol::find_signal(name)] = v;
  return s;
}

ControlState forward(std::uint8_t drive = 255) { return state_with({{"drive", drive}, {"speed_high", 1}}); }

/// Feeds the model s at 25 Hz for seconds from tick `tick` (advanced past them).
void send(VehicleModel& model, const ControlState& s, double seconds, std::int64_t& tick) {
  protocol::DecodedFrame f;
  f.data = protocol::FrameBuilder(0x01).build(s);
  f.checksum_ok = true;
  f.valid = true;
  const auto n = static_cast<std::int64_t>(seconds * 25);
  for (std::int64_t k = 0; k < n; ++k) model.on_frame(f, tick++ * kPeriodNs);
}

Course open_course() {
  Course c;
  c.name = "t";
  c.min_x = -20;
  c.max_x = 40;
  c.min_y = -20;
  c.max_y = 20;
  return c;
}

/// A wall across the x axis at x = at, 2 m high.
Block wall_at(double at) { return {{{at, 0}, 0.2, 10, 0}, 2}; }

TEST(VehicleCourse, TheVehicleStopsAtAWallAndEachContactCounts) {
  auto c = open_course();
  c.blocks.push_back(wall_at(5));
  VehicleModel model(hd1(), c);
  std::int64_t tick = 0;
  send(model, forward(), 6, tick);  // 14 m at top speed on open ground
  const auto& s = model.state();
  // Short of the wall's face (4.9), not past it, and stopped where it met it:
  // the stowed arm's elbow reaches a third of a metre past the nose, and
  // meets the wall first.
  EXPECT_LT(s.pose.x + hd1().length_m.value / 2, 4.9);
  EXPECT_GT(s.pose.x + hd1().length_m.value / 2, 4.9 - 0.4);
  EXPECT_EQ(s.speed, 0.0);
  EXPECT_EQ(s.course.contacts, 1U);  // pushing on is the same contact
  send(model, forward(0), 1, tick);  // back off
  send(model, forward(), 2, tick);   // and into it again
  EXPECT_EQ(model.state().course.contacts, 2U);
  EXPECT_LT(model.state().pose.x + hd1().length_m.value / 2, 4.9 + 1e-9);
}

TEST(VehicleCourse, TheGroundsEdgeIsAWall) {
  auto c = open_course();
  c.max_x = 3;
  VehicleModel model(hd1(), c);
  std::int64_t tick = 0;
  send(model, forward(), 4, tick);
  EXPECT_LT(model.state().pose.x, 3.0);
  EXPECT_EQ(model.state().course.contacts, 1U);
}

TEST(VehicleCourse, TheArmStopsAtAWallAndTheContactCounts) {
  // The arm unfolds forward at the shoulder's height: a wall 1.2 m ahead of
  // the centre is within its reach (the stowed arm clears it).
  auto c = open_course();
  c.blocks.push_back(wall_at(1.3));
  VehicleModel free_model(hd1(), open_course());
  VehicleModel model(hd1(), c);
  std::int64_t tick = 0;
  std::int64_t free_tick = 0;
  const auto unfold = state_with({{"elbow_ccw", 1}});
  send(model, unfold, 10, tick);
  send(free_model, unfold, 10, free_tick);
  EXPECT_EQ(free_model.state().arm.elbow, hd1().elbow.max.value);  // open ground: all the way
  EXPECT_LT(model.state().arm.elbow, 150.0);                       // at the wall: stopped short
  EXPECT_EQ(model.state().course.contacts, 1U);
  EXPECT_EQ(free_model.state().course.contacts, 0U);
}

Course with_slope(double angle, bool stairs) {
  auto c = open_course();
  c.slopes.push_back({{{6, 0}, 4, 3, 0}, angle, stairs});
  return c;
}

TEST(VehicleCourse, NoClimbSteeperThanTheStatedAngle) {
  const double limit = hd1().max_climb_deg.value;
  VehicleModel steep(hd1(), with_slope(limit + 5, false));
  VehicleModel climbable(hd1(), with_slope(limit - 15, false));
  std::int64_t t1 = 0;
  std::int64_t t2 = 0;
  // 2.2 s at top speed: 5.1 m, the centre half way up the slope (it ends at x = 8).
  send(steep, forward(), 2.2, t1);
  send(climbable, forward(), 2.2, t2);
  EXPECT_EQ(steep.state().course.elevation, 0.0);
  // Its tracks' front at the foot of the slope (its back edge at x = 4).
  EXPECT_LT(steep.state().pose.x + hd1().length_m.value / 2, 4.0 + 0.05);
  EXPECT_EQ(steep.state().course.climbs_refused, 1U);
  EXPECT_GT(climbable.state().course.elevation, 0.5);
  EXPECT_EQ(climbable.state().course.climbs_refused, 0U);
}

TEST(VehicleCourse, StairsAreMountedOnlyWithTheFrontFlippersUp) {
  VehicleModel down(hd1(), with_slope(35, true));
  VehicleModel up(hd1(), with_slope(35, true));
  std::int64_t t1 = 0;
  std::int64_t t2 = 0;
  send(down, forward(), 2.2, t1);
  send(up, state_with({{"front_art_up", 1}}), 1, t2);  // 30 deg/s: 30 degrees up
  send(up, forward(), 2.2, t2);
  EXPECT_EQ(down.state().course.elevation, 0.0);
  EXPECT_EQ(down.state().course.climbs_refused, 1U);
  EXPECT_GT(up.state().course.elevation, 0.5);
}

TEST(VehicleCourse, TheArmOutOnASlopeWarnsThenTipsItOver) {
  // Facing down a steep slope, the front flippers raised (they no longer
  // lengthen what it stands on), the arm unfolds and reaches out.
  auto c = with_slope(hd1().max_climb_deg.value, false);
  c.start = {6, 0};
  c.start_heading = 180;
  VehicleModel slope(hd1(), c);
  auto flat_course = open_course();
  VehicleModel flat(hd1(), flat_course);
  std::int64_t t1 = 0;
  std::int64_t t2 = 0;
  const auto raise = state_with({{"front_art_up", 1}});
  send(slope, raise, 2, t1);
  send(flat, raise, 2, t2);
  EXPECT_FALSE(slope.state().course.tip_warning);
  const auto reach = state_with({{"elbow_ccw", 1}, {"wrist_extend_right", 1}});
  std::uint32_t warned_before_tipping = 0;
  for (int i = 0; i < 12 * 25 && !slope.state().course.tipped; ++i) {
    send(slope, reach, 0.04, t1);
    warned_before_tipping = slope.state().course.tip_warnings;
  }
  send(flat, reach, 12, t2);
  EXPECT_TRUE(slope.state().course.tipped);
  EXPECT_GE(warned_before_tipping, 1U);
  EXPECT_FALSE(flat.state().course.tipped);  // the same arm on flat ground stands
  // Tipped over, nothing moves it any more.
  const auto pose = slope.state().pose;
  send(slope, forward(), 2, t1);
  EXPECT_EQ(slope.state().pose.x, pose.x);
}

TEST(VehicleCourse, GatesCountOnlyInOrder) {
  auto c = open_course();
  c.gates.push_back({{8, 0}, 0, 3});  // the first gate is the far one
  c.gates.push_back({{4, 0}, 0, 3});
  VehicleModel model(hd1(), c);
  std::int64_t tick = 0;
  send(model, forward(), 5, tick);  // through the near (second) gate first, then the far (first)
  EXPECT_EQ(model.state().course.gates, 1U);
}

TEST(VehicleCourse, WithoutACourseTheModelIsUnchanged) {
  // Open ground with no course: no contact, no course state (the trail's digest test holds the rest).
  VehicleModel model(hd1());
  std::int64_t tick = 0;
  send(model, forward(), 2, tick);
  EXPECT_EQ(model.state().course.contacts, 0U);
  EXPECT_FALSE(model.course_done());
}

}  // namespace
}  // namespace andros::vehicle::on_course
