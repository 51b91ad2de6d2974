#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "andros/view/status_view.hpp"

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
  s.sent_timing = timing::TimingSummary{.rate_hz = 25.0, .period_ms = 40.0, .jitter_ms = 0.05};
  s.vehicle = link::VehicleSnapshot{};
  s.vehicle->last = s.sent;
  return s;
}

std::vector<std::string> shown(const RunStatus& s, TermSize size) {
  std::vector<std::string> out;
  for (const auto& line : render_run_view(s, size).fit(size)) {
    out.push_back(plain(line, static_cast<std::size_t>(size.cols)));
  }
  return out;
}

/// The header's lines start so, in this order, from the top.
void expect_header(const std::vector<std::string>& lines, bool weapons) {
  std::vector<std::string> want = {"andros-bridge run  robot HD1  code 01  25.0 Hz", "state       ENABLED",
                                   "link        /dev/andros-switchbox", "controller  Xbox 360 Controller",
                                   "mapping     "};
  if (weapons) want.insert(want.begin(), "");  // the banner, checked below
  ASSERT_GE(lines.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i) {
    const auto prefix = want[i].substr(0, lines[i].size());
    EXPECT_TRUE(lines[i].starts_with(prefix)) << "line " << i << ": " << lines[i];
  }
  const auto banner = lines[0].find("WEAPONS ENABLED");
  EXPECT_EQ(banner != std::string::npos, weapons) << lines[0];
}

