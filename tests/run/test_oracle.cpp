// The fault simulation's oracle (tests/oracle/safety_oracle.hpp) on frames
// made by hand: each rule, broken once, is named; what the rules allow passes.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "andros/input/events.hpp"
#include "andros/mapping/loader.hpp"
#include "oracle/safety_oracle.hpp"
#include "oracle/simulation.hpp"
#include "oracle/wire_frame.hpp"

namespace andros::run {
namespace {

constexpr std::uint8_t kCode = 0x5A;

// The oracle itself, on frames made by hand: each rule, broken once, is named.
class OracleTest : public ::testing::Test {
 protected:
  OracleTest() : valid_(library_.load(mapping::find_robot_mapping("HD1", {ANDROS_MAPPINGS_DIR}).string())) {}

  test::SafetyOracle oracle(const std::string& script, bool weapons = false, const std::string& file = {}) {
    return test::SafetyOracle(
        file.empty() ? *valid_ : *library_.load(file), input::parse_event_script(script, "oracle.events"),
        [this](const std::string& f) { return library_.find(f); },
        test::SafetyOracle::Options{.weapons = weapons, .code = kCode});
  }
  static protocol::DataBytes frame(std::initializer_list<std::pair<protocol::SignalId, int>> set = {}) {
    protocol::ControlState s;
    s[protocol::signal_id("drive")] = 128;
    s[protocol::signal_id("pivot")] = 128;
    for (const auto& [id, v] : set) s[id] = static_cast<std::uint8_t>(v);
    return protocol::FrameBuilder(kCode).build(s);
  }
  static protocol::DataBytes moving() {
    return frame({{protocol::signal_id("safety"), 1},
                  {protocol::signal_id("drive_brake"), 1},
                  {protocol::signal_id("drive"), 255}});
  }

