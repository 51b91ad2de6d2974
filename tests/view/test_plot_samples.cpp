// The plot of a session from its change points (view/plot.hpp): as many
// samples as records, never one a tick, and the same drive drawn.
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace andros::view
