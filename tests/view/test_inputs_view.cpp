// The input tester's lines and screen, and the deadzones it reads from a mapping.
#include <gtest/gtest.h>

#include <algorithm>

#include "andros/mapping/loader.hpp"
#include "andros/view/inputs_view.hpp"
#include "support/temp_dir.hpp"

namespace andros::view {
namespace {

using input::InputEvent;
using input::InputKey;
using input::InputKind;
using T = InputEvent::Type;

constexpr InputKey kLeftX{InputKind::kPadAxis, 0};
constexpr InputKey kLeftY{InputKind::kPadAxis, 1};
constexpr InputKey kRightX{InputKind::kPadAxis, 2};
constexpr InputKey kRightTrigger{InputKind::kPadAxis, 5};

InputEvent event(std::int64_t t, T type, InputKey key = {}, int value = 0, std::string name = "") {
  InputEvent e;
  e.t_ms = t;
  e.type = type;
  e.key = key;
  e.value = value;
  e.name = std::move(name);
  return e;
}

input::DeviceLayout pad_layout() {
  input::DeviceLayout d{"Test Pad", "0300aaaa", true, {}, {}, 0, {}};
  for (std::uint16_t b = 0; b < 15; ++b)
    d.buttons.push_back({InputKind::kPadButton, b});  // no misc1, paddles, touchpad
  for (std::uint16_t a = 0; a < 6; ++a) d.axes.push_back({InputKind::kPadAxis, a});
  return d;
}

AxisUses core_uses() { return axis_uses(*mapping::load_mapping(ANDROS_TEST_DATA_DIR "/mappings/core.yaml")); }

TEST(InputsView, AxisUsesAreTheBindingsThatReadEachAxis) {
  const auto uses = core_uses();
  EXPECT_EQ(uses.at(kLeftY).rest, AxisUse::Rest::kDeadzone);
  EXPECT_DOUBLE_EQ(uses.at(kLeftY).limit, 0.1);
  EXPECT_EQ(uses.at(kLeftY).signal, "drive");
  EXPECT_TRUE(uses.at(kLeftY).invert);
  EXPECT_EQ(uses.at(kRightX).rest, AxisUse::Rest::kBand);
  EXPECT_EQ(uses.at(kRightX).signal, "pt_left/pt_right");
  EXPECT_DOUBLE_EQ(uses.at(kRightTrigger).limit, 0.0);
  EXPECT_FALSE(uses.contains(InputKey{InputKind::kPadAxis, 3}));  // righty: unbound
  const auto unbound = axis_use(uses, InputKey{InputKind::kPadAxis, 3});
  EXPECT_EQ(unbound.rest, AxisUse::Rest::kDeadzone);
  EXPECT_DOUBLE_EQ(unbound.limit, 0.0);
}

TEST(InputsView, AxisUsesFindLayersAndTriggerDeadmen) {
  testing::TempDir dir;
  const auto uses = axis_uses(*mapping::load_mapping(dir.write("m.yaml",
                                                               "robot: HD1\n"
                                                               "deadman: lefttrigger\n"
                                                               "layers:\n"
                                                               "  arm:\n"
                                                               "    hold: a\n"
                                                               "    bindings:\n"
                                                               "      - analog: drive\n"
                                                               "        axis: righty\n"
                                                               "        deadzone: 0.2\n")));
  const auto deadman = uses.at(InputKey{InputKind::kPadAxis, 4});
  EXPECT_EQ(deadman.rest, AxisUse::Rest::kThreshold);
  EXPECT_DOUBLE_EQ(deadman.limit, 0.5);
  EXPECT_EQ(deadman.signal, "deadman");
  const auto righty = uses.at(InputKey{InputKind::kPadAxis, 3});
  EXPECT_DOUBLE_EQ(righty.limit, 0.2);
  EXPECT_EQ(righty.layer, "arm");
  EXPECT_EQ(format_input_change(event(0, T::kAxis, {InputKind::kPadAxis, 3}, 9000), uses, std::nullopt),
            "0 axis righty #3 9000 0.275 deadzone 0.20 drive in layer arm: moves");
}

TEST(InputsView, OneLinePerChangeByNameAndNumber) {
  const auto uses = core_uses();
  const auto pad = std::optional(pad_layout());
  EXPECT_EQ(format_input_change(event(0, T::kConnect, {}, 0, "Test Pad"), uses, pad),
            "0 connect Test Pad (game controller, GUID 0300aaaa)");
  EXPECT_EQ(format_input_change(event(40, T::kButton, {InputKind::kPadButton, 11}, 1), uses, pad),
            "40 button dpup #11 down");
  EXPECT_EQ(format_input_change(event(80, T::kButton, {InputKind::kPadButton, 0}, 0), uses, pad), "80 button a #0 up");
  EXPECT_EQ(format_input_change(event(120, T::kAxis, kLeftY, -1000), uses, pad),
            "120 axis lefty #1 -1000 -0.031 deadzone 0.10 drive: at rest");
  EXPECT_EQ(format_input_change(event(160, T::kAxis, kLeftY, -18112), uses, pad),
            "160 axis lefty #1 -18112 -0.553 deadzone 0.10 drive: moves");
  EXPECT_EQ(format_input_change(event(200, T::kAxis, kRightX, 16384), uses, pad),
            "200 axis rightx #2 16384 0.500 threshold 0.50 pt_left/pt_right: on");
  EXPECT_EQ(format_input_change(event(240, T::kAxis, {InputKind::kPadAxis, 4}, 300), uses, pad),
            "240 trigger lefttrigger #4 300 0.009 deadzone 0.00 (default): moves");
  EXPECT_EQ(format_input_change(event(280, T::kHat, {InputKind::kHat, 4}, 9), {}, std::nullopt), "280 hat 1 up+left");
  EXPECT_EQ(format_input_change(event(320, T::kAxis, {InputKind::kJoyAxis, 2}, 0), {}, std::nullopt),
            "320 axis 2 0 0.000 deadzone 0.00 (default): at rest");
  EXPECT_EQ(format_input_change(event(360, T::kButton, {InputKind::kJoyButton, 7}, 1), {}, std::nullopt),
            "360 button 7 down");
  EXPECT_EQ(format_input_change(event(400, T::kDisconnect), uses, std::nullopt), "400 disconnect");
}

TEST(InputsView, TheScreenShowsEveryInputOfThePad) {
  InputsBoard board(core_uses(), "heading line");
  EXPECT_NE(board.compose().find("none connected"), std::string::npos);
  const auto lines =
      board.update({event(0, T::kConnect, {}, 0, "Test Pad"), event(0, T::kButton, {InputKind::kPadButton, 9}, 1),
                    event(0, T::kAxis, kLeftY, -32768)},
                   pad_layout());
  EXPECT_EQ(lines.size(), 3U);
  const auto screen = board.compose();
  EXPECT_EQ(screen.rfind("heading line\n", 0), 0U);
  EXPECT_NE(screen.find("controller: Test Pad (game controller)\n  GUID 0300aaaa\n"), std::string::npos);
  EXPECT_NE(screen.find("*  9 leftshoulder"), std::string::npos) << screen;
  EXPECT_NE(screen.find("   10 rightshoulder"), std::string::npos) << screen;
  for (const auto name : {"a", "b", "x", "y", "back", "guide", "start", "leftstick", "dpright"}) {
    EXPECT_NE(screen.find(" " + std::string(name) + " "), std::string::npos) << name;
  }
  EXPECT_NE(screen.find("not in its SDL mapping: misc1 paddle1 paddle2 paddle3 paddle4 touchpad"), std::string::npos);
  EXPECT_NE(screen.find("    1 lefty        -32768 -1.000 [=====|     ] moves   deadzone 0.10 drive\n"),
            std::string::npos)
      << screen;
  EXPECT_NE(screen.find("triggers\n    4 lefttrigger       0  0.000 [|          ] at rest deadzone 0.00 (default)\n"),
            std::string::npos)
      << screen;
  EXPECT_NE(screen.find("righttrigger"), std::string::npos);
  for (std::size_t from = 0, to = 0; (to = screen.find('\n', from)) != std::string::npos; from = to + 1) {
    EXPECT_LE(to - from, 79U) << screen.substr(from, to - from);
  }
}

// A controller names itself: its name is shown escaped, never obeyed.
TEST(InputsView, AControllersNameReachesTheTerminalEscaped) {
  InputsBoard board(core_uses(), "h");
  auto layout = pad_layout();
  layout.name = "Evil\x1B[2J\nPad";
  const auto lines = board.update({event(0, T::kConnect, {}, 0, layout.name)}, layout);
  ASSERT_EQ(lines.size(), 1U);
  EXPECT_NE(lines[0].find("connect Evil\\x1B[2J\\nPad (game controller"), std::string::npos) << lines[0];
  const auto screen = board.compose();
  EXPECT_NE(screen.find("controller: Evil\\x1B[2J\\nPad (game controller)\n"), std::string::npos) << screen;
  EXPECT_EQ(screen.find('\x1B'), std::string::npos);
}

TEST(InputsView, TheScreenShowsAJoysticksNumberedInputsAndHats) {
  InputsBoard board({}, "h");
  input::DeviceLayout stick{"Stick", "0300bbbb", false, {}, {}, 1, {}};
  for (std::uint16_t b = 0; b < 12; ++b) stick.buttons.push_back({InputKind::kJoyButton, b});
  for (std::uint16_t a = 0; a < 4; ++a) stick.axes.push_back({InputKind::kJoyAxis, a});
  board.update({event(0, T::kConnect, {}, 0, "Stick"), event(0, T::kHat, {InputKind::kHat, 0}, 2),
                event(0, T::kButton, {InputKind::kJoyButton, 11}, 1)},
               stick);
  const auto screen = board.compose();
  EXPECT_NE(screen.find("controller: Stick (joystick)\n  GUID 0300bbbb\n"), std::string::npos);
  EXPECT_NE(screen.find("* 11 11 "), std::string::npos) << screen;
  EXPECT_NE(screen.find("    3 3 "), std::string::npos) << screen;
  EXPECT_NE(screen.find("hats\n    0 hat0         right"), std::string::npos) << screen;
  EXPECT_EQ(screen.find("triggers"), std::string::npos);
  EXPECT_EQ(screen.find("not in its SDL mapping"), std::string::npos);
}

// Issue 19, finding 8: a small terminal gets the screen reflowed (fewer
// button columns, no blank lines), never its triggers or a button column cut;
// a wide one a finer bar; an axis's value from -1 to 1 is always beside it.
TEST(InputsView, TheScreenReflowsToTheTerminal) {
  InputsBoard board(core_uses(), "andros-bridge inputs: the first controller (Ctrl-C ends)\ndeadzones of core.yaml");
  board.update({event(0, T::kConnect, {}, 0, "Test Pad"), event(0, T::kAxis, kLeftX, 3276),
                event(0, T::kButton, {InputKind::kPadButton, 14}, 1)},
               pad_layout());
  const auto lines_of = [](const std::string& screen) {
    std::vector<std::string> out;
    for (std::size_t from = 0, to = 0; (to = screen.find('\n', from)) != std::string::npos; from = to + 1) {
      out.push_back(screen.substr(from, to - from));
    }
    return out;
  };
  const auto small = lines_of(board.compose({60, 20}));
  EXPECT_LE(small.size(), 20U);
  const auto has = [](const std::vector<std::string>& lines, const std::string& what) {
    return std::any_of(lines.begin(), lines.end(),
                       [&](const std::string& l) { return l.find(what) != std::string::npos; });
  };
  EXPECT_TRUE(has(small, "    5 righttrigger")) << board.compose({60, 20});
  EXPECT_TRUE(has(small, "* 14 dpright")) << board.compose({60, 20});  // the last button, in its column
  for (const auto& line : small) EXPECT_LE(line.size(), 60U) << line;
  // Three columns of buttons at 60 columns: a row holds a, b, x, not y.
  const auto row = std::find_if(small.begin(), small.end(),
                                [](const std::string& l) { return l.find(" 0 a ") != std::string::npos; });
  ASSERT_NE(row, small.end());
  EXPECT_NE(row->find(" 2 x"), std::string::npos) << *row;
  EXPECT_EQ(row->find(" 3 y"), std::string::npos) << *row;
  // 0.1 of the way: the value says it, whatever the bar's resolution.
  EXPECT_TRUE(has(small, "    0 leftx          3276  0.100 [     |     ] at rest")) << board.compose({60, 20});
  // Wide: a bar of 21 cells, a tenth of the way a cell.
  EXPECT_TRUE(
      has(lines_of(board.compose({120, 40})), "    0 leftx          3276  0.100 [          |=         ] at rest"))
      << board.compose({120, 40});
}

TEST(InputsView, APadsHatsOutsideItsMappingAreShown) {
  InputsBoard board({}, "h");
  auto layout = pad_layout();
  layout.free_hats = {1};
  board.update({event(0, T::kConnect, {}, 0, "Test Pad"), event(0, T::kHat, {InputKind::kHat, 4}, 1)}, layout);
  const auto screen = board.compose();
  EXPECT_NE(screen.find("hats outside its SDL mapping (bind them as hatNup, ...)\n    1 hat1         up\n"),
            std::string::npos)
      << screen;
}

// Issue 28, item 5: at 80x24 with the shipped layout, the mapping's file
// name and every binding's name are shown whole (a line too long wraps under
// itself), and everything still fits the rows.
TEST(InputsView, At80x24NamesAndTheFileNameAreWhole) {
  const std::string file = "/home/operator/.config/andros-bridge/mappings/field-teams/north/hd1.yaml";
  InputsBoard board(axis_uses(*mapping::load_mapping(ANDROS_MAPPINGS_DIR "/hd1.yaml")),
                    "andros-bridge inputs: the first controller (Ctrl-C ends)\ndeadzones and thresholds of " + file +
                        " (run's default: no --robot or --mapping given)");
  board.update({event(0, T::kConnect, {}, 0, "Test Pad")}, pad_layout());
  const auto screen = board.compose({80, 24});
  std::string joined;  // the lines as one text, a wrap's break and indent taken out
  std::size_t rows = 0;
  for (std::size_t from = 0, to = 0; (to = screen.find('\n', from)) != std::string::npos; from = to + 1, ++rows) {
    const auto line = screen.substr(from, to - from);
    EXPECT_LE(line.size(), 80U) << line;
    joined += " " + line.substr(line.find_first_not_of(' ') == std::string::npos ? 0 : line.find_first_not_of(' '));
  }
  EXPECT_LE(rows, 24U) << screen;
  for (const auto* whole : {"hd1.yaml", "fiber_takeup", "fiber_unwind", "pt_left/pt_right", "pt_up/pt_down",
                            "righttrigger", "lefttrigger"}) {
    EXPECT_NE(joined.find(whole), std::string::npos) << whole << "\n" << screen;
  }
}

// Issue 33, item 7: a controller named by its port makes the heading a line
// longer, and the screen no longer fitted 80x24 wrapped: every line was cut,
// binding names and the mapping's path with them. Now the middle of a path
// gives way first (its start and its file name shown), then a long name's,
// each as little as the rows need, and the binding names stay whole.
TEST(InputsView, At80x24AControllerByPortCutsThePathsMiddleNotTheNames) {
  const std::string port = "/dev/input/by-path/pci-0000:00:14.0-usb-0:1:1.0-event-joystick";
  const std::string file = "/home/operator/.config/andros-bridge/mappings/field-teams/north/hd1.yaml";
  InputsBoard board(axis_uses(*mapping::load_mapping(ANDROS_MAPPINGS_DIR "/hd1.yaml")),
                    "andros-bridge inputs: the controller at " + port + " (Ctrl-C ends)\ndeadzones and thresholds of " +
                        file + " (run's default: no --robot or --mapping given)");
  board.update({event(0, T::kConnect, {}, 0, "Test Pad")}, pad_layout());
  const auto screen = board.compose();  // an 80x24 terminal
  std::vector<std::string> lines;
  for (std::size_t from = 0, to = 0; (to = screen.find('\n', from)) != std::string::npos; from = to + 1) {
    lines.push_back(screen.substr(from, to - from));
    EXPECT_LE(lines.back().size(), static_cast<std::size_t>(kInputsSize.cols)) << lines.back();
  }
  EXPECT_LE(lines.size(), static_cast<std::size_t>(kInputsSize.rows)) << screen;
  const auto has = [&lines](const std::string& what) {
    return std::any_of(lines.begin(), lines.end(),
                       [&](const std::string& l) { return l.find(what) != std::string::npos; });
  };
  for (const auto* whole :
       {" pt_left/pt_right", " pt_up/pt_down", " fiber_takeup", " fiber_unwind", "    5 righttrigger", " 14 dpright"}) {
    EXPECT_TRUE(has(whole)) << whole << "\n" << screen;
  }
  // Each path: its start, "...", its end, on one line.
  for (const auto& path : {port, file}) {
    const auto line = std::find_if(lines.begin(), lines.end(), [&](const std::string& l) {
      return l.find(path.substr(0, 6)) != std::string::npos;
    });
    ASSERT_NE(line, lines.end()) << path << "\n" << screen;
    const auto start = line->find(path.substr(0, 6));
    const auto shown = line->substr(start, line->find(' ', start) - start);
    const auto cut = shown.find("...");
    ASSERT_NE(cut, std::string::npos) << *line;
    const auto end = shown.substr(shown.rfind("...") + 3);
    EXPECT_GE(end.size(), 16U) << *line;
    EXPECT_TRUE(path.starts_with(shown.substr(0, cut))) << *line;
    EXPECT_TRUE(path.ends_with(end)) << *line;
  }
  // A layer's name too long for the line loses its middle, not its end.
  AxisUses uses = axis_uses(*mapping::load_mapping(ANDROS_MAPPINGS_DIR "/hd1.yaml"));
  uses[kRightX].layer = "camera-and-manipulator-arm-positioning-for-the-north-field-team-at-night";
  InputsBoard named(uses, "andros-bridge inputs: the controller at " + port + " (Ctrl-C ends)\nno mapping");
  named.update({event(0, T::kConnect, {}, 0, "Test Pad")}, pad_layout());
  const auto layered = named.compose();
  EXPECT_LE(std::count(layered.begin(), layered.end(), '\n'), kInputsSize.rows) << layered;
  const auto layer = layered.find("camera-");
  ASSERT_NE(layer, std::string::npos) << layered;
  const auto shown = layered.substr(layer, layered.find_first_of(" \n", layer) - layer);
  EXPECT_NE(shown.find("..."), std::string::npos) << shown;
  EXPECT_TRUE(shown.ends_with("-at-night")) << shown;
  EXPECT_NE(layered.find("    5 righttrigger"), std::string::npos) << layered;
}

}  // namespace
}  // namespace andros::view
