// The plot's samples (andros/view/plot.hpp): a replay's report a tick, or a
// session's records: one at each change point (a frame record, a state or
// layer change or a stop record inside one), one at the last tick each holds
// to, and one, sending nothing, where the loop skipped ticks (a stall); never
// one a tick, so that the work is the records', whatever the session's length.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "andros/protocol/signals.hpp"
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
std::int64_t reset_time(const record::StopRecord* r) { return r != nullptr ? r->t_ms : -1; }

}  // namespace

PlotSample plot_sample(const run::TickReport& r) {
  return PlotSample{r.t_ms, r.data, r.delivered(), r.state, r.engine.layer, stopper(r.stopped_by), stopper(r.reset_by)};
}

namespace {

/// Samples in time order, to out: those of one pixel column are held until
/// the column ends, then only those the drawing tells apart are kept
/// (plot_samples(session, axis)).
class ColumnSamples {
 public:
  ColumnSamples(std::vector<PlotSample>& out, std::optional<plot_detail::Page> page)
      : out_(out), page_(std::move(page)) {}

  void add(PlotSample s) {
    if (!page_) {
      out_.push_back(std::move(s));
      return;
    }
    // Before the axis and after it are columns of their own (the page draws
    // only the last sample before it, and none after).
    const long column = s.t_ms < page_->from() ? std::numeric_limits<long>::min() + 1
                        : s.t_ms > page_->to() ? std::numeric_limits<long>::max()
                                               : std::lround(page_->x(s.t_ms));
    if (column != column_) flush();
    column_ = column;
    held_.push_back(std::move(s));
  }

  void finish() { flush(); }

 private:
  /// The bits of the switch signals (drawn as runs), byte by byte.
  static const protocol::DataBytes& bit_mask() {
    static const protocol::DataBytes mask = [] {
      protocol::DataBytes m{};
      for (const auto& sig : protocol::kSignals) {
        if (sig.is_bit()) m[sig.byte] = static_cast<std::uint8_t>(m[sig.byte] | (1U << sig.bit));
      }
      return m;
    }();
    return mask;
  }
  /// The bytes the page traces: drive and pivot.
  static const std::array<std::size_t, 2>& traced() {
    static const std::array<std::size_t, 2> bytes{protocol::kSignals[*protocol::find_signal("drive")].byte,
                                                  protocol::kSignals[*protocol::find_signal("pivot")].byte};
    return bytes;
  }

  static bool same_band(const PlotSample& a, const PlotSample& b) {
    return a.sent == b.sent && a.state == b.state && a.layer == b.layer && a.stop == b.stop && a.reset == b.reset &&
           a.ticks != 0 && b.ticks != 0;
  }

  void flush() {
    const std::size_t n = held_.size();
    if (n == 0) return;
    std::vector<bool> keep(n, false);
    keep.front() = keep.back() = true;
    // The traced bytes (drive, pivot): the lowest and highest of each stretch
    // of one band (a trace's line breaks where nothing was sent), as the trace draws them.
    std::array<std::size_t, 2> lo{};
    std::array<std::size_t, 2> hi{};
    const auto keep_extremes = [&] {
      for (std::size_t t = 0; t < traced().size(); ++t) keep[lo[t]] = keep[hi[t]] = true;
    };
    for (std::size_t i = 1; i < n; ++i) {
      const auto& s = held_[i];
      const auto& before = held_[i - 1];
      // A change of band, or of a switch signal's bit: drawn as it is, every one.
      if (!same_band(before, s)) {
        keep[i] = true;
        keep_extremes();
        lo.fill(i);
        hi.fill(i);
      }
      for (std::size_t b = 0; b < s.data.size(); ++b) {
        if (((s.data[b] ^ before.data[b]) & bit_mask()[b]) != 0) keep[i] = true;
      }
      for (std::size_t t = 0; t < traced().size(); ++t) {
        const auto byte = traced()[t];
        if (s.data[byte] < held_[lo[t]].data[byte]) lo[t] = i;
        if (s.data[byte] > held_[hi[t]].data[byte]) hi[t] = i;
      }
    }
    keep_extremes();
    // A kept sample stands for the ticks of those dropped after it (none is a
    // break: a sample of ticks not run differs in its band, and is kept).
    PlotSample* last = nullptr;
    for (std::size_t i = 0; i < n; ++i) {
      if (keep[i]) {
        out_.push_back(std::move(held_[i]));
        last = &out_.back();
      } else if (last != nullptr) {
        last->ticks += held_[i].ticks;
      }
    }
    held_.clear();
  }

  std::vector<PlotSample>& out_;
  std::optional<plot_detail::Page> page_;
  long column_ = std::numeric_limits<long>::min();
  std::vector<PlotSample> held_;
};

std::vector<PlotSample> make_samples(const record::Session& session, const PlotAxis* axis) {
  std::vector<PlotSample> out;
  const timing::FrameClock clock(session.settings.rate_millihertz);
  const auto& frames = session.frames;
  const std::int64_t last = session.end ? session.end->last_tick : (frames.empty() ? -1 : frames.back().tick);
  // The state, layer and stop in effect at a tick's time; who reset the last stop until the next stop or enabled.
  RecordCursor records(session);
  std::optional<plot_detail::Page> page;
  if (axis != nullptr)
    page.emplace(axis->from_ms, axis->to_ms < 0 ? clock.time_of(std::max<std::int64_t>(last, 0)) : axis->to_ms);
  ColumnSamples columns(out, page);
  const auto sample = [&](const record::FrameRecord& f, std::int64_t tick, std::int64_t ticks) {
    const std::int64_t t = clock.time_of(tick);
    records.at(t);
    columns.add(PlotSample{t, f.data, f.delivered(), records.state, records.layer, stopper(records.stop),
                           stopper(records.reset), ticks, reset_time(records.reset)});
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
      columns.add(PlotSample{t,
                             {},
                             false,
                             records.state,
                             records.layer,
                             stopper(records.stop),
                             stopper(records.reset),
                             0,
                             reset_time(records.reset)});
    }
  }
  columns.finish();
  return out;
}

}  // namespace

std::vector<PlotSample> plot_samples(const record::Session& session) { return make_samples(session, nullptr); }

std::vector<PlotSample> plot_samples(const record::Session& session, const PlotAxis& axis) {
  return make_samples(session, &axis);
}

}  // namespace andros::view
