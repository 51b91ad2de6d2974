// A plot's range starts and ends at the times asked (view/plot.hpp): what was
// in effect at --from is drawn from the left edge, a reset before it is not
// put at a later time, nothing is drawn past the last tick; a stop label
// that does not fit its band is left off; a stop pressed and released within
// a millisecond still shows on its lane.
#include <gtest/gtest.h>
#include <spdlog/fmt/fmt.h>

#include <regex>
#include <tuple>

#include "andros/input/events.hpp"
#include "andros/mapping/loader.hpp"
#include "andros/view/plot.hpp"

namespace andros::view {
namespace {

/// A 10 s session at 25 Hz, one frame repeated: not enabled, enabled at 1 s,
/// stopped by the operator at 2 s and by the supervisor at 2.04 s, reset by
/// the supervisor at 4 s, enabled again at 7 s.
record::Session stops_session() {
  record::Session s;
  s.settings.rate_millihertz = 25'000;
  s.frames.emplace_back();
  using S = run::OpState;
  s.states = {
      {0, S::kNotEnabled}, {1'000, S::kEnabled}, {2'000, S::kStopped}, {4'000, S::kNotEnabled}, {7'000, S::kEnabled}};
  for (const auto& [t, reset, by] :
       std::vector<std::tuple<std::int64_t, bool, run::StopBy>>{{2'000, false, run::StopBy::kOperator},
                                                                {2'040, false, run::StopBy::kSupervisor},
                                                                {4'000, true, run::StopBy::kSupervisor}}) {
    record::StopRecord r;
    r.t_ms = t;
    r.reset = reset;
    r.by = by;
    s.stops.push_back(r);
  }
  s.end = record::EndRecord{.t_ms = 10'000, .last_tick = 250, .frames_sent = 251, .why = "SIGINT"};
  return s;
}

/// The state band's rects: (x, x + width, colour), left to right.
std::vector<std::tuple<double, double, std::string>> bands(const std::string& svg) {
  std::vector<std::tuple<double, double, std::string>> out;
  const std::regex band(R"re(<rect x="([\d.]+)" y="74.0" width="([\d.]+)" height="20.0" fill="([^"]+)")re");
  for (auto m = std::sregex_iterator(svg.begin(), svg.end(), band); m != std::sregex_iterator(); ++m) {
    out.emplace_back(std::stod((*m)[1]), std::stod((*m)[1]) + std::stod((*m)[2]), (*m)[3]);
  }
  return out;
}

PlotInput page_of(const record::Session& s, std::int64_t from_ms, std::int64_t to_ms) {
  PlotInput in;
  in.samples = plot_samples(s);
  in.from_ms = from_ms;
  in.to_ms = to_ms;
  return in;
}

constexpr const char* kNotEnabled = "#c9c9c9";
constexpr const char* kEnabled = "#4caf50";

TEST(PlotRange, WhatHeldAtTheStartIsDrawnFromTheLeftEdge) {
  // 5 to 8 s: inside the "not enabled" after the reset at 4 s.
  const auto svg = render_plot_svg(page_of(stops_session(), 5'000, 8'000));
  const auto got = bands(svg);
  ASSERT_EQ(got.size(), 2U) << svg;
  EXPECT_DOUBLE_EQ(std::get<0>(got[0]), 150.0);
  EXPECT_EQ(std::get<2>(got[0]), kNotEnabled);
  EXPECT_NEAR(std::get<0>(got[1]), 150 + 945.0 * 2 / 3, 0.06);  // enabled at 7 s
  EXPECT_EQ(std::get<2>(got[1]), kEnabled);
  EXPECT_NEAR(std::get<1>(got[1]), 1095, 0.06);
  // The reset at 4 s is before the range: neither its tick nor its label, anywhere.
  EXPECT_EQ(svg.find("reset by the"), std::string::npos) << svg;
  EXPECT_EQ(svg.find("stroke=\"#212121\""), std::string::npos);
  EXPECT_NE(svg.find("5 to 8 s, 76 ticks"), std::string::npos) << "5.00 to 8.00 s at 25 Hz";

  // From 3 s: the reset is in the range, at 4 s.
  const auto with_reset = render_plot_svg(page_of(stops_session(), 3'000, 8'000));
  EXPECT_NE(with_reset.find(fmt::format("<line x1=\"{:.1f}\" y1=\"71.0\"", 150 + 945.0 / 5)), std::string::npos)
      << with_reset;
  EXPECT_NE(with_reset.find(">reset by the supervisor<"), std::string::npos);
}

TEST(PlotRange, NothingIsDrawnPastTheLastTick) {
  const auto svg = render_plot_svg(page_of(stops_session(), 0, 20'000));
  const auto got = bands(svg);
  ASSERT_FALSE(got.empty());
  EXPECT_NEAR(std::get<1>(got.back()), 150 + 945.0 / 2, 0.06) << "the last tick is at 10 s, half the page";
}

TEST(PlotRange, AStopLabelThatDoesNotFitItsBandIsLeftOff) {
  // The whole 10 s: the operator's stop lasts 40 ms (3.8 px), no room for a word; the supervisor's 1.96 s has.
  const auto svg = render_plot_svg(page_of(stops_session(), 0, -1));
  // (The band's labels are white; the legend's are not.)
  EXPECT_EQ(svg.find("fill=\"white\">stopped by the operator<"), std::string::npos) << svg;
  EXPECT_EQ(svg.find("fill=\"white\">operator<"), std::string::npos) << svg;
  EXPECT_NE(svg.find("fill=\"white\">stopped by the supervisor<"), std::string::npos) << svg;
  // The band still says it: its colour (named in the legend) and its tooltip.
  EXPECT_NE(svg.find("fill=\"#e57373\"><title>stopped by the operator, 2 to 2.04 s</title>"), std::string::npos);
}

TEST(PlotRange, AStopPressedAndReleasedWithinAMillisecondShowsOnItsLane) {
  const auto m = mapping::load_mapping_text("robot: HD1\ndeadman: leftshoulder\nestop: guide\n", "tap.yaml");
  LaneBuilder b(*m, false);
  for (const auto& e :
       input::parse_event_script("0 connect Pad\n5000 button guide 1\n5000 button guide 0\n", "tap.events")) {
    b.event(e);
  }
  PlotInput in = page_of(stops_session(), 0, -1);
  in.lanes = b.lanes();
  const auto stop = std::find_if(in.lanes.begin(), in.lanes.end(),
                                 [](const PlotLane& l) { return l.kind == LaneKind::kOperatorStop; });
  ASSERT_NE(stop, in.lanes.end());
  ASSERT_EQ(stop->spans.size(), 1U);
  EXPECT_EQ(stop->spans[0].from_ms, 5'000);
  EXPECT_EQ(stop->spans[0].to_ms, 5'000);
  // Drawn where it was pressed, wide enough to see, on the fourth lane (the
  // controller, the link, the deadman, the stop button).
  const auto svg = render_plot_svg(in);
  const std::regex mark(R"re(<rect x="([\d.]+)" y="182.0" width="([\d.]+)" height="9.0" fill="#e57373")re");
  std::smatch got;
  ASSERT_TRUE(std::regex_search(svg, got, mark)) << svg;
  EXPECT_NEAR(std::stod(got[1]), 150 + 945.0 / 2, 0.06);
  EXPECT_GE(std::stod(got[2]), 2.0);
}

}  // namespace
}  // namespace andros::view
