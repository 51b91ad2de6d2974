#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "andros/view/operator_screens.hpp"
#include "andros/view/status_board.hpp"

namespace andros::view {
namespace {

/// A run as the board reports it mid-drive, with the simulated vehicle.
RunStatus driving(bool weapons) {
  RunStatus s;
  s.robot = "HD1";
  s.mapping_file = "/usr/share/andros-bridge/mappings/hd1.yaml";
  s.weapons = weapons;
  s.code = 1;
  s.rate_hz = 25;
  s.t_ms = 4600;
  s.input = "controller";
  s.connected = true;
  s.controller = "Xbox 360 Controller";
  s.state = run::OpState::kEnabled;
  s.enable_text = "enabled";
  s.layer = "arm";
  s.link_name = "/dev/andros-switchbox 9600 8N1";
  s.link_state = link::LinkState::kUp;
  s.sent_timing = timing::TimingSummary{.rate_hz = 25.0, .period_ms = 40.0, .jitter_ms = 0.05, .count = 250};
  s.vehicle = link::VehicleStatus{};
  s.vehicle->last = s.sent;
  return s;
}

std::vector<std::string> shown(const RunStatus& s, TermSize size) {
  std::vector<std::string> out;
  for (const auto& line : render_run_screen(s, size).fit(size)) {
    out.push_back(plain(line, static_cast<std::size_t>(size.cols)));
  }
  return out;
}

/// The header's lines start so, in this order, from the top (a line too
/// long for the terminal wraps: its continuations, indented, are passed over).
void expect_header(const std::vector<std::string>& all, bool weapons) {
  std::vector<std::string> want = {"andros-bridge run  robot HD1  code 01  25.0 Hz", "state       ENABLED",
                                   "link        /dev/an", "controller  Xbox 360 Controller", "mapping     "};
  if (weapons) want.insert(want.begin(), "");  // the banner, checked below
  std::vector<std::string> lines;
  for (const auto& line : all) {
    if (lines.size() < (weapons ? 1U : 0U) || !line.starts_with("  ")) lines.push_back(line);
  }
  ASSERT_GE(lines.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i) {
    const auto prefix = want[i].substr(0, lines[i].size());
    EXPECT_TRUE(lines[i].starts_with(prefix)) << "line " << i << ": " << lines[i];
  }
  const auto banner = lines[0].find("WEAPONS ENABLED");
  EXPECT_EQ(banner != std::string::npos, weapons) << lines[0];
}

TEST(RunScreen, TheHeaderIsFirstAndWholeAt80x24AndSmaller) {
  for (const bool weapons : {false, true}) {
    for (const TermSize size : {TermSize{80, 24}, TermSize{80, 10}, TermSize{40, 24}, TermSize{120, 40}}) {
      SCOPED_TRACE(std::to_string(size.cols) + "x" + std::to_string(size.rows) + (weapons ? " weapons" : ""));
      const auto lines = shown(driving(weapons), size);
      EXPECT_LE(lines.size(), static_cast<std::size_t>(size.rows));
      expect_header(lines, weapons);
      for (const auto& line : lines) EXPECT_LE(line.size(), static_cast<std::size_t>(size.cols)) << line;
    }
  }
  // At 80x24 the header is whole, not cut: the state, the mapping's file name.
  const auto lines = shown(driving(false), {80, 24});
  EXPECT_EQ(lines[1], "state       ENABLED   layer: arm");
  EXPECT_EQ(lines[4], "mapping     /usr/share/andros-bridge/mappings/hd1.yaml");
}

TEST(RunScreen, TheTrainerSaysSoInItsTitleAndWhereItsPageIs) {
  RunStatus s = driving(false);
  s.trainer = "simulated vehicle only; page http://127.0.0.1:8037/";
  const auto lines = shown(s, {80, 24});
  EXPECT_TRUE(lines[0].starts_with("andros-bridge TRAINER  robot HD1")) << lines[0];
  EXPECT_EQ(lines[1], "trainer     simulated vehicle only; page http://127.0.0.1:8037/");
  EXPECT_EQ(lines[2], "state       ENABLED   layer: arm");
  EXPECT_TRUE(shown(driving(false), {80, 24})[0].starts_with("andros-bridge run ")) << "run's title unchanged";
}

TEST(RunScreen, AtLeastTheBannerAndTheStateOnATinyTerminal) {
  const auto lines = shown(driving(true), {30, 2});
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_NE(lines[0].find("WEAPONS ENABLED"), std::string::npos) << lines[0];
  EXPECT_TRUE(lines[1].starts_with("andros-bridge run")) << lines[1];
}

TEST(RunScreen, AWeaponsModeIsSaidInTheBannerAndOnTheStateLine) {
  RunStatus s = driving(true);
  s.layer = "weapons";
  s.weapons_mode = true;
  for (const TermSize size : {TermSize{80, 24}, TermSize{30, 2}}) {
    const auto lines = shown(s, size);
    EXPECT_NE(lines[0].find("WEAPONS LAYER: an armed fire"), std::string::npos) << lines[0];
  }
  const auto lines = shown(s, {80, 24});
  EXPECT_EQ(lines[2], "state       ENABLED   layer: weapons    WEAPONS LAYER ");
  const auto text = render_run_screen(s, {80, 24}).render({80, 24}, true);
  EXPECT_NE(text.find("\x1b[1;97;41m WEAPONS LAYER \x1b[0m"), std::string::npos) << text;
  // Out of it, the run's banner again and no word of a layer with weapons.
  s.weapons_mode = false;
  const auto plain_lines = shown(s, {80, 24});
  EXPECT_NE(plain_lines[0].find("WEAPONS ENABLED: weapon signals may be sent"), std::string::npos) << plain_lines[0];
  EXPECT_EQ(plain_lines[2], "state       ENABLED   layer: weapons");
}

// Issue 28, item 1: with --weapons, A and LT held and RB pressed, the state
// line (a long held-back reason, the layer, the weapons mode) wraps under its
// label: nothing is cut, at 80 columns or 100.
TEST(RunScreen, TheStateLineWrapsAndKeepsTheLayerAndTheWeaponsMode) {
  RunStatus s = driving(true);
  s.layer = "weapons";
  s.weapons_mode = true;
  s.armed = true;
  s.speed = {0, 3, 0.25};
  s.enable_text = "enabled; at rest first: a lefttrigger rightx righty dpup";
  s.held_back = "a lefttrigger rightx righty dpup";
  for (const TermSize size : {TermSize{80, 24}, TermSize{100, 30}}) {
    SCOPED_TRACE(std::to_string(size.cols));
    const auto lines = shown(s, size);
    std::string state;  // the state's lines, joined
    bool in_state = false;
    for (const auto& line : lines) {
      EXPECT_LE(line.size(), static_cast<std::size_t>(size.cols)) << line;
      if (line.starts_with("state ")) in_state = true;
      else if (!line.starts_with("            ")) in_state = false;
      if (in_state) state += line + "\n";
    }
    for (const auto* whole : {"ENABLED", "at rest first: a lefttrigger rightx righty dpup", "layer: weapons",
                              "WEAPONS LAYER ARMED", "speed level 1/3 (25%)"}) {
      EXPECT_NE(state.find(whole), std::string::npos) << whole << "\n" << state;
    }
  }
  // A long reason while not enabled: wrapped under the label, the layer after it.
  s.state = run::OpState::kNotEnabled;
  s.weapons_mode = false;
  s.enable_text = "driving was interrupted: release and press the deadman again (the link came back while it was held)";
  const auto lines = shown(s, {80, 24});
  for (const auto& line : lines) EXPECT_LE(line.size(), 80U) << line;
  EXPECT_EQ(lines[2], "state       NOT ENABLED: driving was interrupted: release and press the deadman");
  EXPECT_EQ(lines[3], "            again (the link came back while it was held)   layer: weapons");
}

// Issue 28, items 6 and 10: the rate says "measuring" until frames since the
// link came up mean something; one loss is "1 time".
TEST(RunScreen, TheRateIsMeasuringUntilItMeansSomething) {
  RunStatus s = driving(false);
  s.sent_timing = timing::TimingSummary{.rate_hz = 14.2, .period_ms = 70.0, .jitter_ms = 339.5, .count = 3};
  s.link.losses = 1;
  auto text = render_run_screen(s, {80, 24}).text();
  EXPECT_NE(text.find("rate        measuring since the link came up (3 frames, of 25 Hz)"), std::string::npos) << text;
  EXPECT_NE(text.find("andros-bridge run  robot HD1  code 01  measuring"), std::string::npos) << text;
  EXPECT_EQ(text.find("14.2"), std::string::npos) << text;
  EXPECT_NE(text.find("link lost 1 time\n"), std::string::npos) << text;
  s.sent_timing.count = 25;
  s.link.losses = 2;
  text = render_run_screen(s, {80, 24}).text();
  EXPECT_NE(text.find("rate        14.2 Hz of 25"), std::string::npos) << text;
  EXPECT_NE(text.find("link lost 2 times\n"), std::string::npos) << text;
}

TEST(RunScreen, TheSpeedLevelIsOnTheStateLineWhenTheMappingHasLevels) {
  RunStatus s = driving(false);
  EXPECT_EQ(shown(s, {80, 24})[1], "state       ENABLED   layer: arm");  // the default, one level of 100%: not said
  s.speed = {1, 3, 0.5};
  EXPECT_EQ(shown(s, {80, 24})[1], "state       ENABLED   layer: arm   speed level 2/3 (50%)");
  s.speed = {0, 1, 0.125};  // one level below full speed: said too
  EXPECT_EQ(shown(s, {80, 24})[1], "state       ENABLED   layer: arm   speed level 1/1 (12.5%)");
  // Not enabled, a long reason: after it, or on a line of its own rather than cut.
  s.state = run::OpState::kNotEnabled;
  s.enable_text = "deadman held since connect or start-up: release and press it again";
  s.speed = {2, 3, 1.0};
  EXPECT_EQ(shown(s, {80, 24})[2], "            press it again   layer: arm   speed level 3/3 (100%)");
  const auto narrow = shown(s, {40, 24});
  const auto link = std::find_if(narrow.begin(), narrow.end(), [](const auto& l) { return l.starts_with("link"); });
  ASSERT_NE(link, narrow.begin());
  EXPECT_EQ(*(link - 1), "            speed level 3/3 (100%)");
  for (const auto& line : narrow) EXPECT_LE(line.size(), 40U) << line;
}

TEST(RunScreen, NotEnabledLinkDownAndNoControllerAreSaidInRed) {
  RunStatus s = driving(false);
  s.state = run::OpState::kNotEnabled;
  s.enable_text = "deadman released";
  s.link_state = link::LinkState::kConnecting;
  s.link_detail = "gone";
  s.connected = false;
  const auto lines = shown(s, {80, 24});
  EXPECT_EQ(lines[1], "state       NOT ENABLED: deadman released   layer: arm");
  EXPECT_EQ(lines[2], "link        /dev/andros-switchbox 9600 8N1: connecting - gone");
  EXPECT_EQ(lines[3], "controller  none connected");
  const auto text = render_run_screen(s, {80, 24}).render({80, 24}, true);
  EXPECT_NE(text.find("\x1b[1;31mNOT ENABLED: deadman released\x1b[0m"), std::string::npos) << text;
  EXPECT_NE(text.find("\x1b[1;31mconnecting\x1b[0m"), std::string::npos) << text;
  EXPECT_NE(text.find("\x1b[1;31mnone connected\x1b[0m"), std::string::npos) << text;
  const auto ok = render_run_screen(driving(true), {80, 24}).render({80, 24}, true);
  EXPECT_NE(ok.find("\x1b[1;32mENABLED\x1b[0m"), std::string::npos) << ok;
  EXPECT_NE(ok.find("\x1b[1;32mup\x1b[0m"), std::string::npos) << ok;
  EXPECT_NE(ok.find("\x1b[1;97;41m"), std::string::npos) << ok;
}

TEST(RunScreen, StoppedIsARedLineAboveAllSayingWhoStopped) {
  RunStatus s = driving(false);
  s.state = run::OpState::kStopped;
  s.stopped_by = "stopped by the supervisor (Pad 2)";
  s.enable_text =
      s.stopped_by + ": to reset, release the deadman and hold back+start 2 s; then press the deadman afresh";
  s.layer.clear();
  const auto lines = shown(s, {80, 24});
  EXPECT_EQ(lines[0], "                    STOP: stopped by the supervisor (Pad 2)                     ");
  EXPECT_TRUE(lines[1].starts_with("andros-bridge run")) << lines[1];
  EXPECT_EQ(lines[2], "state       STOPPED: stopped by the supervisor (Pad 2): to reset, release the");
  const auto text = render_run_screen(s, {80, 24}).render({80, 24}, true);
  EXPECT_NE(text.find("\x1b[1;97;41m                    STOP"), std::string::npos) << text;
  // On a tiny terminal the stop is what stays.
  EXPECT_NE(shown(s, {30, 2})[0].find("STOP"), std::string::npos);
  // Not stopped: no such line.
  s.state = run::OpState::kNotEnabled;
  EXPECT_EQ(shown(s, {80, 24})[0].find("STOP"), std::string::npos);
}

TEST(RunScreen, TheSupervisorsControllerHasItsOwnLineUnderTheOperators) {
  RunStatus s = driving(false);
  EXPECT_TRUE(shown(s, {80, 24})[4].starts_with("mapping     ")) << "a supervisor's line without one";
  s.supervised = true;
  s.supervisor_connected = true;
  s.supervisor = "Pad B";
  s.consent = mapping::ConsentState::kGiven;
  auto lines = shown(s, {80, 24});
  EXPECT_EQ(lines[3], "controller  Xbox 360 Controller");
  EXPECT_EQ(lines[4], "supervisor  Pad B  consent: GIVEN");
  EXPECT_TRUE(lines[5].starts_with("mapping     ")) << lines[5];
  s.supervisor_stop = true;
  s.consent = mapping::ConsentState::kHeldBack;
  EXPECT_EQ(shown(s, {80, 24})[4], "supervisor  Pad B   STOP HELD   consent: release and press again");
  const auto text = render_run_screen(s, {80, 24}).render({80, 24}, true);
  EXPECT_NE(text.find("\x1b[1;97;41m STOP HELD \x1b[0m"), std::string::npos) << text;
  s.consent = mapping::ConsentState::kNotAsked;
  s.supervisor_stop = false;
  EXPECT_EQ(shown(s, {80, 24})[4], "supervisor  Pad B");
  s.supervisor_connected = false;
  EXPECT_EQ(shown(s, {80, 24})[4], "supervisor  none connected: nothing moves without it");
  // At 80x24 with the simulated vehicle the gauges and the frame still fit, and the log keeps 3 rows.
  lines = shown(s, {80, 24});
  EXPECT_LE(lines.size(), 21U);
  EXPECT_TRUE(lines.back().starts_with("  frame     ")) << lines.back();
}

TEST(RunScreen, TheHeadlineIsTheOperatingState) {
  RunStatus s = driving(false);
  s.state = run::OpState::kNoLink;
  s.enable_text = "nothing reaches the vehicle";
  EXPECT_EQ(shown(s, {80, 24})[1], "state       NO LINK: nothing reaches the vehicle   layer: arm");
  s.state = run::OpState::kReloading;
  s.enable_text = "neutral frames while the settings are read";
  EXPECT_EQ(shown(s, {80, 24})[1], "state       RELOADING: neutral frames while the settings are read   layer: arm");
}

TEST(RunScreen, ALongReasonWrapsUnderItsLabelInsteadOfBeingCut) {
  RunStatus s = driving(false);
  s.state = run::OpState::kNotEnabled;
  s.enable_text = "deadman held since connect or start-up: release and press it again";
  const auto lines = shown(s, {80, 24});
  EXPECT_EQ(lines[1], "state       NOT ENABLED: deadman held since connect or start-up: release and");
  EXPECT_EQ(lines[2], "            press it again   layer: arm");
  EXPECT_TRUE(lines[3].starts_with("link ")) << lines[3];
}

TEST(RunScreen, NoEscapesWithoutColour) {
  RunStatus s = driving(true);
  s.state = run::OpState::kShuttingDown;
  const auto text = render_run_screen(s, {80, 24}).render({80, 24}, false);
  EXPECT_EQ(text.find('\x1b'), std::string::npos) << text;
  EXPECT_NE(text.find("SHUTTING DOWN: sending neutral frames"), std::string::npos) << text;
}

TEST(RunScreen, ALongMappingPathKeepsItsFileName) {
  RunStatus s = driving(false);
  s.mapping_file = "/home/operator/a/very/long/directory/name/that/goes/on/and/on/and/on/field/hd1-custom.yaml";
  const auto lines = shown(s, {60, 24});
  const auto mapping = std::find_if(lines.begin(), lines.end(), [](const auto& l) { return l.starts_with("mapping"); });
  ASSERT_NE(mapping, lines.end());
  EXPECT_TRUE(mapping->starts_with("mapping     ...")) << *mapping;
  EXPECT_TRUE(mapping->ends_with("/field/hd1-custom.yaml")) << *mapping;
  EXPECT_EQ(mapping->size(), 60u);
}

TEST(RunScreen, TheSwitchListShrinksToTheActiveOnesBeforeTheGaugesGo) {
  RunStatus s = driving(false);
  protocol::ControlState c;
  c[protocol::signal_id("safety")] = 1;
  c[protocol::signal_id("shoulder_cw")] = 1;
  c[protocol::signal_id("drive")] = 128;
  s.vehicle->last = protocol::FrameBuilder(1).build(c);
  auto text = render_run_screen(s, {80, 40}).text();
  EXPECT_NE(text.find("  drive    ENABLED (DEADMAN HELD) brake released"), std::string::npos) << text;
  text = render_run_screen(s, {80, 24}).text();
  EXPECT_NE(text.find("as the vehicle decodes it:\n  set       vehicle speed medium  main video 1  inset off\n"
                      "  drive    ENABLED (DEADMAN HELD)\n  arm      SHOULDER DOWN\n  drive      ["),
            std::string::npos)
      << text;
  const auto lines = shown(s, {80, 24});
  EXPECT_NE(std::find(lines.begin(), lines.end(), "  drive      [          |          ] 128"), lines.end());
}

// Issue 19, finding 7: the operator's second pass over the screen at 80x24.
TEST(RunScreen, ALongLinkNameIsCutInItsMiddleAndTheStateStays) {
  for (const auto state : {link::LinkState::kUp, link::LinkState::kConnecting}) {
    RunStatus s = driving(false);
    s.link_name = "/dev/serial/by-id/usb-FTDI_FT232R_USB_UART_A50285BI-if00-port0 9600 8N1";
    s.link_state = state;
    const auto lines = shown(s, {79, 24});
    const auto& link = lines[2];
    const auto word = std::string(link::to_string(state));
    EXPECT_TRUE(link.ends_with(": " + word)) << link;
    EXPECT_LE(link.size(), 79u) << link;
    EXPECT_NE(link.find("..."), std::string::npos) << link;
    EXPECT_TRUE(link.starts_with("link        /dev/serial/by-id")) << link;
    EXPECT_NE(link.find("A50285BI-if00-port0 9600 8N1: "), std::string::npos) << link;  // the serial number kept
  }
}

TEST(RunScreen, SelectorPositionsWithoutABitAreShown) {
  RunStatus s = driving(false);
  protocol::ControlState c;
  c[protocol::signal_id("main_video_3")] = 1;
  c[protocol::signal_id("inset_4")] = 1;
  s.vehicle->last = protocol::FrameBuilder(1).build(c);
  auto text = render_run_screen(s, {80, 24}).text();
  EXPECT_NE(text.find("  set       vehicle speed medium  main video 3  inset 4\n"), std::string::npos) << text;
  c = {};
  c[protocol::signal_id("speed_low")] = 1;
  s.vehicle->last = protocol::FrameBuilder(1).build(c);
  text = render_run_screen(s, {80, 24}).text();
  EXPECT_NE(text.find("  set       vehicle speed low  main video 1  inset off\n"), std::string::npos) << text;
}

TEST(RunScreen, WeaponsOffArmedAndFiringAreEachSaid) {
  // Without --weapons the title line says so; no banner.
  auto lines = shown(driving(false), {80, 24});
  EXPECT_TRUE(lines[0].ends_with("  weapons off")) << lines[0];
  // With them, in a weapons mode: armed is said in the banner and the state line.
  RunStatus s = driving(true);
  s.weapons_mode = true;
  s.armed = true;
  lines = shown(s, {80, 24});
  EXPECT_NE(lines[0].find("WEAPONS LAYER: ARMED: a fire button fires"), std::string::npos) << lines[0];
  EXPECT_NE(lines[2].find("WEAPONS LAYER ARMED"), std::string::npos) << lines[2];
  EXPECT_EQ(lines[1].find("weapons off"), std::string::npos) << lines[1];
  s.armed = false;
  EXPECT_EQ(shown(s, {80, 24})[0].find("ARMED"), std::string::npos);
  // A weapon firing is white on red, not the reverse video of any other switch.
  protocol::ControlState c;
  c[protocol::signal_id("safety")] = 1;
  c[protocol::signal_id("weapon_2")] = 1;
  c[protocol::signal_id("tool_on")] = 1;
  const auto data = protocol::FrameBuilder(1).build(c);
  std::optional<Style> weapon;
  std::optional<Style> tool;
  for (const auto& line : switch_lines(data, 80, true, SwitchNames::kOperator)) {
    for (const auto& piece : line.pieces()) {
      if (piece.text == "WEAPON 2") weapon = piece.style;
      if (piece.text == "TOOL ON") tool = piece.style;
    }
  }
  EXPECT_EQ(weapon, Style::kBanner);
  EXPECT_EQ(tool, Style::kReverse);
}

TEST(RunScreen, TheRecorderSaysWhereItWritesOrWhatItDropped) {
  auto s = driving(false);
  const auto line = [&s] {
    const auto lines = shown(s, TermSize{100, 40});
    const auto it =
        std::find_if(lines.begin(), lines.end(), [](const std::string& l) { return l.starts_with("recorder"); });
    return it == lines.end() ? std::string() : *it;
  };
  EXPECT_EQ(line(), "");  // off
  s.recorder = "/var/lib/andros-bridge/20240501-120000-42.andros-session";
  EXPECT_EQ(line(), "recorder    /var/lib/andros-bridge/20240501-120000-42.andros-session");
  s.recorder = "12 records dropped (No space left on device): the session is incomplete";
  s.recorder_failing = true;
  const auto screen = render_run_screen(s, TermSize{100, 40}).fit(TermSize{100, 40});
  const auto it =
      std::find_if(screen.begin(), screen.end(), [](const auto& l) { return plain(l, 100).starts_with("recorder"); });
  ASSERT_NE(it, screen.end());
  EXPECT_EQ(it->pieces().back().style, Style::kAlert);
}

}  // namespace
}  // namespace andros::view