TEST(RunView, TheHeaderIsFirstAndWholeAt80x24AndSmaller) {
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

TEST(RunView, AtLeastTheBannerAndTheStateOnATinyTerminal) {
  const auto lines = shown(driving(true), {30, 2});
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_NE(lines[0].find("WEAPONS ENABLED"), std::string::npos) << lines[0];
  EXPECT_TRUE(lines[1].starts_with("andros-bridge run")) << lines[1];
}

TEST(RunView, AWeaponsModeIsSaidInTheBannerAndOnTheStateLine) {
  RunStatus s = driving(true);
  s.layer = "weapons";
  s.weapons_mode = true;
  for (const TermSize size : {TermSize{80, 24}, TermSize{30, 2}}) {
    const auto lines = shown(s, size);
    EXPECT_NE(lines[0].find("WEAPONS LAYER: an armed fire"), std::string::npos) << lines[0];
  }
  const auto lines = shown(s, {80, 24});
  EXPECT_EQ(lines[2], "state       ENABLED   layer: weapons    WEAPONS LAYER ");
  const auto text = render_run_view(s, {80, 24}).render({80, 24}, true);
  EXPECT_NE(text.find("\x1b[1;97;41m WEAPONS LAYER \x1b[0m"), std::string::npos) << text;
  // Out of it, the run's banner again and no word of a layer with weapons.
  s.weapons_mode = false;
  const auto plain_lines = shown(s, {80, 24});
  EXPECT_NE(plain_lines[0].find("WEAPONS ENABLED: weapon signals may be sent"), std::string::npos) << plain_lines[0];
  EXPECT_EQ(plain_lines[2], "state       ENABLED   layer: weapons");
}

TEST(RunView, NotEnabledLinkDownAndNoControllerAreSaidInRed) {
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
  const auto text = render_run_view(s, {80, 24}).render({80, 24}, true);
  EXPECT_NE(text.find("\x1b[1;31mNOT ENABLED: deadman released\x1b[0m"), std::string::npos) << text;
  EXPECT_NE(text.find("\x1b[1;31mconnecting\x1b[0m"), std::string::npos) << text;
  EXPECT_NE(text.find("\x1b[1;31mnone connected\x1b[0m"), std::string::npos) << text;
  const auto ok = render_run_view(driving(true), {80, 24}).render({80, 24}, true);
  EXPECT_NE(ok.find("\x1b[1;32mENABLED\x1b[0m"), std::string::npos) << ok;
  EXPECT_NE(ok.find("\x1b[1;32mup\x1b[0m"), std::string::npos) << ok;
  EXPECT_NE(ok.find("\x1b[1;97;41m"), std::string::npos) << ok;
}

TEST(RunView, TheHeadlineIsTheOperatingState) {
  RunStatus s = driving(false);
  s.state = run::OpState::kNoLink;
  s.enable_text = "nothing reaches the vehicle";
  EXPECT_EQ(shown(s, {80, 24})[1], "state       NO LINK: nothing reaches the vehicle   layer: arm");
  s.state = run::OpState::kReloading;
  s.enable_text = "neutral frames while the settings are read";
  EXPECT_EQ(shown(s, {80, 24})[1], "state       RELOADING: neutral frames while the settings are read   layer: arm");
}

TEST(RunView, ALongReasonWrapsUnderItsLabelInsteadOfBeingCut) {
  RunStatus s = driving(false);
  s.state = run::OpState::kNotEnabled;
  s.enable_text = "deadman held since connect or start-up: release and press it again";
  const auto lines = shown(s, {80, 24});
  EXPECT_EQ(lines[1], "state       NOT ENABLED: deadman held since connect or start-up: release and");
  EXPECT_EQ(lines[2], "            press it again   layer: arm");
  EXPECT_TRUE(lines[3].starts_with("link ")) << lines[3];
}

TEST(RunView, NoEscapesWithoutColour) {
  RunStatus s = driving(true);
  s.state = run::OpState::kStopping;
  const auto text = render_run_view(s, {80, 24}).render({80, 24}, false);
  EXPECT_EQ(text.find('\x1b'), std::string::npos) << text;
  EXPECT_NE(text.find("SHUTTING DOWN: sending neutral frames"), std::string::npos) << text;
}

TEST(RunView, ALongMappingPathKeepsItsFileName) {
  RunStatus s = driving(false);
  s.mapping_file = "/home/operator/a/very/long/directory/name/that/goes/on/and/on/and/on/field/hd1-custom.yaml";
  const auto lines = shown(s, {60, 24});
  EXPECT_TRUE(lines[4].starts_with("mapping     ...")) << lines[4];
  EXPECT_TRUE(lines[4].ends_with("/field/hd1-custom.yaml")) << lines[4];
  EXPECT_EQ(lines[4].size(), 60u);
}

TEST(RunView, TheSwitchListShrinksToTheActiveOnesBeforeTheGaugesGo) {
  RunStatus s = driving(false);
  protocol::ControlState c;
  c[protocol::signal_id("safety")] = 1;
  c[protocol::signal_id("shoulder_cw")] = 1;
  c[protocol::signal_id("drive")] = 128;
  s.vehicle->last = protocol::FrameBuilder(1).build(c);
  auto text = render_run_view(s, {80, 40}).text();
  EXPECT_NE(text.find("  drive    SAFETY drive_brake"), std::string::npos) << text;
  text = render_run_view(s, {80, 24}).text();
  EXPECT_NE(text.find("as the vehicle decodes it:\n  drive    SAFETY\n  arm      SHOULDER_CW\n  drive      ["), std::string::npos) << text;
  const auto lines = shown(s, {80, 24});
  EXPECT_NE(std::find(lines.begin(), lines.end(), "  drive      [          |          ] 128"), lines.end());
}

TEST(RunView, TheRecorderSaysWhereItWritesOrWhatItDropped) {
  auto s = driving(false);
  const auto line = [&s] {
    const auto lines = shown(s, TermSize{100, 40});
    const auto it = std::find_if(lines.begin(), lines.end(), [](const std::string& l) { return l.starts_with("recorder"); });
    return it == lines.end() ? std::string() : *it;
  };
  EXPECT_EQ(line(), "");  // off
  s.recorder = "/var/lib/andros-bridge/20240501-120000-42.andros-session";
  EXPECT_EQ(line(), "recorder    /var/lib/andros-bridge/20240501-120000-42.andros-session");
  s.recorder = "12 records dropped (No space left on device): the session is incomplete";
  s.recorder_failing = true;
  const auto screen = render_run_view(s, TermSize{100, 40}).fit(TermSize{100, 40});
  const auto it = std::find_if(screen.begin(), screen.end(),
                               [](const auto& l) { return plain(l, 100).starts_with("recorder"); });
  ASSERT_NE(it, screen.end());
  EXPECT_EQ(it->pieces().back().style, Style::kAlert);
}

}  // namespace
}  // namespace andros::view
