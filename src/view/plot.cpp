#include "andros/view/plot.hpp"

#include <spdlog/fmt/fmt.h>

#include <algorithm>

#include "andros/protocol/signals.hpp"
#include "plot_page.hpp"

namespace andros::view {
namespace {

using namespace plot_detail;

/// A step in seconds for about 10..20 marks over span_ms.
std::int64_t time_step_ms(std::int64_t span_ms) {
  for (const std::int64_t s : {100, 200, 500, 1000, 2000, 5000, 10000, 15000, 30000, 60000, 120000, 300000, 600000,
                               900000, 1800000, 3600000}) {
    if (span_ms / s <= 20) return s;
  }
  return 7200000;
}

std::string seconds_text(std::int64_t ms) {
  return ms % 1000 == 0 ? fmt::format("{}", ms / 1000) : fmt::format("{:.1f}", static_cast<double>(ms) / 1000.0);
}

/// The signals that were on at some sample, in frame order.
std::vector<std::size_t> signals_on(const std::vector<const PlotSample*>& s) {
  std::vector<std::size_t> on;
  for (std::size_t i = 0; i < protocol::kSignals.size(); ++i) {
    const auto& sig = protocol::kSignals[i];
    if (!sig.is_bit()) continue;
    const bool seen = std::any_of(
        s.begin(), s.end(), [&sig](const PlotSample* p) { return p->sent && (p->data[sig.byte] >> sig.bit & 1) != 0; });
    if (seen) on.push_back(i);
  }
  return on;
}

/// Rows of signals that fit; the last says how many more when they do not all fit.
std::size_t signal_rows(std::size_t on) {
  const auto fit = static_cast<std::size_t>((kLastRow - kSignalsTop) / kRowHeight);
  return std::min(on, fit);
}

void draw_time_grid(Page& page, double bottom) {
  const std::int64_t step = time_step_ms(page.to() - page.from());
  for (std::int64_t t = (page.from() + step - 1) / step * step; t <= page.to(); t += step) {
    const double x = page.x(t);
    page.line(x, kBandTop, x, kBandTop + kBandHeight, "#e6e6e6", 0.6);  // not across the legend
    page.line(x, kLayerTop, x, bottom, "#e6e6e6", 0.6);
    page.text(x, kDriveTop + kDriveHeight + 14, seconds_text(t), " font-size=\"10\" text-anchor=\"middle\"");
    page.text(x, bottom + 12, seconds_text(t), " font-size=\"10\" text-anchor=\"middle\"");
  }
  page.text(kRight, kDriveTop + kDriveHeight + 28, "time (s)", " font-size=\"10\" text-anchor=\"end\"");
}

void draw_drive(Page& page, const std::vector<const PlotSample*>& s, std::int64_t end) {
  page.rect(kLeft, kDriveTop, kRight, kDriveHeight, "none", " stroke=\"#999\" stroke-width=\"0.8\"");
  constexpr int kCentre = protocol::kNeutralCentre;
  for (const int v : {0, 64, kCentre, 192, protocol::kWholeByteMax}) {
    page.line(kLeft, value_y(v), kRight, value_y(v), v == kCentre ? "#999" : "#e6e6e6", v == kCentre ? 0.8 : 0.6);
    page.text(kLeft - 6, value_y(v) + 4, std::to_string(v), " font-size=\"10\" text-anchor=\"end\"");
  }
  page.text(kLeft - 40, kDriveTop + kDriveHeight / 2, "drive / pivot",
            fmt::format(" font-size=\"11\" text-anchor=\"middle\" transform=\"rotate(-90 {} {})\"", kLeft - 40,
                        kDriveTop + kDriveHeight / 2));
  const auto drive = protocol::find_signal("drive");
  const auto pivot = protocol::find_signal("pivot");
  page.add(fmt::format("<path d=\"{}\" fill=\"none\" stroke=\"#1f77b4\" stroke-width=\"1.4\"/>\n",
                       trace(page, s, end, protocol::kSignals[*drive].byte)));
  page.add(fmt::format("<path d=\"{}\" fill=\"none\" stroke=\"#ff7f0e\" stroke-width=\"1.4\"/>\n",
                       trace(page, s, end, protocol::kSignals[*pivot].byte)));
  page.line(kRight - 170, kDriveTop - 8, kRight - 150, kDriveTop - 8, "#1f77b4", 2);
  page.text(kRight - 146, kDriveTop - 4, "drive", " font-size=\"10\"");
  page.line(kRight - 90, kDriveTop - 8, kRight - 70, kDriveTop - 8, "#ff7f0e", 2);
  page.text(kRight - 66, kDriveTop - 4, "pivot", " font-size=\"10\"");
  page.text(kLeft, kDriveTop - 4, "frames sent, each held until the next (gaps: none sent); 128 is centre",
            " font-size=\"10\" fill=\"#555\"");
}

void draw_signals(Page& page, const std::vector<const PlotSample*>& s, std::int64_t end,
                  const std::vector<std::size_t>& on) {
  page.text(kLeft, kSignalsTop - 8,
            on.empty() ? "switch signals: none was on" : "switch signals that were on (weapons in red)",
            " font-size=\"11\"");
  const std::size_t rows = signal_rows(on.size());
  const std::size_t shown = on.size() > rows ? rows - 1 : on.size();
  for (std::size_t r = 0; r < shown; ++r) {
    const auto& sig = protocol::kSignals[on[r]];
    const double y = kSignalsTop + kRowHeight * static_cast<double>(r);
    const bool weapon = sig.kind == protocol::SignalKind::kWeapon;
    if (r % 2 == 0) page.rect(kLeft, y, kRight, kRowHeight, "#fafafa");
    page.text(kLeft - 8, y + 10, sig.name,
              weapon ? fmt::format(" font-size=\"10\" text-anchor=\"end\" fill=\"{}\" font-weight=\"bold\"",
                                   sheet_detail::kWeaponRed)
                     : std::string(" font-size=\"10\" text-anchor=\"end\""));
    const std::string_view colour = weapon                                        ? sheet_detail::kWeaponRed
                                    : sig.kind == protocol::SignalKind::kSelector ? "#90a4ae"
                                                                                  : "#37474f";
    runs(
        s, end, [&sig](const PlotSample& p) { return p.sent && (p.data[sig.byte] >> sig.bit & 1) != 0; },
        [&](const PlotSample& first, std::int64_t to, bool bit) {
          if (bit) page.rect(page.x(first.t_ms), y + 2, page.x(to), kRowHeight - 4, colour);
        });
  }
  if (shown < on.size()) {
    std::string rest;
    for (std::size_t r = shown; r < on.size(); ++r)
      rest += std::string(r == shown ? "" : ", ") + std::string(protocol::kSignals[on[r]].name);
    page.text(kLeft, kSignalsTop + kRowHeight * static_cast<double>(shown) + 10, "and " + rest, " font-size=\"10\"");
  }
}

/// The ticks from the page's start to its end: of each sample's, those in it.
std::int64_t ticks_in(const std::vector<const PlotSample*>& shown, const Page& page, std::int64_t rate_millihertz) {
  const timing::FrameClock clock(rate_millihertz);
  const std::int64_t first = tick_at_or_after(clock, page.from());
  const std::int64_t after = tick_at_or_after(clock, page.to() + 1);
  std::int64_t n = 0;
  for (const auto* s : shown) {
    const std::int64_t k = tick_at_or_after(clock, s->t_ms);
    n += std::max<std::int64_t>(0, std::min(k + s->ticks, after) - std::max(k, first));
  }
  return n;
}
}  // namespace

std::vector<const PlotSample*> plot_detail::window(const std::vector<PlotSample>& samples, const Page& page) {
  const auto first = std::lower_bound(samples.begin(), samples.end(), page.from(),
                                      [](const PlotSample& s, std::int64_t t) { return s.t_ms < t; });
  std::vector<const PlotSample*> out;
  if (first != samples.begin() && first != samples.end() && first->t_ms > page.from()) out.push_back(&*(first - 1));
  for (auto s = first; s != samples.end() && s->t_ms <= page.to(); ++s) out.push_back(&*s);
  return out;
}

std::string plot_detail::exact_seconds(std::int64_t t_ms) {
  std::string text = fmt::format("{}.{:03}", t_ms / kMsPerSecond, t_ms % kMsPerSecond);
  text.erase(text.find_last_not_of('0') + 1);
  if (text.back() == '.') text.pop_back();
  return text;
}

std::string render_plot_svg(const PlotInput& in) {
  const std::int64_t last = in.samples.empty() ? 0 : in.samples.back().t_ms;
  const std::int64_t to = in.to_ms < 0 ? last : in.to_ms;
  Page page(in.from_ms, to);
  const auto shown = window(in.samples, page);
  const std::int64_t end = std::min(page.to(), last);  // nothing is drawn past the last tick
  const std::int64_t ticks = ticks_in(shown, page, in.rate_millihertz);
  page.add(
      fmt::format("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"297mm\" height=\"210mm\" viewBox=\"0 0 {} {}\" "
                  "font-family=\"DejaVu Sans, Arial, sans-serif\">\n",
                  kWidth, kHeight));
  page.rect(0, 0, kWidth, kHeight, "white");
  page.text(kLeft, 30, in.title, " font-size=\"17\" font-weight=\"bold\"");
  page.text(kLeft, 48, in.settings, " font-size=\"11\" fill=\"#333\"");
  page.text(kLeft, 64,
            fmt::format("{}{} to {} s, {} ticks", in.source.empty() ? "" : in.source + "; ", seconds_text(page.from()),
                        seconds_text(page.to()), ticks),
            " font-size=\"10\" fill=\"#555\"");
  const auto on = signals_on(shown);
  const double bottom =
      kSignalsTop + kRowHeight * static_cast<double>(std::max<std::size_t>(signal_rows(on.size()), 1));
  draw_time_grid(page, bottom);
  Legend legend;
  draw_states(page, shown, end, legend);
  draw_layers(page, shown, end, in, legend);
  legend.draw(page);
  draw_lanes(page, in, end);
  draw_drive(page, shown, end);
  draw_signals(page, shown, end, on);
  page.add("</svg>\n");
  return page.svg();
}

}  // namespace andros::view
