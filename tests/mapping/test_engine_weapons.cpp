// The engine's weapons (docs/mapping.md, "Weapon" and the rest rule): a weapon
// fires in the base layer as in a layer; a fire input held when its weapon
// becomes possible (enabled, a weapons layer entered, armed) waits for a
// release; a weapons mode is never latched past the deadman.
#include <gtest/gtest.h>

#include "andros/mapping/engine.hpp"
#include "support/engine_steps.hpp"

namespace andros::mapping {
namespace {

using namespace testing;  // engine_steps.hpp

constexpr EngineOptions kWeapons{true, 0x01};

const std::string kHead = "robot: HD1\ndeadman: leftshoulder\n";
const std::string kWeapon = "signal: weapon_1\n    button: b\n    arm: rightshoulder\n";
// weapon_1 in the base layer, with no layers at all (the mapping).
const std::string kBase = kHead + "bindings:\n  - " + kWeapon;
// The same weapon in a layer held with y; b is front_art_up in the base.
const std::string kHeld = kHead + "bindings:\n  - signal: front_art_up\n    button: b\n" +
                          "layers:\n  weapons:\n    hold: y\n    bindings:\n      - signal: weapon_1\n"
                          "        button: b\n        arm: rightshoulder\n";
// Two toggled layers, one with the weapon.
const std::string kToggled = kHead +
                             "layers:\n  weapons:\n    toggle: y\n    bindings:\n      - signal: weapon_1\n"
                             "        button: b\n        arm: rightshoulder\n"
                             "  cam:\n    toggle: back\n    bindings:\n      - signal: focus_up\n        button: a\n";

std::uint8_t weapon_1(const protocol::DataBytes& data) {
  return protocol::read_signals(data)[protocol::signal_id("weapon_1")];
}

std::vector<input::InputKey> buttons(std::initializer_list<const char*> names) {
  std::vector<input::InputKey> keys;
  for (const auto* name : names) keys.push_back(*input::parse_button_name(name));
  return keys;
}

// Issue 15, case 5: LB at 10, RB at 20, B at 30. The arming input pressed in the
// frame of the deadman press counts (it fires nothing); b, pressed in that frame
// too, waits for a release, then fires, in the base layer as in a layer.
TEST(EngineWeapons, ABaseLayerWeaponFiresAsALayersDoes) {
  for (const auto& [yaml, layer_key] : {std::pair{kBase, ""}, std::pair{kHeld, "5 button y 1\n"}}) {
    SCOPED_TRACE(layer_key[0] != '\0' ? "in a layer" : "in the base layer");
    DrivenEngine engine(mapping_from_yaml(yaml), kWeapons);
    input::InputState in;
    engine.step(in, 0);
    apply_script(in, "0 connect\n" + std::string(layer_key) +
                         "10 button leftshoulder 1\n20 button rightshoulder 1\n"
                         "30 button b 1\n");
    EXPECT_EQ(weapon_1(engine.step(in, 40)), 0);
    EXPECT_EQ(engine.status().held_back, buttons({"b"}));  // not rightshoulder: it arms
    EXPECT_EQ(weapon_1(engine.step(in, 80)), 0);
    apply_script(in, "90 button b 0\n");
    EXPECT_EQ(weapon_1(engine.step(in, 120)), 0);
    apply_script(in, "130 button b 1\n");
    EXPECT_EQ(weapon_1(engine.step(in, 160)), 1);
    apply_script(in, "170 button rightshoulder 0\n");
    EXPECT_EQ(weapon_1(engine.step(in, 200)), 0);
  }
}

TEST(EngineWeapons, WithoutWeaponsForTheRunNothingFires) {
  DrivenEngine engine(mapping_from_yaml(kBase), EngineOptions{});
  input::InputState in;
  start_enabled(engine, in, "20 button rightshoulder 1\n");
  apply_script(in, "50 button b 1\n");
  EXPECT_EQ(weapon_1(engine.step(in, 80)), 0);
  EXPECT_FALSE(engine.status().weapons_mode);
}

// Armed while b is held: b was pressed for nothing (or for something else) and
// waits for a release; a tap in the frame that arms is dropped too.
TEST(EngineWeapons, AFireInputHeldWhenItsWeaponIsArmedWaitsForARelease) {
  DrivenEngine engine(mapping_from_yaml(kBase), kWeapons);
  input::InputState in;
  start_enabled(engine, in);
  apply_script(in, "50 button b 1\n");
  EXPECT_EQ(weapon_1(engine.step(in, 80)), 0);  // not armed
  apply_script(in, "90 button rightshoulder 1\n");
  EXPECT_EQ(weapon_1(engine.step(in, 120)), 0);
  EXPECT_EQ(engine.status().held_back, buttons({"b"}));
  EXPECT_EQ(weapon_1(engine.step(in, 160)), 0);
  apply_script(in, "170 button b 0\n180 button b 1\n");
  EXPECT_EQ(weapon_1(engine.step(in, 200)), 1);
  apply_script(in, "210 button b 0\n210 button rightshoulder 0\n");
  EXPECT_EQ(weapon_1(engine.step(in, 240)), 0);
  apply_script(in, "250 button rightshoulder 1\n255 button b 1\n260 button b 0\n");
  EXPECT_EQ(weapon_1(engine.step(in, 280)), 0);  // tapped in the frame that armed
  apply_script(in, "290 button b 1\n");
  EXPECT_EQ(weapon_1(engine.step(in, 320)), 1);
}

TEST(EngineWeapons, AFireInputHeldWhenTheBridgeIsEnabledWaitsForARelease) {
  DrivenEngine engine(mapping_from_yaml(kBase), kWeapons);
  input::InputState in;
  engine.step(in, 0);
  apply_script(in, "0 connect\n5 button b 1\n");
  EXPECT_EQ(weapon_1(engine.step(in, 40)), 0);
  apply_script(in, "50 button leftshoulder 1\n60 button rightshoulder 1\n");
  EXPECT_EQ(weapon_1(engine.step(in, 80)), 0);
  EXPECT_EQ(engine.status().held_back, buttons({"b"}));
  apply_script(in, "90 button b 0\n100 button b 1\n");
  EXPECT_EQ(weapon_1(engine.step(in, 120)), 1);
}

// Entering the layer changes what b means (front_art_up -> weapon_1): b waits.
// An arming input held since before a change waits as well, and re-arming with
// b held makes b wait again.
TEST(EngineWeapons, AFireInputHeldWhenAWeaponsLayerIsEnteredWaitsForARelease) {
  DrivenEngine engine(mapping_from_yaml(kHeld), kWeapons);
  input::InputState in;
  start_enabled(engine, in);
  apply_script(in, "50 button b 1\n");
  EXPECT_EQ(protocol::read_signals(engine.step(in, 80))[protocol::signal_id("front_art_up")], 1);
  apply_script(in, "90 button y 1\n95 button rightshoulder 1\n");
  auto f = protocol::read_signals(engine.step(in, 120));
  EXPECT_EQ(engine.status().layer, "weapons");
  EXPECT_EQ(f[protocol::signal_id("front_art_up")], 0);
  EXPECT_EQ(f[protocol::signal_id("weapon_1")], 0);
  EXPECT_EQ(engine.status().held_back, buttons({"b"}));
  apply_script(in, "130 button b 0\n140 button b 1\n");
  EXPECT_EQ(weapon_1(engine.step(in, 160)), 1);

  apply_script(in, "170 button y 0\n");  // back to the base: b (front_art_up now) waits
  EXPECT_EQ(protocol::read_signals(engine.step(in, 200))[protocol::signal_id("front_art_up")], 0);
  apply_script(in, "210 button y 1\n");  // rightshoulder held since before: it waits too
  EXPECT_EQ(weapon_1(engine.step(in, 240)), 0);
  EXPECT_EQ(engine.status().held_back, buttons({"b", "rightshoulder"}));
  apply_script(in, "250 button b 0\n260 button b 1\n");
  EXPECT_EQ(weapon_1(engine.step(in, 280)), 0);  // not armed
  apply_script(in, "290 button rightshoulder 0\n300 button rightshoulder 1\n");
  EXPECT_EQ(weapon_1(engine.step(in, 320)), 0);  // armed with b held: b waits
  apply_script(in, "330 button b 0\n340 button b 1\n");
  EXPECT_EQ(weapon_1(engine.step(in, 360)), 1);
}

TEST(EngineWeapons, TheWeaponsModeIsEnabledWithWeaponsInTheActiveLayer) {
  DrivenEngine engine(mapping_from_yaml(kHeld), kWeapons);
  input::InputState in;
  start_enabled(engine, in);
  EXPECT_FALSE(engine.status().weapons_mode);
  apply_script(in, "50 button y 1\n");
  engine.step(in, 80);
  EXPECT_TRUE(engine.status().weapons_mode);
  apply_script(in, "90 button leftshoulder 0\n");
  engine.step(in, 120);
  EXPECT_EQ(engine.status().layer, "weapons");  // a held layer is shown while not enabled...
  EXPECT_FALSE(engine.status().weapons_mode);   // ...but nothing can fire
  apply_script(in, "130 button leftshoulder 1\n");
  engine.step(in, 160);
  EXPECT_TRUE(engine.status().weapons_mode);
  apply_script(in, "170 button y 0\n");
  engine.step(in, 200);
  EXPECT_FALSE(engine.status().weapons_mode);

  DrivenEngine without(mapping_from_yaml(kHeld), EngineOptions{});
  input::InputState pad;
  start_enabled(without, pad, "20 button y 1\n");
  EXPECT_EQ(without.status().layer, "weapons");
  EXPECT_FALSE(without.status().weapons_mode);  // no --weapons

  // Weapons in the base layer: a weapons mode whenever enabled.
  DrivenEngine base(mapping_from_yaml(kBase), kWeapons);
  input::InputState other;
  start_enabled(base, other);
  EXPECT_TRUE(base.status().weapons_mode);
}

// Issue 15, case 4: nothing is latched past the deadman. A toggled layer, a
// weapons layer above all, ends with the deadman, with any stop (restart) and
// with the controller.
TEST(EngineWeapons, ToggledLayersEndWithTheDeadmanAndAnyStop) {
  DrivenEngine engine(mapping_from_yaml(kToggled), kWeapons);
  input::InputState in;
  start_enabled(engine, in, "20 button y 1\n25 button y 0\n");
  EXPECT_EQ(engine.status().layer, "weapons");
  EXPECT_TRUE(engine.status().weapons_mode);
  apply_script(in, "50 button leftshoulder 0\n");
  engine.step(in, 80);
  EXPECT_EQ(engine.status().layer, "");
  EXPECT_FALSE(engine.status().weapons_mode);
  apply_script(in, "90 button leftshoulder 1\n95 button rightshoulder 1\n");
  engine.step(in, 120);
  EXPECT_EQ(engine.status().layer, "");  // still off: the layer needs its toggle again
  apply_script(in, "130 button b 1\n");
  EXPECT_EQ(weapon_1(engine.step(in, 160)), 0);

  apply_script(in, "170 button back 1\n175 button back 0\n");  // any toggled layer
  engine.step(in, 200);
  EXPECT_EQ(engine.status().layer, "cam");
  apply_script(in, "210 button leftshoulder 0\n");
  engine.step(in, 240);
  EXPECT_EQ(engine.status().layer, "");

  apply_script(in, "250 button leftshoulder 1\n255 button y 1\n260 button y 0\n");
  engine.step(in, 280);
  EXPECT_EQ(engine.status().layer, "weapons");
  engine.restart(in);  // a stop: suspend, reload, ...
  engine.step(in, 320);
  EXPECT_EQ(engine.status().layer, "");
  EXPECT_FALSE(engine.status().weapons_mode);

  apply_script(in, "330 button leftshoulder 0\n");
  engine.step(in, 340);
  apply_script(in, "340 button leftshoulder 1\n345 button y 1\n350 button y 0\n");
  engine.step(in, 360);
  EXPECT_EQ(engine.status().layer, "weapons");
  apply_script(in, "370 disconnect\n380 connect\n");
  engine.step(in, 400);
  EXPECT_EQ(engine.status().layer, "");
}

// The shipped layout: a stray left-stick click while driving is the camera
// layer; weapons are live only while RB is held.
TEST(EngineWeapons, OnTheShippedLayoutWeaponsAreLiveOnlyWhileRBIsHeld) {
  DrivenEngine engine(hd1_mapping(), kWeapons);
  input::InputState in;
  start_enabled(engine, in);
  apply_script(in, "50 axis lefty -32768\n60 button leftstick 1\n65 button leftstick 0\n");
  engine.step(in, 80);
  EXPECT_EQ(engine.status().layer, "camera");
  EXPECT_FALSE(engine.status().weapons_mode);
  apply_script(in, "90 axis lefty 0\n90 button leftstick 1\n95 button leftstick 0\n");
  engine.step(in, 120);
  apply_script(in, "130 button rightshoulder 1\n140 axis lefttrigger 32767\n");
  engine.step(in, 160);
  EXPECT_EQ(engine.status().layer, "weapons");
  EXPECT_TRUE(engine.status().weapons_mode);
  apply_script(in, "170 button a 1\n");
  EXPECT_EQ(weapon_1(engine.step(in, 200)), 1);
  apply_script(in, "210 button rightshoulder 0\n");
  const auto f = protocol::read_signals(engine.step(in, 240));
  EXPECT_EQ(engine.status().layer, "");
  EXPECT_FALSE(engine.status().weapons_mode);
  EXPECT_EQ(f[protocol::signal_id("weapon_1")], 0);
  EXPECT_EQ(f[protocol::signal_id("rear_art_down")], 0);  // a, held across the change, waits
  EXPECT_EQ(f[protocol::signal_id("fiber_takeup")], 0);   // and LT
}

// Issue 19, finding 7: "armed" is what the screen says while the arming input
// is held in a weapons mode, and only then.
TEST(EngineWeapons, ArmedIsTheArmingInputHeldInAWeaponsMode) {
  DrivenEngine engine(mapping_from_yaml(kHeld), kWeapons);
  input::InputState in;
  start_enabled(engine, in);
  apply_script(in, "50 button rightshoulder 1\n");
  engine.step(in, 80);
  EXPECT_FALSE(engine.status().armed);  // held, but not in the weapons layer
  apply_script(in, "90 button y 1\n");
  engine.step(in, 120);
  EXPECT_TRUE(engine.status().weapons_mode);
  EXPECT_FALSE(engine.status().armed);  // held through the layer change: it must be let go first
  apply_script(in, "130 button rightshoulder 0\n140 button rightshoulder 1\n");
  engine.step(in, 160);
  EXPECT_TRUE(engine.status().armed);
  apply_script(in, "170 button rightshoulder 0\n");
  engine.step(in, 200);
  EXPECT_FALSE(engine.status().armed);
  apply_script(in, "210 button rightshoulder 1\n");
  engine.step(in, 240);
  EXPECT_TRUE(engine.status().armed);
  apply_script(in, "250 button leftshoulder 0\n");
  engine.step(in, 280);
  EXPECT_FALSE(engine.status().armed);  // the deadman released: no weapons mode, nothing armed

  DrivenEngine without(mapping_from_yaml(kHeld), EngineOptions{});
  input::InputState pad;
  start_enabled(without, pad, "20 button y 1\n30 button rightshoulder 1\n");
  EXPECT_FALSE(without.status().armed);  // no --weapons
}

}  // namespace
}  // namespace andros::mapping
