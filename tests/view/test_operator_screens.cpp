#include <gtest/gtest.h>

#include <set>

#include "andros/base/clock.hpp"
#include "andros/timing/frame_timing.hpp"
#include "andros/view/operator_screens.hpp"

namespace andros::view {
namespace {

/// The lines as plain text, one a line.
std::string joined(const std::vector<Line>& lines) {
  std::string out;
  for (const auto& line : lines) out += plain(line, 1000) + "\n";
  return out;
}

/// switch_lines at 78 columns, then the gauges: the old panel.
std::string render_frame_panel(const protocol::DataBytes& data, int center) {
  return joined(switch_lines(data, 78, false)) + joined(gauge_lines(data, center));
}

TEST(OperatorScreens, EveryBitSignalIsInExactlyOneGroup) {
  std::multiset<protocol::SignalId> seen;
  for (const auto& g : signal_groups()) seen.insert(g.signals.begin(), g.signals.end());
  for (protocol::SignalId id = 0; id < protocol::kSignalCount; ++id) {
    const bool shown = protocol::info(id).is_bit() && protocol::info(id).kind != protocol::SignalKind::kConstant;
    EXPECT_EQ(seen.count(id), shown ? 1u : 0u) << protocol::info(id).name;
  }
}

TEST(OperatorScreens, PanelShowsActiveSwitchesAndGauges) {
  protocol::ControlState s;
  s[protocol::signal_id("safety")] = 1;
  s[protocol::signal_id("pt_left")] = 1;
  s[protocol::signal_id("drive")] = 255;
  s[protocol::signal_id("pivot")] = 0;
  s[protocol::signal_id("light")] = 255;
  const auto text = render_frame_panel(protocol::FrameBuilder(1).build(s), mapping::kDefaultCenter);
  EXPECT_NE(text.find(" SAFETY drive_brake"), std::string::npos) << text;
  EXPECT_NE(text.find(" PT_LEFT pt_right"), std::string::npos) << text;
  EXPECT_NE(text.find("drive      [          |##########] 255"), std::string::npos) << text;
  EXPECT_NE(text.find("pivot      [##########|          ]   0"), std::string::npos) << text;
  EXPECT_NE(text.find("light      [#####################] 255"), std::string::npos) << text;
  for (std::size_t start = 0, end; (end = text.find('\n', start)) != std::string::npos; start = end + 1) {
    EXPECT_LE(end - start, 80u) << text.substr(start, end - start);
  }
}

/// A frame with drive and pivot at these bytes, enabled (safety 1) or neutral.
protocol::DataBytes drive_pivot(std::uint8_t drive, std::uint8_t pivot, bool enabled = true) {
  protocol::ControlState s;
  s[protocol::signal_id("safety")] = enabled ? 1 : 0;
  s[protocol::signal_id("drive")] = drive;
  s[protocol::signal_id("pivot")] = pivot;
  return protocol::FrameBuilder(1).build(s);
}

// The blocks are kept from one redraw to the next (the frame at rest): asked
// again for what they last drew, and then for something else, they must say
// what that is, never what they said before.
TEST(OperatorScreens, KeptBlocksFollowEveryChangeOfWhatTheyShow) {
  const auto rest = drive_pivot(128, 128, false);
  const auto moving = drive_pivot(200, 60);
  const auto at_rest = render_frame_panel(rest, mapping::kDefaultCenter);
  EXPECT_EQ(render_frame_panel(rest, mapping::kDefaultCenter), at_rest);
  const auto driving = render_frame_panel(moving, mapping::kDefaultCenter);
  EXPECT_NE(driving, at_rest);
  EXPECT_NE(driving.find(" SAFETY"), std::string::npos) << driving;
  EXPECT_EQ(render_frame_panel(rest, mapping::kDefaultCenter), at_rest);
  // The same frame, another centre (a new mapping's trim): the gauges move.
  EXPECT_NE(render_frame_panel(moving, 100), driving);
  EXPECT_EQ(render_frame_panel(moving, mapping::kDefaultCenter), driving);
  // The same frame, compact or not, narrower, the operator's words: each its own.
  const auto full = joined(switch_lines(moving, 78, false));
  const auto compact = joined(switch_lines(moving, 78, true));
  EXPECT_NE(compact, full);
  EXPECT_EQ(compact.find("drive_brake"), std::string::npos) << compact;
  EXPECT_NE(joined(switch_lines(moving, 30, false)), full);
  EXPECT_NE(joined(switch_lines(moving, 78, false, SwitchNames::kOperator)), full);
  EXPECT_EQ(joined(switch_lines(moving, 78, false)), full);
  EXPECT_NE(plain(selector_line(moving), 200), "");
}

TEST(OperatorScreens, CentredGaugesGrowFromTheCentreTheyAreHanded) {
  // center: 120 (the lowest trim): 120 is at rest while enabled, 60 half way down, 255 and 0 the ends.
  auto text = render_frame_panel(drive_pivot(120, 60), 120);
  EXPECT_NE(text.find("drive      [          |          ] 120"), std::string::npos) << text;
  EXPECT_NE(text.find("pivot      [     #####|          ]  60"), std::string::npos) << text;
  text = render_frame_panel(drive_pivot(255, 0), 120);
  EXPECT_NE(text.find("drive      [          |##########] 255"), std::string::npos) << text;
  EXPECT_NE(text.find("pivot      [##########|          ]   0"), std::string::npos) << text;
  // The run screen draws around the centre in its status.
  RunStatus s;
  s.center = 120;
  s.sent = drive_pivot(120, 120);
  text = render_run_screen(s, {80, 40}).text();
  EXPECT_NE(text.find("drive      [          |          ] 120"), std::string::npos) << text;
  EXPECT_NE(text.find("pivot      [          |          ] 120"), std::string::npos) << text;
}

TEST(OperatorScreens, ANeutralFrameDrawsEmptyGaugesWhateverTheTrim) {
  // Neutral frames carry the protocol's 128, not the trim: at rest, so empty.
  auto text = render_frame_panel(drive_pivot(128, 128, false), 120);
  EXPECT_NE(text.find("drive      [          |          ] 128"), std::string::npos) << text;
  EXPECT_NE(text.find("pivot      [          |          ] 128"), std::string::npos) << text;
  // Enabled, 128 is 8 above the trim: a step forward.
  text = render_frame_panel(drive_pivot(128, 128, true), 120);
  EXPECT_NE(text.find("drive      [          |#         ] 128"), std::string::npos) << text;
}

TEST(OperatorScreens, StateLineNamesTheInputsHeldBackUntilAtRest) {
  RunStatus s;
  s.state = run::OpState::kEnabled;
  s.enable_text = "enabled";
  EXPECT_NE(render_run_screen(s, {80, 24}).text().find("state       ENABLED\n"), std::string::npos);
  s.enable_text = "enabled; at rest first: lefty";
  s.held_back = "lefty";
  EXPECT_NE(render_run_screen(s, {80, 24}).text().find("state       ENABLED; at rest first: lefty\n"),
            std::string::npos);
  // The screen says what the board gave it apart, never a part of the words it parsed.
  s.enable_text = "enabled";
  EXPECT_NE(render_run_screen(s, {80, 24}).text().find("state       ENABLED; at rest first: lefty\n"),
            std::string::npos);
  s.held_back.clear();
  s.enable_text = "enabled; at rest first: lefty";
  EXPECT_NE(render_run_screen(s, {80, 24}).text().find("state       ENABLED\n"), std::string::npos);
}

TEST(FrameTiming, MeasuresRateAndJitter) {
  timing::FrameTiming t;
  const std::int64_t p = 40 * kNsPerMs;
  for (int i = 0; i < 50; ++i) t.add(i * p + (i % 2 == 0 ? 0 : kNsPerMs));
  const auto s = t.summary(49 * p);
  EXPECT_EQ(s.count, 50u);
  EXPECT_NEAR(s.rate_hz, 25.0, 0.02);  // 1 / the mean period
  EXPECT_NEAR(s.period_ms, 40.0, 0.05);
  EXPECT_NEAR(s.jitter_ms, 1.0, 0.05);
  EXPECT_NEAR(s.worst_ms, 1.0, 0.05);
}

TEST(FrameTiming, TheRateIsTheWindowsMeanNotACountThatFlipsWithThePhase) {
  // 25 Hz with a little jitter, read at every phase of a period: a count of
  // the last second said 25 or 26; the window's mean says 25.0 each time.
  timing::FrameTiming t;
  const std::int64_t p = 40'000'000;
  for (int i = 0; i < 200; ++i) t.add(i * p + (i % 3) * 300'000);
  for (std::int64_t phase = 0; phase < p; phase += p / 8) {
    const auto s = t.summary(199 * p + phase);
    EXPECT_NEAR(s.rate_hz, 25.0, 0.05) << phase;
  }
  // A stream that stopped: 0 once no frame came for 2 periods (at least 1 s).
  EXPECT_GT(t.summary(199 * p + 900'000'000).rate_hz, 24.9);
  EXPECT_EQ(t.summary(199 * p + 1'100'000'000).rate_hz, 0.0);
}

}  // namespace
}  // namespace andros::view
