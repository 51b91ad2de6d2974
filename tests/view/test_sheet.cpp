#include <gtest/gtest.h>

#include <algorithm>

#include "andros/mapping/loader.hpp"
#include "andros/view/sheet.hpp"
#include "support/temp_dir.hpp"

namespace andros::view {
namespace {

Sheet kinds_sheet() { return build_sheet(*mapping::load_mapping(ANDROS_TEST_DATA_DIR "/sheet/kinds.yaml")); }

const SheetEntry& entry(const Sheet& sheet, std::size_t panel, std::string_view input) {
  const auto& entries = sheet.panels.at(panel).entries;
  const auto it = std::find_if(entries.begin(), entries.end(), [&](const SheetEntry& e) { return e.input == input; });
  if (it == entries.end()) throw std::runtime_error("no entry for " + std::string(input));
  return *it;
}

void expect_entry(const Sheet& sheet, std::size_t panel, std::string_view input, SheetMark mark,
                  std::string_view function, std::string_view detail = {}, bool inherited = false) {
  const auto& e = entry(sheet, panel, input);
  EXPECT_EQ(e.mark, mark) << input;
  EXPECT_EQ(e.function, function) << input;
  EXPECT_EQ(e.detail, detail) << input;
  EXPECT_EQ(e.inherited, inherited) << input;
}

TEST(Sheet, EveryBindingKindHasItsEntryAndMark) {
  const auto s = kinds_sheet();
  EXPECT_EQ(s.robot, "F6A");
  EXPECT_EQ(s.file, "kinds.yaml");
  EXPECT_EQ(s.deadman, "LT");
  EXPECT_TRUE(s.pad);
  ASSERT_EQ(s.panels.size(), 3u);
  expect_entry(s, 0, "LT", SheetMark::kDeadman, "hold to enable motion", "past half way");
  // Issue 19, finding 10: the operator's words, and a stick's deadzone and expo.
  expect_entry(s, 0, "D-pad up", SheetMark::kPlain, "front articulators up");
  expect_entry(s, 0, "X", SheetMark::kToggle, "tool on");
  expect_entry(s, 0, "RT", SheetMark::kPlain, "pay out tether");
  expect_entry(s, 0, "right stick up/down", SheetMark::kPlain, "up: rear articulators up", "past 30%");
  expect_entry(s, 0, "right stick left/right", SheetMark::kPlain, "left: pan left, right: pan right");
  expect_entry(s, 0, "left stick up/down", SheetMark::kPlain, "drive forward/back", "up = forward");
  expect_entry(s, 0, "B", SheetMark::kKnob, "light brighter", "64/s");
  expect_entry(s, 0, "A", SheetMark::kKnob, "light dimmer", "64/s");
  expect_entry(s, 0, "Start", SheetMark::kSelector, "speed selector: next");
  expect_entry(s, 0, "Back", SheetMark::kSelector, "speed selector: previous");
  expect_entry(s, 0, "LB", SheetMark::kLayerKey, "hold: arm layer");
  expect_entry(s, 0, "RB", SheetMark::kLayerKey, "weapons layer on/off");
}

TEST(Sheet, LayersShowTheirOwnBindingsAndTheBaseOnesTheyKeep) {
  const auto s = kinds_sheet();
  EXPECT_EQ(s.panels[1].title, "arm layer");
  EXPECT_EQ(s.panels[1].how, "while LB is held");
  expect_entry(s, 1, "RT", SheetMark::kPlain, "arm speed faster/slower", "analog 0..255");
  expect_entry(s, 1, "X", SheetMark::kToggle, "tool on", "", true);
  expect_entry(s, 1, "LB", SheetMark::kLayerKey, "held: arm layer");
  expect_entry(s, 1, "RB", SheetMark::kLayerKey, "weapons layer on/off");
  expect_entry(s, 1, "LT", SheetMark::kDeadman, "hold to enable motion", "past half way");

  EXPECT_EQ(s.panels[2].how, "RB turns it on and off");
  expect_entry(s, 2, "Y", SheetMark::kWeapon, "fire weapon 1", "needs --weapons + left stick click");
  expect_entry(s, 2, "left stick click", SheetMark::kArming, "hold to arm weapons");
  expect_entry(s, 2, "RB", SheetMark::kLayerKey, "weapons layer off (back to base)");
  expect_entry(s, 2, "RT", SheetMark::kPlain, "pay out tether", "", true);
}

TEST(Sheet, EntriesFollowTheDrawingsOrder) {
  const auto s = kinds_sheet();
  std::vector<std::string> inputs;
  for (const auto& e : s.panels[0].entries) inputs.push_back(e.input);
  const std::vector<std::string> want = {"LT",
                                         "LB",
                                         "Back",
                                         "left stick up/down",
                                         "D-pad up",
                                         "RT",
                                         "RB",
                                         "Start",
                                         "B",
                                         "X",
                                         "A",
                                         "right stick up/down",
                                         "right stick left/right"};
  EXPECT_EQ(inputs, want);
}

TEST(Sheet, NotesGiveSelectorPositionsKnobsAndTheWeaponsRule) {
  const auto s = kinds_sheet();
  const auto has = [&](std::string_view text) {
    return std::any_of(s.notes.begin(), s.notes.end(), [&](const std::string& n) { return n == text; });
  };
  // A position without a bit says what it means on the switchbox.
  EXPECT_TRUE(
      has("speed selector, Start steps, Back back: vehicle speed low > vehicle speed medium > vehicle speed high; "
          "starts at vehicle speed medium"));
  EXPECT_TRUE(has("light knob: B brighter, A dimmer, 64 units/s; starts at 10, kept while not enabled"));
  EXPECT_TRUE(
      has("Analog inputs: drive (left stick up/down): deadzone 0.1, expo 0; arm speed (RT, arm layer): "
          "deadzone 0, expo 0."));
  EXPECT_FALSE(std::any_of(s.notes.begin(), s.notes.end(),
                           [](const std::string& n) { return n.find("numbered from 0") != std::string::npos; }));
  EXPECT_TRUE(
      has("Weapons fire only when the run has --weapons, the deadman (LT) is held and the arming input "
          "(left stick click) is held."));
}

// The shipped layout with speed levels on the one button it leaves free in every layer.
Sheet speed_sheet(const std::string& scale) {
  const testing::TempDir dir;
  return build_sheet(*mapping::load_mapping(
      dir.write("speed.yaml",
                "robot: HD1\ndeadman: leftshoulder\nbindings:\n  - {analog: drive, axis: lefty}\n"
                "  - {selector: speed, next: start, positions: [[speed_low], [], [speed_high]]}\n"
                "layers:\n  arm:\n    hold: rightshoulder\n    bindings:\n      - {analog: pivot, axis: leftx}\n"
                "scale: " +
                    scale + "\n")));
}

std::string note_starting(const Sheet& sheet, std::string_view start) {
  const auto it =
      std::find_if(sheet.notes.begin(), sheet.notes.end(), [&](const std::string& n) { return n.starts_with(start); });
  return it == sheet.notes.end() ? "no such note" : *it;
}

TEST(Sheet, TheSpeedButtonsAreInEveryPanelAndTheLevelsInTheNotes) {
  const auto s = speed_sheet("{button: guide, levels: [0.25, 0.5, 1.0]}");
  EXPECT_TRUE(s.pad);
  EXPECT_TRUE(s.speed);
  for (std::size_t panel = 0; panel < s.panels.size(); ++panel) {
    expect_entry(s, panel, "Guide", SheetMark::kSpeed, "speed level up", "then back to the slowest");
  }
  EXPECT_EQ(note_starting(s, "Speed levels"),
            "Speed levels (drive and pivot), Guide steps up, after the fastest back to the slowest: 25% > 50% > 100% "
            "of the stick's travel from rest; starts at 25%, again after the controller is lost or driving was "
            "interrupted; kept while the deadman is released. A stick held when the level changes waits until it is "
            "back at rest. Not the speed_low/speed_high selector: that sets the vehicle's own speed range; the level "
            "scales the stick within it.");
  std::string text = render_sheet_text(s);  // the notes wrapped: read as one line
  for (std::size_t at; (at = text.find("\n  ")) != std::string::npos;) text.replace(at, 3, " ");
  EXPECT_NE(text.find("SPEED steps the speed level"), std::string::npos);
  EXPECT_NE(render_sheet_svg(s).find("\">SPEED</tspan>"), std::string::npos);

  const auto two = speed_sheet("{button: guide, down: misc1, levels: [0.3, 0.6, 1], initial: 0.6}");
  expect_entry(two, 0, "Guide", SheetMark::kSpeed, "speed level up");
  EXPECT_EQ(note_starting(two, "Speed levels").substr(0, 111),
            "Speed levels (drive and pivot), Guide steps up, Misc down: 30% > 60% > 100% of the stick's travel from "
            "rest; st");
  EXPECT_NE(note_starting(two, "Speed levels").find("starts at 60%,"), std::string::npos);
  EXPECT_FALSE(two.pad) << "Misc is not on the drawing";

  const auto capped = speed_sheet("{levels: [0.5]}");
  EXPECT_FALSE(capped.speed);
  EXPECT_EQ(note_starting(capped, "Drive and pivot"),
            "Drive and pivot move 50% of the stick's travel from rest (scale).");
}

TEST(Sheet, WithoutSpeedLevelsNoWordOfThem) {
  const auto s = build_sheet(*mapping::load_mapping(ANDROS_MAPPINGS_DIR "/hd1.yaml"));
  EXPECT_FALSE(s.speed);
  EXPECT_EQ(render_sheet_svg(s).find("SPEED"), std::string::npos);
  EXPECT_EQ(render_sheet_text(s).find("SPEED"), std::string::npos);
}

// The supervisor's buttons are on its own controller: a note, not the operator's pad drawing.
TEST(Sheet, NotesGiveTheSupervisorsButtons) {
  const auto s = build_sheet(*mapping::load_mapping(ANDROS_TEST_DATA_DIR "/mappings/supervisor.yaml"));
  const auto has = [&](std::string_view text) {
    return std::any_of(s.notes.begin(), s.notes.end(), [&](const std::string& n) { return n == text; });
  };
  EXPECT_TRUE(
      has("Weapons fire only when the run has --weapons, the deadman (LB) is held and the arming input "
          "(RB) is held, and the supervisor holds its consent."));
  EXPECT_TRUE(
      has("Supervisor's controller (run --supervisor): X stops (latched; it never resets); Back and Start held "
          "together 2 s resets any stop (then the deadman pressed afresh); A held is the weapons consent (a "
          "two-person rule: pressed after the weapons became possible). Losing either controller stops motion."));
  EXPECT_NE(render_sheet_text(s).find("Supervisor's controller"), std::string::npos);
  EXPECT_NE(render_sheet_svg(s).find("Supervisor"), std::string::npos);
  for (const auto& n : kinds_sheet().notes) EXPECT_EQ(n.find("upervisor"), std::string::npos) << n;
}

// Issue 25: what the sheet says of a stop is the reset by the book, never the
// old "released with the deadman".
TEST(Sheet, TheStopNoteIsTheResetHold) {
  const auto s = build_sheet(*mapping::load_mapping(ANDROS_MAPPINGS_DIR "/hd1.yaml"));
  const auto text = render_sheet_text(s);
  EXPECT_NE(text.find("Press Guide to STOP: latched until reset on that controller (see the notes).\n"),
            std::string::npos)
      << text;
  EXPECT_NE(std::find(s.notes.begin(), s.notes.end(),
                      "STOP: a press of Guide (or holding it) stops the vehicle, whenever; it stays stopped until "
                      "reset on the controller that stopped: release every stop button and the deadman, then Back "
                      "and Start held together 2 s; then press the deadman afresh."),
            s.notes.end());
  EXPECT_EQ(text.find("deadman are released"), std::string::npos) << text;
  EXPECT_EQ(render_sheet_svg(s).find("deadman are released"), std::string::npos);
}

TEST(Sheet, PlainJoystickGetsListPanels) {
  const auto s = build_sheet(*mapping::load_mapping(ANDROS_TEST_DATA_DIR "/mappings/joystick.yaml"));
  EXPECT_FALSE(s.pad);
  expect_entry(s, 0, "button 4", SheetMark::kDeadman, "hold to enable motion");
  expect_entry(s, 0, "hat 0 up", SheetMark::kPlain, "front articulators up");
  expect_entry(s, 0, "axis 1", SheetMark::kPlain, "drive forward/back", "negative = forward");
  expect_entry(s, 0, "axis 2", SheetMark::kPlain, "positive: zoom in", "past 25%");
  expect_entry(s, 0, "axis 3", SheetMark::kPlain, "negative: zoom out", "past 25%");
  // Numbered inputs: the sheet says where the numbers start.
  EXPECT_TRUE(std::any_of(s.notes.begin(), s.notes.end(), [](const std::string& n) {
    return n.starts_with("Joystick buttons, axes and hats are numbered from 0");
  }));
  const auto svg = render_sheet_svg(s);
  EXPECT_EQ(svg.find("<ellipse"), std::string::npos) << "no pad drawing for a joystick";
  EXPECT_NE(svg.find(">button 4</text>"), std::string::npos);
}

TEST(Sheet, TextIsATablePerLayer) {
  const auto text = render_sheet_text(kinds_sheet());
  EXPECT_NE(text.find("\nBASE LAYER: active when no other layer is\n"
                      "  input                  mark     function\n"
                      "  LT                     DEADMAN  hold to enable motion (past half way)\n"
                      "  LB                     LAYER    hold: arm layer\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("\n  Y                      WEAPON   fire weapon 1 (needs --weapons + left stick click)\n"),
            std::string::npos);
  EXPECT_NE(text.find("\n  X                      TOGGLE   tool on [base]\n"), std::string::npos);
  const auto notes = text.substr(text.find("\nNOTES\n"));
  EXPECT_NE(notes.find("\n- speed selector, Start steps, Back back: vehicle speed low > vehicle speed\n"
                       "  medium > vehicle speed high; starts at vehicle speed medium\n"),
            std::string::npos)
      << notes;
  for (std::size_t start = 0, end; (end = notes.find('\n', start)) != std::string::npos; start = end + 1) {
    EXPECT_LE(end - start, 80u) << notes.substr(start, end - start);
  }
}

TEST(Sheet, SvgIsOnePageAndEscapesNames) {
  testing::TempDir dir;
  const auto file =
      dir.write("a&<b>.yaml", "robot: HD1\ndeadman: a\nlayers:\n  l\"1:\n    hold: b\n    bindings: []\n");
  const auto svg = render_sheet_svg(build_sheet(*mapping::load_mapping(file)));
  EXPECT_NE(svg.find("width=\"190mm\" height=\"260mm\" viewBox=\"0 0 190 260\""), std::string::npos);
  EXPECT_NE(svg.find("a&amp;&lt;b&gt;.yaml"), std::string::npos);
  EXPECT_NE(svg.find("L&quot;1 LAYER"), std::string::npos);
  EXPECT_EQ(svg.find("a&<b>"), std::string::npos);
}

TEST(Sheet, NamesFromTheFileAreShownEscaped) {
  testing::TempDir dir;
  const auto file = dir.write("odd.yaml",
                              "robot: HD1\ndeadman: a\nbindings:\n  - selector: \"cam\\e[31m\"\n    next: x\n"
                              "    positions: [[main_video_2], [main_video_3]]\nlayers:\n  \"two\\nlines\\e]0;t\\a\":\n"
                              "    hold: b\n    bindings: []\n");
  const auto text = render_sheet_text(build_sheet(*mapping::load_mapping(file)));
  EXPECT_NE(text.find("TWO\\NLINES\\X1B]0;T\\X07 LAYER: while B is held\n"), std::string::npos) << text;
  EXPECT_NE(text.find("hold: two\\nlines\\x1B]0;t\\x07 layer"), std::string::npos) << text;
  EXPECT_NE(text.find("cam\\x1B[31m selector: next"), std::string::npos) << text;
  EXPECT_EQ(text.find('\x1B'), std::string::npos);
  EXPECT_EQ(text.find('\a'), std::string::npos);
  const auto svg = render_sheet_svg(build_sheet(*mapping::load_mapping(file)));
  EXPECT_EQ(svg.find('\x1B'), std::string::npos);
}

// Issue 28, item 4: a stick's analog words read in the order its label
// names its way ("left stick left/right: pivot left/right"), inverted or not.
TEST(Sheet, AStickAnalogReadsInTheOrderOfItsLabel) {
  const auto text = render_sheet_text(build_sheet(*mapping::load_mapping(ANDROS_MAPPINGS_DIR "/hd1.yaml")));
  EXPECT_NE(text.find("left stick left/right           pivot left/right (analog)"), std::string::npos) << text;
  EXPECT_NE(text.find("left stick up/down              drive forward/back (up = forward)"), std::string::npos) << text;
  EXPECT_EQ(text.find("pivot right/left"), std::string::npos) << text;
  testing::TempDir dir;
  const auto file = dir.write("m.yaml",
                              "robot: HD1\ndeadman: leftshoulder\nbindings:\n"
                              "  - {analog: pivot, axis: rightx, invert: true}\n  - {analog: drive, axis: righty}\n");
  const auto inverted = render_sheet_text(build_sheet(*mapping::load_mapping(file)));
  EXPECT_NE(inverted.find("right stick left/right          pivot right/left"), std::string::npos) << inverted;
  EXPECT_NE(inverted.find("right stick up/down             drive back/forward"), std::string::npos) << inverted;
}

/// The font size of the SVG <text> that holds what, in mm.
double font_size_of(const std::string& svg, std::string_view what) {
  const auto at = svg.find(what);
  if (at == std::string::npos) return 0;
  const auto text = svg.rfind("<text ", at);
  const auto size = svg.find("font-size=\"", text);
  return std::stod(svg.substr(size + 11));
}

// Issue 28, items 4 and 10: the DEADMAN and STOP rows are drawn at the labels'
// full size even with a long detail (a trigger deadman's panic point): the
// detail is left off the drawing and given in the notes instead.
TEST(Sheet, TheDeadmanAndStopRowsAreReadable) {
  const auto sheet = build_sheet(*mapping::load_mapping(ANDROS_MAPPINGS_DIR "/examples/trigger-deadman.yaml"));
  const auto svg = render_sheet_svg(sheet);
  EXPECT_GE(font_size_of(svg, "DEADMAN </tspan>"), 2.5) << svg;
  EXPECT_GE(font_size_of(svg, "STOP </tspan>"), 2.5) << svg;
  EXPECT_NE(svg.find("The deadman, LT: held past half way; off past 90% until fully released."), std::string::npos);
  // Every label at a readable size: never below 85% of the labels' size.
  for (std::size_t at = svg.find("<text "); at != std::string::npos; at = svg.find("<text ", at + 1)) {
    const auto size = std::stod(svg.substr(svg.find("font-size=\"", at) + 11));
    EXPECT_GE(size, 2.0) << svg.substr(at, 200);
  }
}

TEST(Sheet, FormatIsSvgOrText) {
  EXPECT_EQ(parse_sheet_format("svg", {}), SheetFormat::kSvg);
  EXPECT_EQ(parse_sheet_format("text", {}), SheetFormat::kText);
  EXPECT_THROW(parse_sheet_format("png", {}), InputError);
}

}  // namespace
}  // namespace andros::view
