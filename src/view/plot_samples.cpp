// The plot's samples (andros/view/plot.hpp): a replay's report a tick, or a
// session's records: one at each change point (a frame record, a state or
// layer change or a stop record inside one), one at the last tick each holds
// to, and one, sending nothing, where the loop skipped ticks (a stall); never
// one a tick, so that the work is the records', whatever the session's length.
#include <algorithm>
#include <limits>
#include <vector>

#include "andros/timing/rate.hpp"
#include "andros/view/plot.hpp"
#include "plot_page.hpp"
#include "record_cursor.hpp"

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
std::string stopper(const record::StopRecord* r) { return r != nullptr ? stopper(r->by) : std::string(); }

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
  // The state, layer and stop in effect at a tick's time; who reset the last stop until the next stop or enabled.
  RecordCursor records(session);
  const auto sample = [&](const record::FrameRecord& f, std::int64_t tick, std::int64_t ticks) {
    const std::int64_t t = clock.time_of(tick);
    records.at(t);
    out.push_back(PlotSample{t, f.data, f.offered && f.result == link::SendResult::kSent, records.state, records.layer,
                             stopper(records.stop), stopper(records.reset), ticks});
  };
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const auto& f = frames[i];
    const std::int64_t through = i + 1 < frames.size() ? frames[i + 1].tick - frames[i + 1].gap - 1 : last;
    std::int64_t from = f.tick;
    while (from <= through) {
      // To the tick before the next state or layer change inside this record, or its end.
      std::int64_t next = through + 1;
      records.at(clock.time_of(from));
      if (const auto change = records.next_change(); change != std::numeric_limits<std::int64_t>::max()) {
        next = std::min(next, tick_at_or_after(clock, change));
      }
      next = std::max(next, from + 1);
      sample(f, from, next - from == 1 ? 1 : next - from - 1);
      if (next - from > 1) sample(f, next - 1, 1);  // where it holds to: a step, not a slope
      from = next;
    }
    if (i + 1 < frames.size() && frames[i + 1].gap > 0) {
      // The ticks the loop did not run: nothing went out, the line breaks.
      const std::int64_t t = clock.time_of(through + 1);
      records.at(t);
      out.push_back(
          PlotSample{t, {}, false, records.state, records.layer, stopper(records.stop), stopper(records.reset), 0});
    }
  }
  return out;
}

}  // namespace andros::view
