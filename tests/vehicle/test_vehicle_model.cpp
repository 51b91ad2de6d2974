// The vehicle model against issue 37's requirements (docs/trainer.md): each
// oracle is the requirement's figure, not the model's code.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "andros/protocol/decoder.hpp"
#include "andros/protocol/frame.hpp"
#include "andros/vehicle/vehicle_model.hpp"

namespace andros::vehicle {
namespace {

using protocol::ControlState;
using protocol::signal_id;

constexpr std::int64_t kPeriodNs = 40'000'000;  // 25 Hz
constexpr std::uint8_t kCode = 0x01;

const RobotFigures& hd1() { return figures_for("HD1"); }

/// The neutral state: drive and pivot centred, nothing else on.
ControlState neutral() {
  ControlState s;
  s[signal_id("drive")] = protocol::kNeutralCentre;
  s[signal_id("pivot")] = protocol::kNeutralCentre;
  return s;
}

/// Driving allowed: safety and drive brake both say drive, speed high.
ControlState driving() {
  auto s = neutral();
  s[signal_id("safety")] = 1;
  s[signal_id("drive_brake")] = 1;
  s[signal_id("speed_high")] = 1;
  return s;
}

/// The frames as the wire carries them, decoded by the protocol's decoder.
std::vector<protocol::DecodedFrame> decoded(const protocol::Frame& wire) {
  std::vector<protocol::DecodedFrame> out;
  protocol::Decoder decoder;
  decoder.push(wire, [&](const protocol::DecodedFrame& f) { out.push_back(f); });
  return out;
}

protocol::Frame wire(const ControlState& s) { return protocol::encode(protocol::FrameBuilder(kCode).build(s)); }

/// Sends s at 25 Hz for the given seconds, starting at tick `from`; returns the next tick.
std::int64_t send_for(VehicleModel& model, const ControlState& s, double seconds, std::int64_t from = 0) {
  const auto frames = decoded(wire(s));
  const auto ticks = static_cast<std::int64_t>(std::llround(seconds * 25));
  for (std::int64_t k = from; k <= from + ticks; ++k) model.on_frame(frames.at(0), k * kPeriodNs);
  return from + ticks + 1;
}

TEST(VehicleModel, FullForwardForTenSecondsMovesTopSpeedTimesTenAlongTheHeading) {
  VehicleModel model(hd1());
  auto s = driving();
  s[signal_id("drive")] = 255;
  send_for(model, s, 10.0);
  const double expected = 8.4 / 3.6 * 10.0;  // HD-1: 8.4 km/h, the issue's figure
  EXPECT_NEAR(model.state().pose.x, expected, 1e-6);
  EXPECT_NEAR(model.state().pose.y, 0.0, 1e-9);
  EXPECT_NEAR(model.state().pose.heading, 0.0, 1e-9);
}

// No inertia: the frame that commands a speed is the one that shows it, as
// it arrives, before the vehicle has moved (the page shows it with that frame).
TEST(VehicleModel, TheSpeedIsTheFramesFromTheFrameThatCommandsIt) {
  VehicleModel model(hd1());
  send_for(model, neutral(), 0.2);
  auto s = driving();
  s[signal_id("drive")] = 255;
  model.on_frame(decoded(wire(s)).at(0), 6 * kPeriodNs);
  EXPECT_NEAR(model.state().speed, 8.4 / 3.6, 1e-9);
  EXPECT_EQ(model.state().pose.x, 0.0);
  auto pivot = driving();
  pivot[signal_id("pivot")] = 0;
  model.on_frame(decoded(wire(pivot)).at(0), 7 * kPeriodNs);
  EXPECT_EQ(model.state().speed, 0.0);
  EXPECT_NEAR(model.state().turn_rate, 60.0, 1e-9);  // below 128: counter-clockwise, at the turn rate
  model.on_frame(decoded(wire(neutral())).at(0), 8 * kPeriodNs);
  EXPECT_EQ(model.state().turn_rate, 0.0);
}

TEST(VehicleModel, FullForwardAfterATurnMovesAlongTheNewHeading) {
  VehicleModel model(hd1());
  auto turn = driving();
  turn[signal_id("pivot")] = 0;  // below 128: left, counter-clockwise
  std::int64_t next = 0;
  // Until the heading passes +90 degrees (REP 103: counter-clockwise is positive).
  while (model.state().pose.heading < 90.0) next = send_for(model, turn, 0.04, next);
  next = send_for(model, driving(), 0.04, next);  // still again: the turn ends at this frame
  const auto start = model.state().pose;
  auto ahead = driving();
  ahead[signal_id("drive")] = 255;
  send_for(model, ahead, 10.0, next);  // the first frame ends the still one: then 10 s ahead
  const auto& p = model.state().pose;
  EXPECT_NEAR(std::hypot(p.x - start.x, p.y - start.y), 8.4 / 3.6 * 10.0, 1e-6);
  EXPECT_NEAR(std::atan2(p.y - start.y, p.x - start.x) * 180 / std::numbers::pi, start.heading, 1e-6);
  EXPECT_GT(start.heading, 90.0);
}

TEST(VehicleModel, PivotAloneTurnsInPlace) {
  VehicleModel model(hd1());
  auto s = driving();
  s[signal_id("pivot")] = 255;  // right: clockwise, a negative heading
  send_for(model, s, 1.0);
  EXPECT_NEAR(model.state().pose.x, 0.0, 1e-9);
  EXPECT_NEAR(model.state().pose.y, 0.0, 1e-9);
  EXPECT_LT(model.state().pose.heading, -10.0);
}

TEST(VehicleModel, NeutralFramesHoldItStill) {
  VehicleModel model(hd1());
  auto s = neutral();
  s[signal_id("arm_speed")] = 255;
  s[signal_id("speed_high")] = 1;
  send_for(model, s, 10.0);
  const auto& st = model.state();
  EXPECT_EQ(st.pose.x, 0.0);
  EXPECT_EQ(st.pose.y, 0.0);
  EXPECT_EQ(st.pose.heading, 0.0);
  EXPECT_EQ(st.arm.shoulder, 0.0);
  EXPECT_EQ(st.front_flipper, 0.0);
  EXPECT_EQ(st.frames, 251U);
}

TEST(VehicleModel, NoMotionWithoutTheDriveBrakeBit) {
  VehicleModel model(hd1());
  auto s = driving();
  s[signal_id("drive_brake")] = 0;
  s[signal_id("drive")] = 255;
  send_for(model, s, 2.0);
  EXPECT_EQ(model.state().pose.x, 0.0);
}

TEST(VehicleModel, TheArmNeverMovesWithTheSafetyBitOff) {
  VehicleModel model(hd1());
  auto s = neutral();
  s[signal_id("drive_brake")] = 1;
  s[signal_id("arm_speed")] = 255;
  for (const auto* name : {"shoulder_ccw", "torso_left", "elbow_ccw", "wrist_ccw", "gripper_rot_ccw", "gripper_open",
                           "wrist_extend_right", "front_art_up", "rear_art_up"}) {
    s[*protocol::find_signal(name)] = 1;
  }
  send_for(model, s, 5.0);
  const auto& st = model.state();
  EXPECT_EQ(st.arm.torso, 0.0);
  EXPECT_EQ(st.arm.shoulder, 0.0);
  EXPECT_EQ(st.arm.elbow, 0.0);
  EXPECT_EQ(st.arm.wrist, 0.0);
  EXPECT_EQ(st.arm.wrist_extension, 0.0);
  EXPECT_EQ(st.arm.gripper_rotation, 0.0);
  EXPECT_EQ(st.arm.gripper_opening, 0.0);
  EXPECT_EQ(st.front_flipper, 0.0);
  EXPECT_EQ(st.rear_flipper, 0.0);
  // The same frame with the safety bit on moves them: the check above can fail.
  s[signal_id("safety")] = 1;
  send_for(model, s, 1.0, 200);
  EXPECT_GT(model.state().arm.shoulder, 0.0);
  EXPECT_GT(model.state().front_flipper, 0.0);
}

TEST(VehicleModel, TheArmMovesAtTheArmSpeedBytesShare) {
  VehicleModel slow(hd1());
  VehicleModel fast(hd1());
  auto s = driving();
  s[signal_id("shoulder_ccw")] = 1;
  s[signal_id("arm_speed")] = 51;
  send_for(slow, s, 1.0);
  s[signal_id("arm_speed")] = 255;
  send_for(fast, s, 1.0);
  EXPECT_NEAR(slow.state().arm.shoulder * 5, fast.state().arm.shoulder, 1e-9);
}

TEST(VehicleModel, InvalidFramesAreIgnored) {
  auto go = driving();
  go[signal_id("drive")] = 255;
  go[signal_id("shoulder_ccw")] = 1;
  go[signal_id("arm_speed")] = 255;
  auto bad_checksum = wire(go);
  bad_checksum[34] ^= 0x01;
  auto bad_rule = protocol::FrameBuilder(kCode).build(go);
  bad_rule[protocol::kTrailerByte] = 0x03;  // the validation table: byte 15 is 0x02
  for (const auto& frame : {bad_checksum, protocol::encode(bad_rule)}) {
    VehicleModel model(hd1());
    send_for(model, neutral(), 0.2);
    const auto frames = decoded(frame);
    ASSERT_EQ(frames.size(), 1U);
    ASSERT_FALSE(frames[0].valid);
    for (std::int64_t k = 6; k < 56; ++k) model.on_frame(frames[0], k * kPeriodNs);
    EXPECT_EQ(model.state().pose.x, 0.0);
    EXPECT_EQ(model.state().arm.shoulder, 0.0);
    EXPECT_EQ(model.state().ignored, 50U);
  }
}

TEST(VehicleModel, TheWatchdogStopsItWhenFramesStop) {
  VehicleModel model(hd1());
  auto s = driving();
  s[signal_id("drive")] = 255;
  const auto next = send_for(model, s, 1.0);
  const double at_last_frame = model.state().pose.x;
  // No frame for ten seconds: it moves on only until the watchdog's time.
  model.advance((next - 1) * kPeriodNs + 10'000'000'000);
  const double watchdog_s = hd1().watchdog_ms.value / 1000.0;
  EXPECT_NEAR(model.state().pose.x - at_last_frame, 8.4 / 3.6 * watchdog_s, 1e-6);
  EXPECT_TRUE(model.state().watchdog);
  EXPECT_EQ(model.state().speed, 0.0);
}

TEST(VehicleModel, InvalidFramesDoNotFeedTheWatchdog) {
  VehicleModel model(hd1());
  auto s = driving();
  s[signal_id("drive")] = 255;
  const auto next = send_for(model, s, 1.0);
  const double at_last_frame = model.state().pose.x;
  auto broken = wire(s);
  broken[34] ^= 0x01;
  const auto frames = decoded(broken);
  for (std::int64_t k = next; k < next + 250; ++k) model.on_frame(frames.at(0), k * kPeriodNs);
  const double watchdog_s = hd1().watchdog_ms.value / 1000.0;
  EXPECT_NEAR(model.state().pose.x - at_last_frame, 8.4 / 3.6 * watchdog_s, 1e-6);
}

TEST(VehicleModel, AWeaponFiresOnTheRiseOfItsBitOnlyInAFrameThatAllowsIt) {
  VehicleModel model(hd1());
  auto s = driving();
  s[signal_id("weapon_1")] = 1;
  auto next = send_for(model, s, 1.0);  // held: one rise
  EXPECT_EQ(model.state().fired[0], 1U);
  s[signal_id("weapon_1")] = 0;
  next = send_for(model, s, 0.04, next);
  auto off = neutral();
  off[signal_id("weapon_1")] = 1;  // safety off: not allowed
  next = send_for(model, off, 0.2, next);
  EXPECT_EQ(model.state().fired[0], 1U);
  EXPECT_EQ(weapon_name(0), "weapon_1");
  EXPECT_EQ(weapon_name(6), "shotgun");
}

TEST(VehicleModel, TheVideoBitsSelectTheCameras) {
  VehicleModel model(hd1());
  auto s = neutral();
  send_for(model, s, 0.04);
  EXPECT_EQ(model.state().cameras.main, Camera::kFrontDrive);
  EXPECT_EQ(model.state().cameras.inset, Camera::kNone);
  s[signal_id("main_video_2")] = 1;
  s[signal_id("inset_video_1")] = 1;
  s[signal_id("light")] = 255;
  send_for(model, s, 0.04, 10);
  EXPECT_EQ(model.state().cameras.main, Camera::kGripper);
  EXPECT_EQ(model.state().cameras.inset, Camera::kFrontDrive);
  EXPECT_EQ(model.state().light, 1.0);
}

TEST(VehicleModel, TheSameFramesAtTheSameTimesGiveTheSameState) {
  auto s = driving();
  s[signal_id("drive")] = 200;
  s[signal_id("pivot")] = 90;
  VehicleModel a(hd1());
  VehicleModel b(hd1());
  send_for(a, s, 3.0);
  send_for(b, s, 3.0);
  EXPECT_EQ(a.state().pose.x, b.state().pose.x);
  EXPECT_EQ(a.state().pose.heading, b.state().pose.heading);
  EXPECT_EQ(a.trail().size(), b.trail().size());
}

TEST(RobotFigures, TheHd1CarriesTheIssuesPublishedFiguresAndEveryOtherTypeIsAssumed) {
  const auto& f = figures_for("HD1");
  EXPECT_EQ(f.length_m.value, 1.209);
  EXPECT_EQ(f.width_m.value, 0.66);
  EXPECT_EQ(f.height_m.value, 0.635);
  EXPECT_EQ(f.mass_kg.value, 118);
  EXPECT_EQ(f.top_speed_kmh.value, 8.4);
  EXPECT_EQ(f.top_speed_kmh.source, Source::kPublished);
  EXPECT_EQ(f.watchdog_ms.source, Source::kAssumed);
  EXPECT_EQ(figures_for("F6A").top_speed_kmh.source, Source::kAssumed);
  EXPECT_EQ(figures_for("nonsense").robot, "HD1");
}

}  // namespace
}  // namespace andros::vehicle
