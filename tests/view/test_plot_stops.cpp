// Who stopped, where it is said outside the screen: the plot labels each stop
// with whose it was (from a replay's reports and from a session's records),
// and the service's STATUS= line carries the state's words.
#include <gtest/gtest.h>

#include "andros/view/plot.hpp"
#include "andros/view/status_board.hpp"
#include "cli/run_service.hpp"

namespace andros::view {
namespace {

/// A session at 25 Hz: enabled, stopped by the operator at 40 ms, reset at
/// 120 ms and not enabled from then to its end at last_tick.
record::Session stopped_and_reset(std::int64_t last_tick) {
  record::Session s;
  s.settings.rate_millihertz = 25'000;
  s.states = {{0, run::OpState::kEnabled}, {40, run::OpState::kStopped}, {120, run::OpState::kNotEnabled}};
  s.stops = {{.t_ms = 40, .reset = false, .by = run::StopBy::kOperator, .name = "Pad A"},
             {.t_ms = 120, .reset = true, .by = run::StopBy::kOperator, .name = ""}};
  s.end.emplace();
  s.end->t_ms = last_tick * 40;
  s.end->last_tick = last_tick;
  return s;
}

TEST(PlotStops, EachStopIsLabelledWithWhoseItWas) {
  run::TickReport r;
  r.state = run::OpState::kEnabled;
  PlotInput in;
  in.samples.push_back(plot_sample(r));
  r.t_ms = 40;
  r.state = run::OpState::kStopped;
  r.stopped_by = run::StopBy::kSupervisor;
  in.samples.push_back(plot_sample(r));
  r.t_ms = 80;
  in.samples.push_back(plot_sample(r));
  const auto svg = render_plot_svg(in);
  EXPECT_NE(svg.find(">stopped by the supervisor<"), std::string::npos) << svg;
  EXPECT_EQ(svg.find("stopped by the operator"), std::string::npos);

  // From a session: the stop record names whose, the reset ends it.
  record::Session s = stopped_and_reset(4);
  s.frames.emplace_back();  // tick 0, repeated to the end
  const auto samples = plot_samples(s);
  ASSERT_EQ(samples.size(), 5U);
  EXPECT_EQ(samples[0].stop, "");
  EXPECT_EQ(samples[1].stop, "operator");
  EXPECT_EQ(samples[2].stop, "operator");
  EXPECT_EQ(samples[3].stop, "");
}

// A reset is drawn where it happened, and not at all on a page that begins
// after it, even when the page's first instant is a tick and the reset still
// stands there (nothing enabled between): under load, a run put the reset
// close before such a page, and the page drew a reset at its left edge.
TEST(PlotStops, AResetBeforeThePageIsNotDrawnAtItsStart) {
  record::Session s = stopped_and_reset(10);
  for (std::int64_t tick = 0; tick <= 10; ++tick) {  // a frame of its own every tick: a sample at each
    s.frames.push_back({.tick = tick, .t_ms = tick * 40, .data = {static_cast<std::uint8_t>(tick)}});
  }
  for (const std::int64_t from : {160, 200}) {
    PlotInput in;
    in.rate_millihertz = s.settings.rate_millihertz;
    in.from_ms = from;
    in.to_ms = 400;
    in.samples = plot_samples(s, PlotAxis{.from_ms = in.from_ms, .to_ms = in.to_ms});
    EXPECT_EQ(render_plot_svg(in).find("reset by the"), std::string::npos) << "from " << from << " ms";
  }
  for (const std::int64_t from : {0, 80, 120}) {
    PlotInput in;
    in.rate_millihertz = s.settings.rate_millihertz;
    in.from_ms = from;
    in.to_ms = 400;
    in.samples = plot_samples(s, PlotAxis{.from_ms = in.from_ms, .to_ms = in.to_ms});
    EXPECT_NE(render_plot_svg(in).find("reset by the operator at 0.12 s"), std::string::npos)
        << "from " << from << " ms";
  }
}

TEST(ServiceStatus, SaysWhoStoppedAndWhoReset) {
  RunStatus s;
  s.robot = "HD1";
  s.state = run::OpState::kStopped;
  s.enable_text = "stopped by the supervisor (Pad B): to reset, release the deadman and hold back+start 2 s";
  EXPECT_NE(cli::service_status_line(s).find("HD1; stopped: stopped by the supervisor (Pad B): to reset"),
            std::string::npos)
      << cli::service_status_line(s);
  s.state = run::OpState::kNotEnabled;
  s.enable_text = "stop reset by the operator: press the deadman afresh";
  EXPECT_NE(cli::service_status_line(s).find("not enabled: stop reset by the operator: press the deadman afresh"),
            std::string::npos);
}

}  // namespace
}  // namespace andros::view
