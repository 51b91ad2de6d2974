// The mapping loader and validate(): every class of bad file docs/mapping.md
// lists is rejected at its FILE:LINE:COL, and good files mean what they say.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "andros/base/version.hpp"
#include "andros/mapping/loader.hpp"
#include "support/input_error.hpp"
#include "support/temp_dir.hpp"

namespace andros::mapping {
namespace {

namespace fs = std::filesystem;

using MappingDir = testing::TempDir;

const std::string kHead = "robot: HD1\ndeadman: leftshoulder\nbindings:\n";  // bindings start on line 4
const std::string kUnbindHead = "robot: HD1\nextends: base.yaml\nbindings:\n";
const std::string kUnbindBase =
    "deadman: leftshoulder\nbindings:\n  - signal: front_art_up\n    button: dpup\nlayers:\n  arm:\n"
    "    hold: rightshoulder\n    bindings:\n      - signal: gripper_open\n        button: a\n";

struct BadMapping {
  const char* what;
  std::string text;
  int line;
  int column;
  const char* message;            // a substring of the error
  std::string base = "";          // written as base.yaml beside it
  const char* file = "bad.yaml";  // the file the error names
};

void PrintTo(const BadMapping& c, std::ostream* os) { *os << c.what; }

class MappingErrors : public ::testing::TestWithParam<BadMapping> {};

TEST_P(MappingErrors, NameFileLineAndColumn) {
  const auto& c = GetParam();
  MappingDir dir;
  if (!c.base.empty()) dir.write("base.yaml", c.base);
  const auto file = dir.write("bad.yaml", c.text);
  testing::expect_input_error([&] { load_mapping(file); }, c.file, c.line, c.column, c.message, c.text);
}

INSTANTIATE_TEST_SUITE_P(
    Catalogue, MappingErrors,
    ::testing::Values(
        BadMapping{"stop_reset_hold below 1 s", "robot: HD1\ndeadman: leftshoulder\nstop_reset_hold: 0.5\n", 3, 18,
                   "stop_reset_hold 0.5 is out of range 1..10"},
        BadMapping{"stop_reset_hold above 10 s", "robot: HD1\ndeadman: leftshoulder\nstop_reset_hold: 11\n", 3, 18,
                   "stop_reset_hold 11 is out of range 1..10"},
        // The reset gesture: never a stop button (a stop only ever stops), nor the deadman, nor an axis.
        BadMapping{"stop_reset on the stop button",
                   "robot: HD1\ndeadman: leftshoulder\nestop: guide\nstop_reset: [back, guide]\n", 4, 20,
                   "'guide' is the stop button (line 3): a stop button only ever stops, it cannot also reset"},
        BadMapping{"stop_reset on the deadman", "robot: HD1\ndeadman: leftshoulder\nstop_reset: leftshoulder\n", 3, 13,
                   "'leftshoulder' is the deadman"},
        BadMapping{"stop_reset an axis", "robot: HD1\ndeadman: leftshoulder\nstop_reset: [back, lefty]\n", 3, 20,
                   "unknown button 'lefty'"},
        BadMapping{"stop_reset a chord of three", "robot: HD1\ndeadman: leftshoulder\nstop_reset: [a, b, x]\n", 3, 13,
                   "a chord of 2 buttons held together"},
        BadMapping{"stop_reset the same button twice", "robot: HD1\ndeadman: leftshoulder\nstop_reset: [back, back]\n",
                   3, 20, "'back' is twice in stop_reset"},
        BadMapping{"the supervisor's reset on its stop",
                   "robot: HD1\ndeadman: leftshoulder\nsupervisor: {stop: b, reset: [b, start]}\n", 3, 31,
                   "'b' is the supervisor's stop button (line 3): a stop button only ever stops"},
        BadMapping{"the supervisor's reset on its consent",
                   "robot: HD1\ndeadman: leftshoulder\nsupervisor: {stop: b, weapons_consent: a, reset: a}\n", 3, 50,
                   "'a' is the supervisor's weapons consent"},
        BadMapping{"a stop on a hat a pad cannot have", "robot: HD1\ndeadman: leftshoulder\nestop: hat9left\n", 3, 8,
                   "estop 'hat9left' is on a hat a controller may not have"},
        BadMapping{"the supervisor's stop on such a hat",
                   "robot: HD1\ndeadman: leftshoulder\nsupervisor:\n  stop: hat1up\n", 4, 9,
                   "the supervisor's stop 'hat1up' is on a hat a controller may not have"},
        BadMapping{"unknown top-level key", "robot: HD1\ndeadman: leftshoulder\nrobto: F6A\n", 3, 1,
                   "unknown key 'robto' in a mapping file"},
        BadMapping{"unknown binding key", kHead + "  - signal: tool_on\n    butten: a\n", 5, 5,
                   "unknown key 'butten' in a button binding"},
        BadMapping{"unknown constants key", "robot: HD1\ndeadman: a\nconstants: {byte13: 0}\n", 3, 13,
                   "unknown key 'byte13'"},
        BadMapping{"unknown signal", kHead + "  - signal: front_art_upp\n    button: a\n", 4, 13,
                   "unknown signal 'front_art_upp'"},
        BadMapping{"unknown button", kHead + "  - signal: tool_on\n    button: trigger\n", 5, 13,
                   "unknown button 'trigger'"},
        BadMapping{"unknown axis", kHead + "  - analog: drive\n    axis: lefttrig\n", 5, 11, "unknown axis 'lefttrig'"},
        BadMapping{"unknown robot", "robot: HD2\ndeadman: a\n", 1, 8, "unknown robot 'HD2'"},
        BadMapping{"fixed validation bit", kHead + "  - signal: byte2.3\n    button: a\n", 4, 13,
                   "byte 2 bit 3 is a fixed validation bit"},
        BadMapping{"byte 15", kHead + "  - analog: byte15\n    axis: leftx\n", 4, 13, "byte 15 is fixed at 0x02"},
        BadMapping{"interlock safety", kHead + "  - signal: safety\n    button: a\n", 4, 13,
                   "'safety' is set by the safety layer"},
        BadMapping{"interlock by address", kHead + "  - signal: byte0.2\n    button: a\n", 4, 13,
                   "'drive_brake' is set by the safety layer"},
        BadMapping{"constant code", kHead + "  - analog: code\n    axis: leftx\n", 4, 13,
                   "'code' is not an analog byte"},
        BadMapping{"selector signal on a button", kHead + "  - signal: speed_high\n    button: a\n", 4, 13,
                   "selector-like switch"},
        // center only trims the enabled rest, within 128 +- 8: neutral frames carry 128 whatever it says.
        BadMapping{"centre 300", "robot: HD1\ndeadman: a\ncenter: 300\n", 3, 9,
                   "center 300 is out of range 120..136 (it only trims"},
        BadMapping{"centre 0", "robot: HD1\ndeadman: a\ncenter: 0\n", 3, 9,
                   "center 0 is out of range 120..136 (it only trims drive and pivot's rest while enabled; neutral "
                   "frames carry 128)"},
        BadMapping{"centre 255", "robot: HD1\ndeadman: a\ncenter: 255\n", 3, 9, "center 255 is out of range 120..136"},
        BadMapping{"centre 119", "robot: HD1\ndeadman: a\ncenter: 119\n", 3, 9, "center 119 is out of range 120..136"},
        BadMapping{"centre 137 in hex", "robot: HD1\ndeadman: a\ncenter: 0x89\n", 3, 9,
                   "center 0x89 is out of range 120..136"},
        BadMapping{"centre -1", "robot: HD1\ndeadman: a\ncenter: -1\n", 3, 9, "center -1 is out of range 120..136"},
        BadMapping{"centre 0 in the base", "robot: HD1\nextends: base.yaml\n", 2, 9,
                   "center 0 is out of range 120..136", "deadman: a\ncenter: 0\n", "base.yaml"},
        BadMapping{"battery out of range", "robot: HD1\ndeadman: a\nconstants: {battery: 0x100}\n", 3, 22,
                   "battery 0x100 is out of range"},
        BadMapping{"deadzone of 1", kHead + "  - analog: drive\n    axis: lefty\n    deadzone: 1.0\n", 6, 15,
                   "deadzone 1.0 is out of range 0..1 (excluded)"},
        BadMapping{"expo above 1", kHead + "  - analog: drive\n    axis: lefty\n    expo: 1.5\n", 6, 11,
                   "expo 1.5 is out of range"},
        BadMapping{"threshold of 0", kHead + "  - signal: [pt_left, pt_right]\n    axis: rightx\n    threshold: 0\n", 6,
                   16, "threshold must be above 0"},
        BadMapping{"knob rate of 0", kHead + "  - analog: light\n    increase: a\n    decrease: b\n    rate: 0\n", 7,
                   11, "rate (units per second) 0 is out of range"},
        BadMapping{"knob initial 256",
                   kHead + "  - analog: light\n    increase: a\n    decrease: b\n    rate: 10\n    initial: 256\n", 8,
                   14, "initial 256 is out of range"},
        BadMapping{"not a number", kHead + "  - analog: drive\n    axis: lefty\n    expo: lots\n", 6, 11,
                   "expo 'lots' is not a number"},
        BadMapping{"not a boolean", kHead + "  - signal: tool_on\n    button: a\n    toggle: yes\n", 6, 13,
                   "toggle must be true or false"},
        BadMapping{"input bound twice",
                   kHead + "  - signal: tool_on\n    button: a\n  - signal: zoom_up\n    button: a\n", 7, 13,
                   "'a' is bound twice in this layer (first at line 5)"},
        BadMapping{"input twice in a layer",
                   kHead + "  - signal: tool_on\n    button: a\nlayers:\n  arm:\n    hold: b\n    bindings:\n      - "
                           "signal: zoom_up\n        button: x\n      - analog: light\n        increase: x\n        "
                           "decrease: y\n        rate: 9\n",
                   13, 19, "'x' is bound twice in this layer (first at line 11)"},
        BadMapping{"two bindings on one analog byte",
                   kHead + "  - analog: drive\n    axis: lefty\n  - analog: drive\n    axis: righty\n", 6, 13,
                   "'drive' is driven by two bindings in this layer (first at line 4)"},
        BadMapping{"weapon without arm", kHead + "  - signal: weapon_1\n    button: b\n", 4, 5, "needs 'arm'"},
        BadMapping{"weapon toggle", kHead + "  - signal: laser\n    button: b\n    arm: a\n    toggle: true\n", 7, 5,
                   "unknown key 'toggle' in a weapon binding"},
        BadMapping{"arm on a non-weapon", kHead + "  - signal: tool_on\n    button: b\n    arm: a\n", 4, 13,
                   "'arm' is only for weapon signals"},
        BadMapping{"arm is the deadman", kHead + "  - signal: weapon_2\n    button: b\n    arm: leftshoulder\n", 6, 10,
                   "not the deadman"},
        BadMapping{
            "arm is a layer key",
            kHead + "  - signal: weapon_2\n    button: b\n    arm: y\nlayers:\n  w:\n    hold: y\n    bindings: []\n",
            6, 10, "'arm' must be a second button, not the key of a layer (line 9)"},
        BadMapping{"arm fires something else",
                   kHead + "  - signal: weapon_2\n    button: b\n    arm: a\n  - signal: tool_on\n    button: a\n", 6,
                   10, "arming input 'a' is also bound at line 8"},
        BadMapping{"deadman bound", kHead + "  - signal: tool_on\n    button: leftshoulder\n", 5, 13,
                   "'leftshoulder' is the deadman or switches a layer"},
        BadMapping{"deadman on a stick", "robot: HD1\ndeadman: leftx\n", 2, 10,
                   "deadman 'leftx' is not a button or a trigger"},
        BadMapping{"arm on a stick", kHead + "  - signal: weapon_2\n    button: b\n    arm: rightx\n", 6, 10,
                   "arm 'rightx' is not a button or a trigger"},
        BadMapping{"knob on drive", kHead + "  - analog: drive\n    increase: a\n    decrease: b\n    rate: 10\n", 4,
                   13, "must return to centre"},
        BadMapping{"pair of a selector", kHead + "  - signal: [speed_low, speed_high]\n    axis: rightx\n", 4, 13,
                   "selector-like switch"},
        BadMapping{"pair of one signal", kHead + "  - signal: [pt_left, pt_left]\n    axis: rightx\n", 4, 13,
                   "two different signals"},
        BadMapping{"selector of a motion signal",
                   kHead + "  - selector: s\n    next: a\n    positions: [[], [tool_on]]\n", 6, 16,
                   "'tool_on' is not one"},
        BadMapping{"selector position both ways",
                   kHead + "  - selector: s\n    next: a\n    positions: [[], [speed_low, speed_high]]\n", 6, 16,
                   "and its opposite"},
        BadMapping{"selector initial out of range",
                   kHead + "  - selector: s\n    next: a\n    positions: [[], [speed_low]]\n    initial: 2\n", 7, 14,
                   "initial position 2 is out of range 0..1"},
        BadMapping{"toggle and momentary on one signal",
                   kHead + "  - signal: tool_on\n    button: x\n    toggle: true\n  - signal: tool_on\n    button: y\n",
                   7, 13, "'tool_on' is a toggle at line 4; a signal is either toggled or momentary"},
        BadMapping{"pair and toggle on one signal",
                   kHead + "  - signal: [pt_left, pt_right]\n    axis: rightx\nlayers:\n  cam:\n    toggle: b\n    "
                           "bindings:\n      - signal: pt_left\n        button: x\n        toggle: true\n",
                   10, 17, "'pt_left' is momentary at line 4"},
        BadMapping{"momentary beside a base's toggle",
                   "robot: HD1\nextends: base.yaml\nbindings:\n  - signal: tool_on\n    button: y\n", 4, 13,
                   "'tool_on' is a toggle at line 3 of ",
                   "deadman: a\nbindings:\n  - signal: tool_on\n    button: x\n    toggle: true\n"},
        BadMapping{"binding with two kinds", kHead + "  - signal: tool_on\n    analog: drive\n    button: a\n", 4, 5,
                   "exactly one of 'signal', 'analog' or 'selector'"},
        BadMapping{"layer with no switch", "robot: HD1\ndeadman: a\nlayers:\n  arm:\n    bindings: []\n", 5, 5,
                   "needs exactly one of 'hold: BUTTON' or 'toggle: BUTTON'"},
        BadMapping{"layer switch is the deadman",
                   "robot: HD1\ndeadman: a\nlayers:\n  arm:\n    hold: a\n    bindings: []\n", 5, 11,
                   "already switches a layer or is the deadman"},
        BadMapping{"key given twice", "robot: HD1\ndeadman: a\nrobot: F6A\n", 3, 1, "key 'robot' given twice"},
        BadMapping{"layer given twice in one file",
                   "robot: HD1\ndeadman: a\nlayers:\n  arm:\n    hold: b\n    bindings: []\n  arm:\n    hold: x\n    "
                   "bindings: []\n",
                   7, 3, "layer 'arm' given twice"},
        BadMapping{"YAML syntax", kHead + "  - signal: tool_on\n    button: [a\n", 6, 1, "YAML syntax"},
        BadMapping{"missing robot", "deadman: a\n", 0, 0, "missing 'robot'"},
        BadMapping{"missing deadman", "robot: HD1\n", 0, 0, "missing 'deadman'"},
        BadMapping{"extends a missing file", "robot: HD1\nextends: nowhere.yaml\n", 2, 10, "cannot open mapping file"},
        BadMapping{"error inside the base", "robot: HD1\nextends: base.yaml\n", 4, 5, "unknown key 'buton'",
                   "deadman: a\nbindings:\n  - signal: tool_on\n    buton: x\n", "base.yaml"},
        BadMapping{
            "signal twice in a position",
            kHead + "  - selector: cam\n    next: a\n    positions: [[main_video_2, main_video_3, main_video_2], []]\n",
            6, 46, "'main_video_2' is given twice in this position"},
        BadMapping{"signal twice in a position through an alias",
                   kHead + "  - selector: cam\n    next: a\n    positions: [[&v main_video_2, *v], []]\n", 6, 18,
                   "'main_video_2' is given twice in this position"},
        BadMapping{"a second document", "robot: HD1\ndeadman: a\n---\nrobot: F6A\n", 4, 1, "a second YAML document"},
        BadMapping{"an empty second document", "robot: HD1\ndeadman: a\n---\n", 4, 1, "a second YAML document"},
        // yaml-cpp's parser stands still on a lone ',' (reading every document never ends): a fuzz finding.
        BadMapping{"a lone comma", ",\n", 1, 1, "YAML syntax: unexpected ','"},
        BadMapping{"a comma before a key", ",extends: other.yaml\n\n", 1, 1, "YAML syntax: unexpected ','"},
        BadMapping{"an alias inside what it names", "robot: HD1\ndeadman: a\nbindings: &b [*b]\n", 3, 11,
                   "more than 100000 YAML nodes"},
        BadMapping{"extends cycle", "robot: HD1\nextends: base.yaml\n", 1, 10,
                   "'extends' makes a cycle: bad.yaml -> base.yaml -> bad.yaml", "extends: bad.yaml\n", "base.yaml"},
        BadMapping{"unbind of an input the base does not bind", kUnbindHead + "  - unbind: paddle2\n", 4, 13,
                   "'unbind: paddle2': the file this one extends binds nothing to it in this layer", kUnbindBase},
        BadMapping{"unbind with no extends", kHead + "  - unbind: dpup\n", 4, 13, "binds nothing to it", kUnbindBase},
        BadMapping{"unbind of a base-layer input in a layer",
                   "robot: HD1\nextends: base.yaml\nlayers:\n  arm:\n    hold: rightshoulder\n    bindings:\n      - "
                   "unbind: dpup\n",
                   7, 17, "binds nothing to it in this layer", kUnbindBase},
        BadMapping{"unbind of an unknown input", kUnbindHead + "  - unbind: dpupp\n", 4, 13, "unknown input 'dpupp'",
                   kUnbindBase},
        BadMapping{"unbind with another key", kUnbindHead + "  - unbind: dpup\n    button: a\n", 5, 5,
                   "unknown key 'button' in an unbind item", kUnbindBase},
        // The supervisor's controller's buttons.
        BadMapping{"supervisor section without stop", "robot: HD1\ndeadman: a\nsupervisor:\n  weapons_consent: a\n", 4,
                   3, "the supervisor section needs 'stop: BUTTON'"},
        BadMapping{"supervisor section with an unknown key",
                   "robot: HD1\ndeadman: a\nsupervisor:\n  stop: b\n  consent: a\n", 5, 3,
                   "unknown key 'consent' in the supervisor section (expected stop, reset, weapons_consent)"},
        BadMapping{"supervisor stop an axis", "robot: HD1\ndeadman: a\nsupervisor: {stop: leftx}\n", 3, 20,
                   "unknown button 'leftx'"},
        BadMapping{"supervisor section not a map", "robot: HD1\ndeadman: a\nsupervisor: b\n", 3, 13,
                   "the supervisor section"},
        BadMapping{"supervisor consent the stop",
                   "robot: HD1\ndeadman: a\nsupervisor:\n  stop: b\n  weapons_consent: b\n", 5, 20,
                   "the supervisor's 'weapons_consent' must be a different button from its 'stop' (line 4)"}),
    [](const auto& param_info) {
      std::string name = param_info.param.what;
      for (auto& ch : name) ch = std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
      return name;
    });

// c0.yaml extends c1.yaml ... extends c{n-1}.yaml, the last a plain base.
fs::path write_chain(const MappingDir& dir, int n) {
  for (int i = 0; i < n; ++i) {
    std::string text = i == 0 ? "robot: HD1\ndeadman: leftshoulder\n" : "";
    text += i + 1 < n ? "extends: c" + std::to_string(i + 1) + ".yaml\n" : "bindings: []\n";
    dir.write("c" + std::to_string(i) + ".yaml", text);
  }
  return dir.path() / "c0.yaml";
}

TEST(MappingLoader, ExtendsChainOfSixteenFilesLoads) {
  MappingDir dir;
  EXPECT_EQ(load_mapping(write_chain(dir, 16))->robot, "HD1");
}

TEST(MappingLoader, ExtendsChainLongerThanSixteenFilesIsRefusedAtTheExtendsTooFar) {
  for (const int n : {17, 9000}) {  // 9,000 nested loads overflowed the stack
    MappingDir dir;
    try {
      load_mapping(write_chain(dir, n));
      FAIL() << n << " files accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(fs::path(e.pos().file).filename(), "c15.yaml");
      EXPECT_EQ(e.pos().line, 1);
      EXPECT_EQ(e.pos().column, 10);
      EXPECT_EQ(e.message(),
                "'extends' chain too long: this base would be file 17 of the chain from 'c0.yaml' "
                "(at most 16 files)");
    }
  }
}

// Aliases are shared nodes in yaml-cpp: a short file can name billions of nodes.
TEST(MappingLoader, AliasBombsAreRefusedBeforeTheyAreExpanded) {
  std::string wide = kHead + "  - selector: cam\n    next: a\n    positions:\n      - &p [main_video_2";
  for (int i = 0; i < 1000; ++i) wide += ",\n        main_video_2";  // also a repeated signal, found too late
  wide += "]\n";
  // Under the reader's 1 MiB and 4 KiB-line bounds, and still 80 million nodes.
  for (int i = 0; i < 80'000; ++i) wide += "      - *p\n";
  std::string deep = "robot: HD1\ndeadman: a\nl0: &l0 [tool_on, tool_on, tool_on, tool_on, tool_on, tool_on]\n";
  for (int level = 1; level < 12; ++level) {
    const auto below = "*l" + std::to_string(level - 1);
    deep += "l" + std::to_string(level) + ": &l" + std::to_string(level) + " [" + below + ", " + below + ", " + below +
            ", " + below + ", " + below + ", " + below + "]\n";
  }
  for (const auto& text : {wide, deep}) {
    MappingDir dir;
    const auto file = dir.write("bomb.yaml", text);
    try {
      load_mapping(file);
      FAIL() << "accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(fs::path(e.pos().file).filename(), "bomb.yaml");
      EXPECT_GT(e.pos().line, 0);
      EXPECT_NE(e.message().find("the mapping is too large: more than 100000 YAML nodes"), std::string::npos)
          << e.what();
    }
  }
}

TEST(MappingLoader, NodeBoundCoversTheFilesExtendedToo) {
  std::string list = "\n";  // a block list: no line over the reader's 4 KiB bound
  for (int i = 0; i < 60'000; ++i) list += "  - tool_on\n";
  MappingDir dir;
  dir.write("base.yaml", "bindings: " + list);
  const auto file = dir.write("top.yaml", "robot: HD1\ndeadman: a\nextends: base.yaml\nbindings: " + list);
  try {
    load_mapping(file);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(fs::path(e.pos().file).filename(), "base.yaml");
    EXPECT_EQ(e.pos().line, 2);  // the list that passed the bound
    EXPECT_EQ(e.pos().column, 3);
    EXPECT_NE(e.message().find("the mapping is too large"), std::string::npos) << e.what();
  }
}

TEST(MappingLoader, ExtendsOverridesByInputAndKeepsTheRest) {
  MappingDir dir;
  dir.write(
      "base.yaml",
      "deadman: leftshoulder\ncenter: 120\nconstants: {battery: 0x10}\nbindings:\n"
      "  - signal: tool_on\n    button: x\n    toggle: true\n"
      "  - analog: drive\n    axis: lefty\n"
      "layers:\n  arm:\n    hold: rightshoulder\n    bindings:\n      - signal: gripper_open\n        button: a\n");
  const auto file = dir.write("child.yaml",
                              "robot: rons\nextends: base.yaml\nconstants: {byte12: 0xFF}\nbindings:\n"
                              "  - signal: zoom_up\n    button: x\n"   // replaces tool_on on x
                              "  - analog: drive\n    axis: righty\n"  // replaces the drive binding
                              "layers:\n  arm:\n    hold: rightshoulder\n    bindings:\n"
                              "      - signal: gripper_close\n        button: b\n");
  const auto m = *load_mapping(file);
  EXPECT_EQ(m.robot, "RONS");
  EXPECT_EQ(m.center, 120);
  EXPECT_EQ(m.battery, 0x10);
  EXPECT_EQ(m.byte12, 0xFF);
  EXPECT_EQ(input::input_name(m.deadman->key), "leftshoulder");
  ASSERT_EQ(m.bindings.size(), 2U);
  EXPECT_EQ(std::get<ButtonBinding>(m.bindings[0].rule).signal, protocol::signal_id("zoom_up"));
  EXPECT_EQ(input::input_name(std::get<AxisBinding>(m.bindings[1].rule).axis), "righty");
  ASSERT_EQ(m.layers.size(), 1U);
  EXPECT_EQ(m.layers[0].bindings.size(), 2U);  // gripper_open on a and gripper_close on b
}

TEST(MappingLoader, CenterTrimBandEndsAreAccepted) {
  MappingDir dir;
  for (const int c : {120, 124, 136}) {
    const auto text = "robot: HD1\ndeadman: a\ncenter: " + std::to_string(c) + "\n";
    EXPECT_EQ(load_mapping(dir.write("trim.yaml", text))->center, c) << text;
  }
  // A child's trim replaces its base's; without one, the base's is kept.
  dir.write("base.yaml", "deadman: a\ncenter: 136\n");
  EXPECT_EQ(load_mapping(dir.write("child.yaml", "robot: HD1\nextends: base.yaml\ncenter: 120\n"))->center, 120);
  EXPECT_EQ(load_mapping(dir.write("child.yaml", "robot: HD1\nextends: base.yaml\n"))->center, 136);
}

TEST(MappingLoader, ValidateRefusesACenterOutsideTheBandBuiltByHand) {
  Mapping m;
  m.center = 0;
  EXPECT_NE(testing::input_error_text([&] { validate(m, false); }).find("center 0 is out of range 120..136"),
            std::string::npos);
  m.center = 136;
  EXPECT_NO_THROW(validate(m, false));
}

TEST(MappingLoader, DefaultsAndEveryBindingKind) {
  MappingDir dir;
  const auto m =
      *load_mapping(dir.write("all.yaml",
                              "robot: va1\ndeadman: lefttrigger\nbrake: moving\nbindings:\n"
                              "  - signal: tool_on\n    button: hat0up\n"
                              "  - signal: zoom_up\n    axis: 3\n    invert: true\n"
                              "  - signal: [pt_left, pt_right]\n    axis: rightx\n"
                              "  - analog: pivot\n    axis: leftx\n"
                              "  - analog: light\n    increase: 4\n    decrease: 5\n    rate: 100\n"
                              "  - selector: video\n    next: a\n    prev: b\n    positions: [[], [main_video_2]]\n"
                              "  - signal: byte3.7\n    button: y\n    arm: righttrigger\n"));
  EXPECT_EQ(m.center, 128);
  EXPECT_EQ(m.byte12, 0x00);
  EXPECT_EQ(m.battery, 0xCC);
  EXPECT_EQ(m.brake, BrakeMode::kMoving);
  EXPECT_EQ(m.deadman->key.kind, input::InputKind::kPadAxis);
  ASSERT_EQ(m.bindings.size(), 7U);
  EXPECT_EQ(std::get<ButtonBinding>(m.bindings[0].rule).input.kind, input::InputKind::kHat);
  const auto& axis_button = std::get<ButtonBinding>(m.bindings[1].rule);
  EXPECT_EQ(axis_button.input, (input::InputKey{input::InputKind::kJoyAxis, 3}));
  EXPECT_TRUE(axis_button.invert);
  EXPECT_EQ(axis_button.threshold, 0.5);
  EXPECT_EQ(std::get<PairBinding>(m.bindings[2].rule).threshold, 0.5);
  const auto& pivot = std::get<AxisBinding>(m.bindings[3].rule);
  EXPECT_EQ(pivot.shape.deadzone, 0.0);
  EXPECT_EQ(pivot.shape.expo, 0.0);
  EXPECT_FALSE(pivot.shape.invert);
  EXPECT_FALSE(std::get<KnobBinding>(m.bindings[4].rule).initial);
  EXPECT_EQ(std::get<SelectorBinding>(m.bindings[5].rule).initial, 0);
  const auto& laser = std::get<WeaponBinding>(m.bindings[6].rule);
  EXPECT_EQ(laser.signal, protocol::signal_id("laser"));
  EXPECT_EQ(input::input_name(*laser.arm), "righttrigger");
  EXPECT_EQ(m.bindings[6].pos.line, 22);  // the laser binding's first line
}

// The supervisor's buttons are read on its own controller: the operator's
// deadman, a layer key or a bound input may be the same button name.
TEST(MappingLoader, StopResetHoldIsOneToTenSecondsTwoByDefault) {
  MappingDir dir;
  EXPECT_EQ(load_mapping(dir.write("d.yaml", "robot: HD1\ndeadman: a\n"))->stop_reset_hold_ms, 2000);
  // The reset gesture: one button or a chord, the operator's and the supervisor's; the reset buttons may be bound too.
  const auto chord = load_mapping(
      dir.write("r.yaml",
                "robot: HD1\ndeadman: a\nestop: guide\nstop_reset: [back, start]\nsupervisor: {stop: guide, reset: x}\n"
                "bindings:\n  - signal: front_art_up\n    button: back\n"));
  ASSERT_EQ(chord->stop_reset.size(), 2u);
  EXPECT_EQ(input::input_name(chord->stop_reset[0].key), "back");
  EXPECT_EQ(input::input_name(chord->stop_reset[1].key), "start");
  ASSERT_EQ(chord->supervisor->reset.size(), 1u);
  EXPECT_EQ(input::input_name(chord->supervisor->reset[0].key), "x");
  EXPECT_TRUE(load_mapping(dir.write("n.yaml", "robot: HD1\ndeadman: a\nestop: guide\n"))->stop_reset.empty());
  EXPECT_EQ(load_mapping(dir.write("lo.yaml", "robot: HD1\ndeadman: a\nstop_reset_hold: 1\n"))->stop_reset_hold_ms,
            1000);
  EXPECT_EQ(load_mapping(dir.write("hi.yaml", "robot: HD1\ndeadman: a\nstop_reset_hold: 10\n"))->stop_reset_hold_ms,
            10000);
  EXPECT_EQ(load_mapping(dir.write("x.yaml", "robot: HD1\ndeadman: a\nstop_reset_hold: 2.5\nestop: hat0up\n"))
                ->stop_reset_hold_ms,
            2500);
}

TEST(MappingLoader, TheSupervisorSectionNamesButtonsOnTheSecondController) {
  MappingDir dir;
  const auto m = *load_mapping(dir.write("sup.yaml",
                                         "robot: HD1\ndeadman: a\nsupervisor:\n  stop: a\n"
                                         "  weapons_consent: hat0up\nbindings:\n  - signal: tool_on\n"
                                         "    button: hat0up\n"));
  ASSERT_TRUE(m.supervisor);
  EXPECT_EQ(input::input_name(m.supervisor->stop.key), "a");
  EXPECT_EQ(m.supervisor->stop.pos.line, 4);
  ASSERT_TRUE(m.supervisor->weapons_consent);
  EXPECT_EQ(input::input_name(m.supervisor->weapons_consent->key), "hat0up");
  const auto stop_only = *load_mapping(dir.write("stop.yaml", "robot: HD1\ndeadman: a\nsupervisor: {stop: guide}\n"));
  EXPECT_FALSE(stop_only.supervisor->weapons_consent);
  EXPECT_FALSE(load_mapping(dir.write("none.yaml", "robot: HD1\ndeadman: a\n"))->supervisor);
  // An extending file's section replaces the base's whole.
  dir.write("base.yaml", "deadman: a\nsupervisor: {stop: b, weapons_consent: x}\n");
  EXPECT_TRUE(load_mapping(dir.write("kept.yaml", "robot: HD1\nextends: base.yaml\n"))->supervisor->weapons_consent);
  const auto over = *load_mapping(dir.write("over.yaml", "robot: HD1\nextends: base.yaml\nsupervisor: {stop: y}\n"));
  EXPECT_EQ(input::input_name(over.supervisor->stop.key), "y");
  EXPECT_FALSE(over.supervisor->weapons_consent);
}

// A base's layer of the same name is extended, not refused; a mapping built
// in code is held to the same rule by validate().
TEST(MappingLoader, ALayerNamedAgainByAnExtendingFileMergesButTwiceInOneMappingIsRefused) {
  MappingDir dir;
  dir.write("base.yaml", "deadman: a\nlayers:\n  arm:\n    hold: b\n    bindings: []\n");
  auto m = *load_mapping(dir.write("top.yaml",
                                   "robot: HD1\nextends: base.yaml\nlayers:\n  arm:\n    hold: b\n"
                                   "    bindings: []\n"));
  ASSERT_EQ(m.layers.size(), 1U);
  m.layers.push_back(Layer{"arm", SourcePos{"code", 9, 3}, InputUse{*input::parse_button_name("x"), {}}, false, {}});
  try {
    validate(m);
    FAIL() << "a layer named twice accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.pos().line, 9);
    EXPECT_EQ(e.message(), "layer 'arm' given twice");
  }
}

TEST(MappingLookup, UserFolderFirstThenTheShippedOnes) {
  MappingDir user;
  const std::vector<fs::path> path = {user.path(), ANDROS_MAPPINGS_DIR};
  EXPECT_EQ(find_robot_mapping("Hd1", path), fs::path(ANDROS_MAPPINGS_DIR) / "hd1.yaml");
  user.write("hd1.yaml", "robot: HD1\ndeadman: a\n");
  EXPECT_EQ(find_robot_mapping("HD1", path), user.path() / "hd1.yaml");
  EXPECT_THROW(find_robot_mapping("HD2", path), InputError);
  EXPECT_THROW(find_robot_mapping("hd1", {}), InputError);
}

TEST(MappingLookup, SearchPathHonoursXdgConfigHome) {
  const char* old = std::getenv("XDG_CONFIG_HOME");
  const std::string saved = old != nullptr ? old : "";
  setenv("XDG_CONFIG_HOME", "/tmp/andros-xdg", 1);
  const auto path = mapping_search_path();
  ASSERT_FALSE(path.empty());
  EXPECT_EQ(path.front(), fs::path("/tmp/andros-xdg/andros-bridge/mappings"));
  EXPECT_EQ(path.back(), fs::path(kInstalledMappingsDir));
  if (old != nullptr) setenv("XDG_CONFIG_HOME", saved.c_str(), 1);
  else unsetenv("XDG_CONFIG_HOME");
}

}  // namespace
}  // namespace andros::mapping
