// The plot of a session from its change points (view/plot.hpp): as many
// samples as records, never one a tick, and the same drive drawn.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "andros/view/plot.hpp"

namespace andros::view {
namespace {

record::Session quiet_hour() {
  record::Session s;
  s.settings.rate_millihertz = 25'000;
  protocol::DataBytes moving{};
  moving[7] = 0xFF;
  s.frames = {record::FrameRecord{.tick = 0, .t_ms = 0},
              record::FrameRecord{.tick = 50'000, .t_ms = 2'000'000, .data = moving},
              record::FrameRecord{.tick = 50'001, .t_ms = 2'000'040}};
  s.states = {{0, run::OpState::kNotEnabled}, {1'000'000, run::OpState::kEnabled}};
  s.end = record::EndRecord{.t_ms = 3'600'000, .last_tick = 90'000, .frames_sent = 90'001, .why = "SIGINT"};
  return s;
}

TEST(PlotSamples, ASessionIsDrawnFromItsChangePointsNotATick) {
  const auto samples = plot_samples(quiet_hour());
  EXPECT_LE(samples.size(), 8u);
  const auto ticks = std::accumulate(samples.begin(), samples.end(), std::int64_t{0},
                                     [](std::int64_t n, const PlotSample& p) { return n + p.ticks; });
  EXPECT_EQ(ticks, 90'001);  // every tick stood for, once
  for (std::size_t i = 1; i < samples.size(); ++i) EXPECT_LT(samples[i - 1].t_ms, samples[i].t_ms);
  // The state changes where it was recorded, and each record holds to its last tick: a step.
  for (const auto& p : samples) {
    EXPECT_EQ(p.state, p.t_ms < 1'000'000 ? run::OpState::kNotEnabled : run::OpState::kEnabled) << p.t_ms;
    EXPECT_EQ(p.data[7], p.t_ms == 2'000'000 ? 0xFF : 0) << p.t_ms;
  }
  EXPECT_EQ(samples.back().t_ms, 3'600'000);
  EXPECT_TRUE(std::any_of(samples.begin(), samples.end(), [](const PlotSample& p) { return p.t_ms == 1'999'960; }));
}

/// Two hours of a stick moving on every tick, a signal bit blinking at
/// 1 Hz, a state change every 10 minutes, a stop and a stall: a frame
/// record a tick (180,000 of them).
record::Session busy_two_hours() {
  record::Session s;
  s.settings.rate_millihertz = 25'000;
  constexpr std::int64_t kTicks = 180'000;
  for (std::int64_t k = 0; k < kTicks; ++k) {
    if (k == 90'000) continue;  // a stall: tick 90,000 not run
    protocol::DataBytes d{};
    d[7] = static_cast<std::uint8_t>(128 + (k * 37 % 127));  // drive
    d[8] = static_cast<std::uint8_t>(k % 256);               // pivot, a ramp
    d[2] = static_cast<std::uint8_t>(k / 25 % 2);            // a bit, a second on, a second off
    s.frames.push_back(record::FrameRecord{.tick = k, .t_ms = k * 40, .data = d, .gap = k == 90'001 ? 1 : 0});
  }
  for (std::int64_t t = 0; t < kTicks * 40; t += 600'000) {
    s.states.push_back({t, run::OpState::kNotEnabled});
    s.states.push_back({t + 300'000, run::OpState::kEnabled});
  }
  s.stops.push_back(record::StopRecord{.t_ms = 4'000'000, .by = run::StopBy::kOperator, .name = "pad"});
  s.end = record::EndRecord{
      .t_ms = (kTicks - 1) * 40, .last_tick = kTicks - 1, .frames_sent = kTicks - 1, .why = "SIGINT", .line = 0};
  return s;
}

// Sampled to the page's width: a few samples a pixel column, not a tick, and
// the page the same to the byte as the one drawn from every sample.
TEST(PlotSamples, ALongSessionIsSampledToThePagesWidthAndDrawnTheSame) {
  const auto s = busy_two_hours();
  const auto whole = plot_samples(s);
  ASSERT_GE(whole.size(), 179'999u);
  for (const PlotAxis axis : {PlotAxis{}, PlotAxis{1'000'000, 2'000'000}}) {
    const auto thin = plot_samples(s, axis);
    EXPECT_LT(thin.size(), 40u * 950u);
    const auto ticks = [](const std::vector<PlotSample>& v) {
      return std::accumulate(v.begin(), v.end(), std::int64_t{0},
                             [](std::int64_t n, const PlotSample& p) { return n + p.ticks; });
    };
    EXPECT_EQ(ticks(thin), ticks(whole));  // every tick stood for, once
    PlotInput a;
    a.samples = whole;
    a.from_ms = axis.from_ms;
    a.to_ms = axis.to_ms;
    PlotInput b = a;
    b.samples = thin;
    const auto whole_svg = render_plot_svg(a);
    const auto thin_svg = render_plot_svg(b);
    const auto at =
        std::mismatch(whole_svg.begin(), whole_svg.end(), thin_svg.begin(), thin_svg.end()).first - whole_svg.begin();
    const auto near = [&](const std::string& svg) {
      const auto from = static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, at - 300));
      return svg.substr(from, 600);
    };
    EXPECT_EQ(whole_svg.size(), thin_svg.size()) << axis.from_ms;
    EXPECT_EQ(near(whole_svg), near(thin_svg)) << "the pages differ at byte " << at << ", from " << axis.from_ms;
  }
}

}  // namespace
}  // namespace andros::view