  test::MappingCache library_;
  const mapping::ValidMapping& valid_;
};

// The stick pushed after the tick that enables: one pushed before it waits for rest (the rest rule).
constexpr const char* kDriving = "0 connect\n20 button leftshoulder 1\n50 axis lefty -32768\n";

TEST_F(OracleTest, AllowsMotionAfterAFreshPress) {
  auto o = oracle(std::string(kDriving) + "70 end\n");
  EXPECT_EQ(o.frame(0, frame()), "");
  EXPECT_EQ(o.frame(40, moving()), "");
  EXPECT_EQ(o.frame(80, moving()), "");
  EXPECT_EQ(o.finish(), "");
}

TEST_F(OracleTest, RefusesMotionWithTheDeadmanHeldThroughALinkFlap) {
  auto o = oracle(std::string(kDriving) + "100 link down\n110 link up\n400 end\n");
  for (const std::int64_t t : {0, 40, 80}) ASSERT_EQ(o.frame(t, t == 0 ? frame() : moving()), "");
  EXPECT_EQ(o.frame(120, moving()),
            "safety = 1 while not enabled (deadman held but not pressed since the last link up)");
}

TEST_F(OracleTest, RefusesMotionWithTheDeadmanHeldAtConnect) {
  auto o = oracle("0 connect\n0 button leftshoulder 1\n400 end\n");
  EXPECT_NE(o.frame(0, moving()), "");
}

TEST_F(OracleTest, RefusesAFrameWhileTheLinkIsDown) {
  auto o = oracle("0 connect\n30 link down\n400 end\n");
  ASSERT_EQ(o.frame(0, frame()), "");
  EXPECT_EQ(o.frame(40, frame()), "delivered while the link is down (script)");
}

TEST_F(OracleTest, RefusesAMissingFrame) {
  auto o = oracle("0 connect\n400 end\n");
  ASSERT_EQ(o.frame(0, frame()), "");
  EXPECT_NE(o.frame(80, frame()).find("no frame at t=40"), std::string::npos);
}

TEST_F(OracleTest, RefusesFramesPastASuspendsNeutralOnes) {
  auto o = oracle("0 connect\n100 suspend\n400 end\n");
  for (const std::int64_t t : {0, 40, 80, 120, 160, 200}) ASSERT_EQ(o.frame(t, frame()), "") << t;
  EXPECT_EQ(o.frame(240, frame()), "delivered while suspended, after its neutral frames");
}

TEST_F(OracleTest, RefusesMotionDuringAReload) {
  auto o =
      oracle(std::string(kDriving) + "100 reload\n110 button leftshoulder 0\n115 button leftshoulder 1\n400 end\n");
  for (const std::int64_t t : {0, 40, 80}) ASSERT_EQ(o.frame(t, t == 0 ? frame() : moving()), "");
  EXPECT_NE(o.frame(120, moving()).find("a reload's neutral frame"), std::string::npos);
}

TEST_F(OracleTest, WantsAStopsThreeNeutralFrames) {
  auto o = oracle("0 connect\n100 stop\n400 end\n");
  for (const std::int64_t t : {0, 40, 80, 120, 160}) ASSERT_EQ(o.frame(t, frame()), "") << t;
  EXPECT_NE(o.finish().find("got 2 of its 3"), std::string::npos);
}

TEST_F(OracleTest, RefusesWeaponsWithoutArmingOrWithoutTheOption) {
  const auto fire = frame({{protocol::signal_id("safety"), 1}, {protocol::signal_id("weapon_1"), 1}});
  auto off = oracle(std::string(kDriving) + "50 axis lefttrigger 32767\n400 end\n");
  ASSERT_EQ(off.frame(0, frame()), "");
  ASSERT_EQ(off.frame(40, frame()), "");
  EXPECT_EQ(off.frame(80, fire), "weapon_1 = 1 without --weapons");
  auto unarmed = oracle(std::string(kDriving) + "400 end\n", true);
  ASSERT_EQ(unarmed.frame(0, frame()), "");
  EXPECT_EQ(unarmed.frame(40, fire), "weapon_1 = 1 without its arming input held");
  auto armed = oracle(std::string(kDriving) + "50 axis lefttrigger 32767\n400 end\n", true);
  ASSERT_EQ(armed.frame(0, frame()), "");
  ASSERT_EQ(armed.frame(40, frame()), "");
  EXPECT_EQ(armed.frame(80, fire), "");
}

TEST_F(OracleTest, RefusesBothOfAnOpposingPair) {
  auto o = oracle(std::string(kDriving) + "400 end\n");
  ASSERT_EQ(o.frame(0, frame()), "");
  const auto both = frame(
      {{protocol::signal_id("safety"), 1}, {protocol::signal_id("zoom_up"), 1}, {protocol::signal_id("zoom_down"), 1}});
  EXPECT_EQ(o.frame(40, both), "zoom_down and zoom_up both 1 (an opposing pair)");
}

// Of a pair asked for both (dpup and dpdown pressed while enabled), neither is sent, not one of them.
TEST_F(OracleTest, RefusesOneOfAPairAskedForBoth) {
  auto o = oracle(std::string(kDriving) + "60 button dpup 1\n60 button dpdown 1\n400 end\n");
  ASSERT_EQ(o.frame(0, frame()), "");
  ASSERT_EQ(o.frame(40, frame({{protocol::signal_id("safety"), 1}})), "");
  const auto up = frame({{protocol::signal_id("safety"), 1}, {protocol::signal_id("front_art_up"), 1}});
  EXPECT_EQ(o.frame(80, up),
            "front_art_up and front_art_down both asked for, and one of them sent (an opposing pair: neither)");
  auto neither = oracle(std::string(kDriving) + "60 button dpup 1\n60 button dpdown 1\n400 end\n");
  ASSERT_EQ(neither.frame(0, frame()), "");
  ASSERT_EQ(neither.frame(40, frame({{protocol::signal_id("safety"), 1}})), "");
  EXPECT_EQ(neither.frame(80, frame({{protocol::signal_id("safety"), 1}})), "");
}

// A toggled layer (the arm's, right stick click) ends with the deadman: after a
// fresh press its signals (A: gripper_close) are bound in no layer in force.
TEST_F(OracleTest, RefusesALayersSignalOnceItsToggledLayerEndedWithTheDeadman) {
  auto o = oracle(std::string(kDriving) +
                  "60 button rightstick 1\n61 button rightstick 0\n100 button leftshoulder 0\n"
                  "150 button leftshoulder 1\n400 end\n");
  const auto gripper = frame({{protocol::signal_id("safety"), 1}, {protocol::signal_id("gripper_close"), 1}});
  ASSERT_EQ(o.frame(0, frame()), "");
  ASSERT_EQ(o.frame(40, frame({{protocol::signal_id("safety"), 1}})), "");
  EXPECT_EQ(o.frame(80, gripper), "");  // in the arm layer
  ASSERT_EQ(o.frame(120, frame()), "");
  EXPECT_EQ(o.frame(160, gripper),
            "gripper_close = 1, bound in no binding of the base layer, the layer in force (a toggled layer ends with "
            "the deadman)");
}

// A fire button held when its weapon is armed fires nothing until pressed again.
TEST_F(OracleTest, RefusesAFireButtonHeldWhenItsWeaponWasArmed) {
  const std::string script = std::string(kDriving) +
                             "60 button rightshoulder 1\n70 button a 1\n100 axis lefttrigger 32767\n"
                             "130 button a 0\n150 button a 1\n400 end\n";
  const auto fire = frame({{protocol::signal_id("safety"), 1}, {protocol::signal_id("weapon_1"), 1}});
  const auto idle = frame({{protocol::signal_id("safety"), 1}});
  auto held = oracle(script, true);
  ASSERT_EQ(held.frame(0, frame()), "");
  ASSERT_EQ(held.frame(40, idle), "");
  ASSERT_EQ(held.frame(80, idle), "");
  EXPECT_EQ(held.frame(120, fire),
            "weapon_1 = 1 with its fire button not pressed after the weapon became possible (enabled, its layer "
            "entered, armed)");
  auto again = oracle(script, true);
  for (const std::int64_t t : {0, 40, 80, 120}) ASSERT_EQ(again.frame(t, t == 0 ? frame() : idle), "") << t;
  EXPECT_EQ(again.frame(160, fire), "");
}

const std::string kTrim = ANDROS_TEST_DATA_DIR "/mappings/trim.yaml";  // center: 124

TEST_F(OracleTest, RefusesANeutralFrameAtTheTrim) {
  auto o = oracle("0 connect\n400 end\n", false, kTrim);
  EXPECT_EQ(o.frame(0, frame({{protocol::signal_id("drive"), 124}, {protocol::signal_id("pivot"), 124}})),
            "pivot = 124 while not enabled (deadman not held)");  // pivot (byte 6) comes first
}

TEST_F(OracleTest, HoldsDriveAtTheTrimUntilItsStickIsAtRest) {
  // Enabled with the stick already pushed: drive rests at the trim until the stick comes back.
  const auto at = [](int drive) {
    return frame({{protocol::signal_id("safety"), 1},
                  {protocol::signal_id("drive"), drive},
                  {protocol::signal_id("pivot"), 124}});
  };
  auto o = oracle(
      "0 connect\n10 axis lefty -32768\n20 button leftshoulder 1\n90 axis lefty 0\n"
      "130 axis lefty -32768\n400 end\n",
      false, kTrim);
  ASSERT_EQ(o.frame(0, frame()), "");
  EXPECT_EQ(o.frame(40, at(124)), "");
  EXPECT_EQ(o.frame(80, at(255)),
            "drive = 255, not the centre 124, before its stick was seen at rest (layer \"\", just enabled, or a new "
            "speed level)");
  auto later = oracle(
      "0 connect\n10 axis lefty -32768\n20 button leftshoulder 1\n90 axis lefty 0\n"
      "130 axis lefty -32768\n400 end\n",
      false, kTrim);
  for (const std::int64_t t : {0, 40, 80, 120}) ASSERT_EQ(later.frame(t, t == 0 ? frame() : at(124)), "") << t;
  EXPECT_EQ(later.frame(160, at(255)), "");  // seen at rest at 120
}

TEST_F(OracleTest, HoldsDriveAtANewSpeedLevelAndKeepsItWithinTheLevel) {
  // consent.yaml: levels 25%, 50%, 100% from the slowest, misc1 up, paddle1
  // down, the trim 124: full forward 157, 190, 255.
  const std::string file = ANDROS_TEST_DATA_DIR "/simulation/mappings/consent.yaml";
  const auto drive = [](int v) {
    return frame({{protocol::signal_id("safety"), 1}, {protocol::signal_id("drive"), v}});
  };
  const std::string script = std::string(kDriving) + "100 button misc1 1\n110 button misc1 0\n400 end\n";
  auto o = oracle(script, false, file);
  ASSERT_EQ(o.frame(0, frame()), "");
  ASSERT_EQ(o.frame(40, drive(124)), "");
  ASSERT_EQ(o.frame(80, drive(157)), "");
  EXPECT_EQ(o.frame(120, drive(190)),
            "drive = 190, not the centre 124, before its stick was seen at rest (layer \"\", just enabled, or a new "
            "speed level)");
  auto fast = oracle(kDriving, false, file);
  ASSERT_EQ(fast.frame(0, frame()), "");
  ASSERT_EQ(fast.frame(40, drive(124)), "");
  EXPECT_EQ(fast.frame(80, drive(190)),
            "drive = 190, beyond the speed level 0.250000's range 93..157 (up wraps to the slowest, down stops "
            "there, a new controller or engine starts at the initial level)");
  // Down at the slowest stays there: no change of meaning, and no faster.
  auto down = oracle(std::string(kDriving) + "100 button paddle1 1\n110 button paddle1 0\n400 end\n", false, file);
  for (const std::int64_t t : {0, 40, 80}) ASSERT_EQ(down.frame(t, t == 0 ? frame() : drive(t == 40 ? 124 : 157)), "");
  EXPECT_EQ(down.frame(120, drive(157)), "");
  EXPECT_NE(down.frame(160, drive(255)), "");
}

TEST_F(OracleTest, HoldsDriveWhenALayerIsLeftWithItsStickPushed) {
  // HD1: the arm layer (right stick click) takes the left stick; leaving it with the stick pushed, drive waits.
  auto o = oracle(std::string(kDriving) +
                  "100 button rightstick 1\n105 button rightstick 0\n"
                  "200 button rightstick 1\n205 button rightstick 0\n400 end\n");
  const auto drive = [](int v) {
    return frame({{protocol::signal_id("safety"), 1}, {protocol::signal_id("drive"), v}});
  };
  ASSERT_EQ(o.frame(0, frame()), "");
  for (const std::int64_t t : {40, 80, 120, 160, 200}) ASSERT_EQ(o.frame(t, drive(t <= 80 ? 255 : 128)), "") << t;
  EXPECT_EQ(o.frame(240, drive(255)),
            "drive = 255, not the centre 128, before its stick was seen at rest (layer \"\", just enabled, or a new "
            "speed level)");
}

// Neutral frames from `from` up to `to` (not included): none of them breaks a rule.
void neutral_until(test::SafetyOracle& o, std::int64_t from, std::int64_t to, const protocol::DataBytes& neutral) {
  for (std::int64_t t = from; t < to; t += 40) ASSERT_EQ(o.frame(t, neutral), "") << t;
}

TEST_F(OracleTest, AStopOutlivesItsOwnTickAndTheDeadmanAlone) {
  // Tapped within one tick, the deadman up: still stopped at that tick, and
  // the deadman pressed before the next one does not enable.
  auto o = oracle(
      "0 connect\n20 button leftshoulder 1\n50 button leftshoulder 0\n85 button guide 1\n"
      "90 button guide 0\n130 button leftshoulder 1\n400 end\n");
  for (const std::int64_t t : {0, 40, 80, 120}) ASSERT_EQ(o.frame(t, frame()), "") << t;
  EXPECT_EQ(o.frame(160, moving()), "safety = 1 while not enabled (stopped by the stop button, not reset)");
  // Held through a release and a press of the deadman: never cleared.
  auto held = oracle(
      "0 connect\n20 button leftshoulder 1\n50 button guide 1\n100 button leftshoulder 0\n"
      "150 button leftshoulder 1\n400 end\n");
  for (const std::int64_t t : {0, 40, 80, 120, 160}) ASSERT_EQ(held.frame(t, t == 40 ? moving() : frame()), "") << t;
  // ISO 13850: a stop device stops whenever it is actuated, whatever came before.
  EXPECT_EQ(held.frame(200, moving()), "safety = 1 while a stop button is pressed or held");
}

TEST_F(OracleTest, NoMotionWhileAnyStopButtonIsHeldWhateverTheLatchSays) {
  // stops.yaml: the supervisor presses its stop and holds it (issue 33); the
  // operator's chord and a fresh deadman press after it change nothing.
  const std::string stops = ANDROS_TEST_DATA_DIR "/mappings/stops.yaml";
  auto o = oracle(
      "0 connect\n0 supervisor connect\n20 button leftshoulder 1\n50 supervisor button guide 1\n"
      "100 button leftshoulder 0\n130 button back 1\n130 button start 1\n2400 button back 0\n2400 button start 0\n"
      "2500 button leftshoulder 1\n5000 end\n",
      false, stops);
  neutral_until(o, 0, 3000, frame());
  EXPECT_EQ(o.frame(3000, moving()), "safety = 1 while a stop button is pressed or held");
  EXPECT_EQ(o.coverage().refused_resets, 0);  // the chord never completed: the held stop holds it off
}

// Stopped at 80 (the shipped HD1: its stop on guide, its reset back and
// start); the reset chord made at 110 with the deadman released: a hold from 120.
constexpr const char* kStopThenHold =
    "0 connect\n20 button leftshoulder 1\n50 button guide 1\n60 button guide 0\n100 button leftshoulder 0\n"
    "110 button back 1\n110 button start 1\n";

TEST_F(OracleTest, AResetChordEndsTheStopAndAFreshPressDrives) {
  // Held 2 s (stop_reset_hold's default) from the tick at 120: reset at 2120, then a fresh press.
  const std::string let_go = "button back 0\n2130 button start 0\n";
  auto o = oracle(std::string(kStopThenHold) + "2130 " + let_go + "2135 button leftshoulder 1\n3000 end\n");
  neutral_until(o, 0, 2160, frame());
  EXPECT_EQ(o.frame(2160, moving()), "");
  // One tick short of the hold: still stopped.
  auto short_hold = oracle(std::string(kStopThenHold) +
                           "2090 button back 0\n2090 button start 0\n2095 button leftshoulder 1\n3000 end\n");
  neutral_until(short_hold, 0, 2160, frame());
  EXPECT_EQ(short_hold.frame(2160, moving()), "safety = 1 while not enabled (stopped by the stop button, not reset)");
  // The deadman pressed during the hold: no reset.
  auto touched = oracle(std::string(kStopThenHold) + "1000 button leftshoulder 1\n1010 button leftshoulder 0\n2130 " +
                        let_go + "2135 button leftshoulder 1\n3000 end\n");
  neutral_until(touched, 0, 2160, frame());
  EXPECT_EQ(touched.frame(2160, moving()), "safety = 1 while not enabled (stopped by the stop button, not reset)");
  // The stop button tapped during the hold: a stop, and the hold is over.
  auto tapped = oracle(std::string(kStopThenHold) + "1000 button guide 1\n1010 button guide 0\n2130 " + let_go +
                       "2135 button leftshoulder 1\n3000 end\n");
  neutral_until(tapped, 0, 2160, frame());
  EXPECT_EQ(tapped.frame(2160, moving()), "safety = 1 while not enabled (stopped by the stop button, not reset)");
  // Another pad in the operator's role (another name) may not reset the first pad's stop.
  auto other = oracle(
      "0 connect Pad A\n20 button leftshoulder 1\n50 button guide 1\n60 button guide 0\n100 disconnect\n"
      "105 connect Pad B\n130 button back 1\n130 button start 1\n2170 button back 0\n2170 button start 0\n"
      "2175 button leftshoulder 1\n3000 end\n");
  neutral_until(other, 0, 2200, frame());
  EXPECT_EQ(other.frame(2200, moving()), "safety = 1 while not enabled (stopped by the stop button, not reset)");
  EXPECT_EQ(other.coverage().refused_resets, 1);
}

TEST_F(OracleTest, RefusesTheOperatorsResetOfTheSupervisorsStop) {
  const std::string stops = ANDROS_TEST_DATA_DIR "/mappings/stops.yaml";
  // The supervisor's stop at 80; the operator's chord from 160 (2 s: 2160) is refused.
  const std::string script =
      "0 connect\n0 supervisor connect\n20 button leftshoulder 1\n50 supervisor button guide 1\n"
      "60 supervisor button guide 0\n100 button leftshoulder 0\n130 button back 1\n130 button start 1\n"
      "2200 button back 0\n2200 button start 0\n2205 button leftshoulder 1\n";
  auto refused = oracle(script + "5000 end\n", false, stops);
  neutral_until(refused, 0, 2240, frame());
  EXPECT_EQ(refused.frame(2240, moving()), "safety = 1 while not enabled (stopped by the stop button, not reset)");
  EXPECT_EQ(refused.coverage().refused_resets, 1);
  // The supervisor's chord, from the tick at 2280 (the deadman pressed since the one at 2200 touches the
  // one at 2240), resets at 4280.
  auto reset = oracle(script +
                          "2210 button leftshoulder 0\n2250 supervisor button back 1\n2250 supervisor button start 1\n"
                          "4285 supervisor button back 0\n4285 supervisor button start 0\n"
                          "4290 button leftshoulder 1\n5000 end\n",
                      false, stops);
  neutral_until(reset, 0, 4280, frame());
  ASSERT_EQ(reset.frame(4280, frame()), "");
  EXPECT_EQ(reset.coverage().supervisor_resets, 1);
  EXPECT_EQ(reset.frame(4320, moving()), "");
}

TEST_F(OracleTest, RefusesMotionAtATickWhoseDeadmanWasLetGoAndPressedAgainSinceTheLast) {
  auto o = oracle(std::string(kDriving) + "90 button leftshoulder 0\n110 button leftshoulder 1\n400 end\n");
  for (const std::int64_t t : {0, 40, 80}) ASSERT_EQ(o.frame(t, t == 0 ? frame() : moving()), "") << t;
  EXPECT_EQ(o.frame(120, moving()), "safety = 1 while not enabled (the deadman let go since the last tick)");
  auto next = oracle(std::string(kDriving) + "90 button leftshoulder 0\n110 button leftshoulder 1\n400 end\n");
  for (const std::int64_t t : {0, 40, 80, 120}) ASSERT_EQ(next.frame(t, t == 0 || t == 120 ? frame() : moving()), "");
  // The press after it is fresh (the stick, pushed since before it, waits for rest: drive stays at centre).
  EXPECT_EQ(next.frame(160, frame({{protocol::signal_id("safety"), 1}})), "");
}

TEST_F(OracleTest, RefusesMotionAfterAPanicSqueezeAndBackWithinATick) {
  // safety.yaml: a trigger deadman (LT) off past 0.9, squeezed past it and back to the middle between two ticks.
  const std::string safety = ANDROS_TEST_DATA_DIR "/mappings/safety.yaml";
  const auto enabled = frame({{protocol::signal_id("safety"), 1}});
  auto o = oracle(
      "0 connect\n20 axis lefttrigger 20000\n85 axis lefttrigger 32767\n95 axis lefttrigger 20000\n"
      "400 end\n",
      false, safety);
  for (const std::int64_t t : {0, 40, 80}) ASSERT_EQ(o.frame(t, t == 0 ? frame() : enabled), "") << t;
  EXPECT_EQ(o.frame(120, enabled),
            "safety = 1 while not enabled (deadman held but not pressed since the last panic squeeze)");
  EXPECT_EQ(o.coverage().panics, 1);
}

// docs/mapping.md, "Enable timeout": an axis moved within 1024 of where it was at the last change is noise.
std::string noisy_script(int size) {
  std::string script = std::string(kDriving);  // enabled at 40, the stick's last change at 50
  for (int t = 150, sign = 1; t <= 2950; t += 100, sign = -sign) {
    script += std::to_string(t) + " axis lefty " + std::to_string(-32768 + 2000 + sign * size) + "\n";
  }
  return script + "3000 end\n";
}

TEST_F(OracleTest, RefusesMotionPastTheEnableTimeoutWhenOnlyNoiseMoved) {
  const std::string hd1 = ANDROS_TEST_DATA_DIR "/simulation/mappings/hd1.yaml";  // enable_timeout: 2
  // Moved 2000 from full at 150 (the last change, seen at 160); then 60 back and forth, within the band: due at 2160.
  auto noise = oracle(noisy_script(30), false, hd1);
  ASSERT_EQ(noise.frame(0, frame()), "");
  for (std::int64_t t = 40; t < 2160; t += 40) ASSERT_EQ(noise.frame(t, moving()), "") << t;
  EXPECT_EQ(noise.frame(2160, moving()),
            "safety = 1 while not enabled (deadman held but not pressed since the last enable timeout)");
  // 2 x 1100 back and forth: a hand, and it drives on.
  auto hand = oracle(noisy_script(1100), false, hd1);
  ASSERT_EQ(hand.frame(0, frame()), "");
  for (std::int64_t t = 40; t <= 3000; t += 40) ASSERT_EQ(hand.frame(t, moving()), "") << t;
}

TEST(OracleWire, ReadsTheProtocolsWorkedExampleAndRefusesABrokenOne) {
  // docs/protocol.md: 00001C2000907F7E3E0000FFFF20CC02, checksum 0x06F2 sent as F2 06.
  const std::string hex = "F1F13030303031433230303039303746374533453030303046464646323043433032F206";
  protocol::Frame wire{};
  for (std::size_t i = 0; i < wire.size(); ++i)
    wire[i] = static_cast<std::uint8_t>(std::stoi(hex.substr(2 * i, 2), nullptr, 16));
  protocol::DataBytes data{};
  ASSERT_EQ(test::read_wire_frame(wire, data), "");
  EXPECT_EQ(data, protocol::parse_data_hex("00001C2000907F7E3E0000FFFF20CC02"));
  auto broken = wire;
  broken[35] = 0x07;
  EXPECT_EQ(test::read_wire_frame(broken, data),
            "the checksum on the wire is not the sum of the 32 digits, low byte first");
  broken = wire;
  broken[2] = 'a';  // a lower-case digit: the wire carries upper case
  EXPECT_EQ(test::read_wire_frame(broken, data), "data byte 0 is not two upper-case hex digits on the wire");
  broken = wire;
  broken[1] = 0xF0;
  EXPECT_EQ(test::read_wire_frame(broken, data), "the frame does not start with F1 F1");
}

// docs/testing.md's table of the oracle's rules ("The oracle's rules") and
// the oracle's code name the same rules: each check is marked [rule: ID]
// where it is made, and each ID is a row of the table.
TEST(OracleRules, TheTableInTestingMdIsTheOraclesChecks) {
  const auto text_of = [](const std::filesystem::path& file) {
    std::ifstream in(file);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  };
  std::set<std::string> table;
  const std::string doc = text_of(ANDROS_DOCS_DIR "/testing.md");
  const auto section = doc.find("\n### The oracle's rules\n");
  ASSERT_NE(section, std::string::npos);
  const auto end = doc.find("\n#", section + 1);
  std::istringstream rows(doc.substr(section, end - section));
  const std::regex row(R"(^\| `([a-z-]+)` \|)");
  for (std::string line; std::getline(rows, line);) {
    std::smatch m;
    if (std::regex_search(line, m, row)) table.insert(m[1]);
  }
  std::set<std::string> code;
  const std::regex mark(R"(\[rule: ([a-z-]+)\])");
  for (const auto& entry : std::filesystem::directory_iterator(ANDROS_ORACLE_DIR)) {
    const std::string text = text_of(entry.path());
    for (auto it = std::sregex_iterator(text.begin(), text.end(), mark); it != std::sregex_iterator(); ++it) {
      code.insert((*it)[1]);
    }
  }
  EXPECT_GE(table.size(), 20U);
  EXPECT_EQ(table, code) << "docs/testing.md's rules and the [rule: ID] marks in tests/oracle/ differ";
}

// The loop's state against the oracle's stop latch: a reset made late (or never) is named as an early one is.
TEST(OracleStopSaid, TheLoopIsStoppedExactlyWhileAStopIsLatchedAndNotReset) {
  EXPECT_EQ(test::stop_said(OpState::kStopped, true), "");
  EXPECT_EQ(test::stop_said(OpState::kNotEnabled, false), "");
  EXPECT_EQ(test::stop_said(OpState::kSuspended, true), "");  // a suspend, a reload, the shutdown outrank it
  EXPECT_EQ(test::stop_said(OpState::kStopped, false),
            "the loop said \"stopped\" where the stop is reset (or none was latched)");
  EXPECT_EQ(test::stop_said(OpState::kNotEnabled, true),
            "the loop said \"not enabled\" where the stop is latched, not reset");
}

}  // namespace
}  // namespace andros::run
