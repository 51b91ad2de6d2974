// The plot's samples (andros/view/plot.hpp): a replay's report a tick, or a
// session's records: one at each change point (a frame record, a state or
// layer change or a stop record inside one), one at the last tick each holds
// to, and one, sending nothing, where the loop skipped ticks (a stall); never
// one a tick, so that the work is the records', whatever the session's length.
#include <algorithm>
#include <vector>

#include "andros/timing/rate.hpp"
#include "andros/view/plot.hpp"
#include "plot_page.hpp"

namespace andros::view {

std::int64_t plot_detail::tick_at_or_after(const timing::FrameClock& clock, std::int64_t t_ms) {
  std::int64_t k = t_ms * clock.rate_millihertz() / (kMsPerSecond * timing::kMillihertzPerHz);
  while (k > 0 && clock.time_of(k - 1) >= t_ms) --k;
  while (clock.time_of(k) < t_ms) ++k;
  return k;
}

namespace {
using plot_detail::tick_at_or_after;

/// Who stopped, as the plot labels it.
std::string stopper(std::optional<run::StopBy> by) { return by ? std::string(run::to_string(*by)) : std::string(); }

}  // namespace

PlotSample plot_sample(const run::TickReport& r) {
  return PlotSample{r.t_ms,
                    r.data,
                    r.sent && r.result == link::SendResult::kSent,
                    r.state,
                    r.engine.layer,
                    stopper(r.stopped_by),
                    stopper(r.reset_by)};
}

std::vector<PlotSample> plot_samples(const record::Session& session) {
  std::vector<PlotSample> out;
  const timing::FrameClock clock(session.settings.rate_millihertz);
  const auto& frames = session.frames;
  const std::int64_t last = session.end ? session.end->last_tick : (frames.empty() ? -1 : frames.back().tick);
  std::size_t state_at = 0;
  std::size_t layer_at = 0;
  std::size_t stop_at = 0;
  run::OpState state = run::OpState::kNoLink;
  std::string layer;
  std::optional<run::StopBy> stop;
  std::optional<run::StopBy> reset;  // who reset the last stop: until the next stop or enabled (TickReport's)
  // The state, layer and stop in effect at tick's time.
  const auto catch_up = [&](std::int64_t t) {
    for (; state_at < session.states.size() && session.states[state_at].t_ms <= t; ++state_at) {
      state = session.states[state_at].state;
      if (state == run::OpState::kEnabled) reset.reset();
    }
    while (layer_at < session.layers.size() && session.layers[layer_at].t_ms <= t)
      layer = session.layers[layer_at++].text;
    for (; stop_at < session.stops.size() && session.stops[stop_at].t_ms <= t; ++stop_at) {
      const auto& r = session.stops[stop_at];
      if (r.again) continue;  // pressed again while stopped: whose the stop is did not change
      stop = r.reset ? std::nullopt : std::optional(r.by);
      reset = r.reset ? std::optional(r.by) : std::nullopt;
    }
  };
  const auto sample = [&](const record::FrameRecord& f, std::int64_t tick, std::int64_t ticks) {
    const std::int64_t t = clock.time_of(tick);
    catch_up(t);
    out.push_back(PlotSample{t, f.data, f.offered && f.result == link::SendResult::kSent, state, layer, stopper(stop),
                             stopper(reset), ticks});
  };
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const auto& f = frames[i];
    const std::int64_t through = i + 1 < frames.size() ? frames[i + 1].tick - frames[i + 1].gap - 1 : last;
    std::int64_t from = f.tick;
    while (from <= through) {
      // To the tick before the next state or layer change inside this record, or its end.
      std::int64_t next = through + 1;
      const std::int64_t t = clock.time_of(from);
      catch_up(t);
      if (state_at < session.states.size())
        next = std::min(next, tick_at_or_after(clock, session.states[state_at].t_ms));
      if (layer_at < session.layers.size())
        next = std::min(next, tick_at_or_after(clock, session.layers[layer_at].t_ms));
      if (stop_at < session.stops.size()) next = std::min(next, tick_at_or_after(clock, session.stops[stop_at].t_ms));
      next = std::max(next, from + 1);
      sample(f, from, next - from == 1 ? 1 : next - from - 1);
      if (next - from > 1) sample(f, next - 1, 1);  // where it holds to: a step, not a slope
      from = next;
    }
    if (i + 1 < frames.size() && frames[i + 1].gap > 0) {
      // The ticks the loop did not run: nothing went out, the line breaks.
      const std::int64_t t = clock.time_of(through + 1);
      catch_up(t);
      out.push_back(PlotSample{t, {}, false, state, layer, stopper(stop), stopper(reset), 0});
    }
  }
  return out;
}

}  // namespace andros::view
