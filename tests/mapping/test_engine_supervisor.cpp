// The engine and the supervisor's controller (docs/mapping.md, "The
// supervisor's controller"): its stop is reported for the run loop to latch;
// its weapons consent gates every weapon (a two-person rule) and, like an
// arming input, counts only when seen pressed since it took on its meaning;
// its controller back is a fresh start.
#include <gtest/gtest.h>

#include "andros/mapping/engine.hpp"
#include "support/engine_steps.hpp"

namespace andros::mapping {
namespace {

using namespace testing;  // engine_steps.hpp

constexpr EngineOptions kWeapons{true, 0x01};

// weapon_1: b with rightshoulder held; the supervisor's stop is x, its consent a.
const std::string kHead = "robot: HD1\ndeadman: leftshoulder\nsupervisor:\n  stop: x\n  weapons_consent: a\n";
const std::string kBase = kHead +
                          "bindings:\n  - signal: weapon_1\n    button: b\n    arm: rightshoulder\n"
                          "  - signal: front_art_up\n    button: dpup\n";
// The weapon in a layer held with y.
const std::string kHeld = kHead +
                          "layers:\n  weapons:\n    hold: y\n    bindings:\n      - signal: weapon_1\n"
                          "        button: b\n        arm: rightshoulder\n";

std::uint8_t weapon_1(const protocol::DataBytes& data) {
  return protocol::read_signals(data)[protocol::signal_id("weapon_1")];
}

/// Both controllers at 0, the deadman pressed at 10, `also` in that frame; enabled at 40.
void start_both(DrivenEngine& engine, input::InputState& in, const std::string& also = "") {
  engine.step(in, 0);
  apply_script(in, "0 connect\n0 supervisor connect\n10 button leftshoulder 1\n" + also);
  engine.step(in, 40);
  ASSERT_EQ(engine.status().deadman, DeadmanState::kFreshHold);
}

TEST(EngineSupervisor, TheSupervisorsStopIsReportedPressedAndWhileHeld) {
  DrivenEngine engine(mapping_from_yaml(kBase), EngineOptions{});
  input::InputState in;
  start_both(engine, in);
  EXPECT_FALSE(engine.status().stop_pressed);
  apply_script(in, "50 supervisor button x 1\n");
  engine.step(in, 80);
  EXPECT_TRUE(engine.status().stop_pressed);
  EXPECT_TRUE(engine.status().stop_held);
  EXPECT_TRUE(engine.status().supervisor_stop);
  engine.step(in, 120);
  EXPECT_TRUE(engine.status().stop_pressed);  // held
  apply_script(in, "130 supervisor button x 0\n");
  engine.step(in, 160);
  EXPECT_FALSE(engine.status().stop_pressed);
  EXPECT_FALSE(engine.status().stop_held);
  // A tap between two ticks.
  apply_script(in, "170 supervisor button x 1\n175 supervisor button x 0\n");
  engine.step(in, 200);
  EXPECT_TRUE(engine.status().stop_pressed);
  EXPECT_FALSE(engine.status().stop_held);
  engine.step(in, 240);
  EXPECT_FALSE(engine.status().stop_pressed);  // reported once
  // The operator's x is another button.
  apply_script(in, "250 button x 1\n");
  engine.step(in, 280);
  EXPECT_FALSE(engine.status().stop_pressed);
  // A restart (a reload, a resume) does not swallow a tap made before it.
  apply_script(in, "290 supervisor button x 1\n295 supervisor button x 0\n");
  engine.restart(in);
  engine.step(in, 320);
  EXPECT_TRUE(engine.status().stop_pressed);
  // Held when its controller connects: a stop too.
  apply_script(in, "330 supervisor disconnect\n340 supervisor connect\n340 supervisor button x 1\n");
  engine.step(in, 360);
  EXPECT_TRUE(engine.status().stop_pressed);
  EXPECT_TRUE(engine.status().stop_held);
}

TEST(EngineSupervisor, WithoutASupervisorSectionNothingIsReported) {
  DrivenEngine engine(hd1_mapping(), EngineOptions{});
  input::InputState in;
  engine.step(in, 0);
  apply_script(in, "0 connect\n0 supervisor connect\n10 supervisor button b 1\n");
  engine.step(in, 40);
  EXPECT_FALSE(engine.status().stop_pressed);
  EXPECT_EQ(engine.status().consent, ConsentState::kNotAsked);
}

// Two people: the operator's fire and arm, and the supervisor's consent.
TEST(EngineSupervisor, AWeaponFiresOnlyWhileTheSupervisorConsents) {
  DrivenEngine engine(mapping_from_yaml(kBase), kWeapons);
  input::InputState in;
  start_both(engine, in, "20 button rightshoulder 1\n");
  EXPECT_EQ(engine.status().consent, ConsentState::kReleased);
  apply_script(in, "50 button b 1\n");
  EXPECT_EQ(weapon_1(engine.step(in, 80)), 0);  // armed, no consent
  apply_script(in, "90 supervisor button a 1\n");
  EXPECT_EQ(weapon_1(engine.step(in, 120)), 0);  // consent came with b held: b waits
  EXPECT_EQ(engine.status().consent, ConsentState::kGiven);
  apply_script(in, "130 button b 0\n140 button b 1\n");
  EXPECT_EQ(weapon_1(engine.step(in, 160)), 1);
  apply_script(in, "170 supervisor button a 0\n");
  EXPECT_EQ(weapon_1(engine.step(in, 200)), 0);  // withdrawn
  apply_script(in, "210 supervisor button a 1\n");
  EXPECT_EQ(weapon_1(engine.step(in, 240)), 0);  // given again with b held: b waits again
  apply_script(in, "250 button b 0\n260 button b 1\n");
  EXPECT_EQ(weapon_1(engine.step(in, 280)), 1);
  apply_script(in, "290 supervisor disconnect\n");
  EXPECT_EQ(weapon_1(engine.step(in, 320)), 0);  // no supervisor, no consent
  EXPECT_EQ(engine.status().consent, ConsentState::kReleased);
}

// Like an arming input: pressed in the frame it takes on its meaning it counts;
// held since before (taped down) it waits for a release.
TEST(EngineSupervisor, AConsentHeldSinceBeforeCountsOnlyOnceReleasedAndPressedAgain) {
  DrivenEngine engine(mapping_from_yaml(kBase), kWeapons);
  input::InputState in;
  engine.step(in, 0);
  apply_script(in, "0 connect\n0 supervisor connect\n5 supervisor button a 1\n");
  engine.step(in, 40);  // not enabled: consent means nothing yet
  apply_script(in, "50 button leftshoulder 1\n60 button rightshoulder 1\n");
  EXPECT_EQ(weapon_1(engine.step(in, 80)), 0);
  EXPECT_EQ(engine.status().deadman, DeadmanState::kFreshHold);
  EXPECT_EQ(engine.status().consent, ConsentState::kHeldBack);
  apply_script(in, "90 button b 1\n");
  EXPECT_EQ(weapon_1(engine.step(in, 120)), 0);  // armed and fired, but the consent is stale
  apply_script(in, "130 supervisor button a 0\n");
  engine.step(in, 160);
  EXPECT_EQ(engine.status().consent, ConsentState::kReleased);
  apply_script(in, "170 supervisor button a 1\n");
  EXPECT_EQ(weapon_1(engine.step(in, 200)), 0);  // b held when the consent came: b waits
  apply_script(in, "210 button b 0\n220 button b 1\n");
  EXPECT_EQ(weapon_1(engine.step(in, 240)), 1);

  // A release and a press between two frames count as such.
  DrivenEngine tap(mapping_from_yaml(kBase), kWeapons);
  input::InputState pad;
  tap.step(pad, 0);
  apply_script(pad,
               "0 connect\n0 supervisor connect\n0 supervisor button a 1\n10 button leftshoulder 1\n"
               "20 button rightshoulder 1\n");
  tap.step(pad, 40);
  EXPECT_EQ(tap.status().consent, ConsentState::kHeldBack);  // held at its connect
  apply_script(pad, "50 supervisor button a 0\n55 supervisor button a 1\n");
  tap.step(pad, 80);
  EXPECT_EQ(tap.status().consent, ConsentState::kGiven);
  apply_script(pad, "90 button b 1\n");
  EXPECT_EQ(weapon_1(tap.step(pad, 120)), 1);
}

TEST(EngineSupervisor, AConsentPressedInTheFrameOfTheDeadmanPressCounts) {
  DrivenEngine engine(mapping_from_yaml(kBase), kWeapons);
  input::InputState in;
  start_both(engine, in, "20 supervisor button a 1\n25 button rightshoulder 1\n");
  EXPECT_EQ(engine.status().consent, ConsentState::kGiven);
  apply_script(in, "50 button b 1\n");
  EXPECT_EQ(weapon_1(engine.step(in, 80)), 1);
}

// Consent means something only where a weapon is in effect: held in the base
// layer, it is stale once the weapons layer is entered; pressed in the frame
// the layer is entered, it counts.
TEST(EngineSupervisor, EnteringAWeaponsLayerGivesTheConsentItsMeaning) {
  DrivenEngine engine(mapping_from_yaml(kHeld), kWeapons);
  input::InputState in;
  start_both(engine, in, "20 supervisor button a 1\n");
  EXPECT_EQ(engine.status().consent, ConsentState::kGiven);  // no weapon here: nothing to hold back
  apply_script(in, "50 button y 1\n55 button rightshoulder 1\n");
  engine.step(in, 80);
  EXPECT_EQ(engine.status().layer, "weapons");
  EXPECT_EQ(engine.status().consent, ConsentState::kHeldBack);
  apply_script(in, "90 button b 1\n");
  EXPECT_EQ(weapon_1(engine.step(in, 120)), 0);

  apply_script(in, "130 button y 0\n135 button b 0\n140 supervisor button a 0\n");
  engine.step(in, 160);
  apply_script(in, "170 button y 1\n175 supervisor button a 1\n");  // in the frame the layer is entered
  engine.step(in, 200);
  EXPECT_EQ(engine.status().consent, ConsentState::kGiven);
  apply_script(in, "210 button b 1\n");
  EXPECT_EQ(weapon_1(engine.step(in, 240)), 0);  // the arm, held since before the layer, waits
  apply_script(in, "250 button rightshoulder 0\n255 button rightshoulder 1\n260 button b 0\n");
  EXPECT_EQ(weapon_1(engine.step(in, 280)), 0);
  apply_script(in, "290 button b 1\n");
  EXPECT_EQ(weapon_1(engine.step(in, 320)), 1);
}

// The supervisor's controller new or back: the deadman held through it is history.
TEST(EngineSupervisor, TheSupervisorsControllerBackNeedsAFreshDeadmanPress) {
  DrivenEngine engine(mapping_from_yaml(kBase), EngineOptions{});
  input::InputState in;
  start_both(engine, in, "20 button dpup 1\n");
  apply_script(in, "50 supervisor disconnect\n60 supervisor connect\n");
  auto f = protocol::read_signals(engine.step(in, 80));
  EXPECT_EQ(engine.status().deadman, DeadmanState::kHeldNotFresh);
  EXPECT_EQ(f[protocol::signal_id("front_art_up")], 0);
  apply_script(in, "90 button leftshoulder 0\n");
  engine.step(in, 100);
  apply_script(in, "110 button leftshoulder 1\n");
  f = protocol::read_signals(engine.step(in, 120));
  EXPECT_EQ(engine.status().deadman, DeadmanState::kFreshHold);
  EXPECT_EQ(f[protocol::signal_id("front_art_up")], 0);  // dpup, held across, waits for a release
  EXPECT_EQ(engine.status().held_back, std::vector{*input::parse_button_name("dpup")});
}

}  // namespace
}  // namespace andros::mapping
