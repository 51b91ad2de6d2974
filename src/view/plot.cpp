#include "andros/view/plot.hpp"

#include <spdlog/fmt/fmt.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "andros/protocol/signals.hpp"
#include "sheet_layout.hpp"

namespace andros::view {
namespace {

// The page, in CSS px at 96 per inch: A4 landscape.
constexpr double kWidth = 1123;
constexpr double kHeight = 794;
constexpr double kLeft = 150;  // signal names left of it
constexpr double kRight = 1095;
constexpr double kBandTop = 78;
constexpr double kBandHeight = 22;
constexpr double kLayerTop = 124;
constexpr double kLayerHeight = 16;
constexpr double kDriveTop = 162;
constexpr double kDriveHeight = 190;
constexpr double kSignalsTop = 392;
constexpr double kRowHeight = 13;
constexpr double kLastRow = 752;  // the signals' rows end above it

/// The operating states as the plot groups them.
struct Band {
  const char* name;
  const char* colour;
};
constexpr std::array<Band, 5> kBands = {{{"not enabled", "#c9c9c9"},
                                         {"enabled", "#4caf50"},
                                         {"stopped", "#e57373"},
                                         {"link down", "#ffb74d"},
                                         {"reloading", "#64b5f6"}}};

std::size_t band_of(run::OpState s) {
  using S = run::OpState;
  switch (s) {
    case S::kNoController:
    case S::kNotEnabled: return 0;
    case S::kEnabled: return 1;
    case S::kStopped:  // by the operator's stop button
    case S::kSuspended:
    case S::kStopping: return 2;
    case S::kNoLink: return 3;
    case S::kReloading: return 4;
  }
  return 0;
}

class Page {
 public:
  Page(std::int64_t from, std::int64_t to) : from_(from), to_(std::max(to, from + 1)) {}
  [[nodiscard]] double x(std::int64_t t_ms) const {
    return kLeft + (kRight - kLeft) * static_cast<double>(t_ms - from_) / static_cast<double>(to_ - from_);
  }
  void add(const std::string& element) { out_ += element; }
  void rect(double x0, double y, double x1, double h, std::string_view fill, std::string_view extra = "") {
    out_ += fmt::format("<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.2f}\" height=\"{:.1f}\" fill=\"{}\"{}/>\n", x0, y,
                        std::max(x1 - x0, 0.6), h, fill, extra);
  }
  void text(double x, double y, std::string_view text, std::string_view attrs = "") {
    out_ += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\"{}>{}</text>\n", x, y, attrs, sheet_detail::xml_escape(text));
  }
  void line(double x0, double y0, double x1, double y1, std::string_view stroke, double width = 1) {
    out_ += fmt::format(
        "<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"{}\" stroke-width=\"{}\"/>\n", x0, y0,
        x1, y1, stroke, width);
  }
  [[nodiscard]] const std::string& svg() const { return out_; }
  [[nodiscard]] std::int64_t from() const { return from_; }
  [[nodiscard]] std::int64_t to() const { return to_; }

 private:
  std::int64_t from_;
  std::int64_t to_;
  std::string out_;
};

/// Runs of equal values over the samples: calls draw(first, end_t, value) per run.
template <typename Value, typename Draw>
void runs(const std::vector<const PlotSample*>& samples, std::int64_t end_t, Value value, Draw draw) {
  for (std::size_t i = 0; i < samples.size();) {
    std::size_t j = i + 1;
    while (j < samples.size() && value(*samples[j]) == value(*samples[i])) ++j;
    draw(*samples[i], j < samples.size() ? samples[j]->t_ms : end_t, value(*samples[i]));
    i = j;
  }
}

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
    page.line(x, kBandTop, x, bottom, "#e6e6e6", 0.6);
    page.text(x, kDriveTop + kDriveHeight + 14, seconds_text(t), " font-size=\"10\" text-anchor=\"middle\"");
    page.text(x, bottom + 12, seconds_text(t), " font-size=\"10\" text-anchor=\"middle\"");
  }
  page.text(kRight, kDriveTop + kDriveHeight + 28, "time (s)", " font-size=\"10\" text-anchor=\"end\"");
}

void draw_bands(Page& page, const std::vector<const PlotSample*>& s) {
  page.text(kLeft - 8, kBandTop + 15, "state", " font-size=\"11\" text-anchor=\"end\"");
  runs(
      s, page.to(), [](const PlotSample& p) { return band_of(p.state); },
      [&](const PlotSample& first, std::int64_t end, std::size_t band) {
        page.rect(page.x(std::max(first.t_ms, page.from())), kBandTop, page.x(end), kBandHeight, kBands[band].colour);
      });
  // Who stopped, at the start of each stop.
  runs(
      s, page.to(), [](const PlotSample& p) { return p.stop; },
      [&](const PlotSample& first, std::int64_t, const std::string& by) {
        if (!by.empty())
          page.text(page.x(std::max(first.t_ms, page.from())) + 2, kBandTop + 14, "stopped by the " + by,
                    " font-size=\"9\" fill=\"white\"");
      });
  double x = kLeft;
  for (const auto& b : kBands) {  // the legend
    page.rect(x, kBandTop + kBandHeight + 6, x + 10, 10, b.colour);
    page.text(x + 14, kBandTop + kBandHeight + 15, b.name, " font-size=\"10\"");
    x += 110;
  }
}

void draw_layers(Page& page, const std::vector<const PlotSample*>& s) {
  page.text(kLeft - 8, kLayerTop + 12, "layer", " font-size=\"11\" text-anchor=\"end\"");
  page.rect(kLeft, kLayerTop, kRight, kLayerHeight, "#f4f4f4");
  runs(
      s, page.to(), [](const PlotSample& p) -> const std::string& { return p.layer; },
      [&](const PlotSample& first, std::int64_t end, const std::string& layer) {
        if (layer.empty()) return;
        const double x0 = page.x(std::max(first.t_ms, page.from()));
        const double x1 = page.x(end);
        page.rect(x0, kLayerTop, x1, kLayerHeight, "#9575cd");
        if (x1 - x0 > 7.0 * static_cast<double>(layer.size())) {
          page.text(x0 + 3, kLayerTop + 12, layer, " font-size=\"10\" fill=\"white\"");
        }
      });
  page.text(kRight, kLayerTop + 12, "(blank: base layer)", " font-size=\"9\" fill=\"#777\" text-anchor=\"end\"");
}

double value_y(int v) { return kDriveTop + kDriveHeight - kDriveHeight * v / protocol::kWholeByteMax; }

/// One byte's line: at most a min and a max point a pixel column, broken
/// where no frame was sent.
std::string trace(const Page& page, const std::vector<const PlotSample*>& s, std::size_t byte) {
  std::string paths;
  std::string current;
  int column = std::numeric_limits<int>::min();
  int lo = 0;
  int hi = 0;
  const auto flush = [&] {
    if (column == std::numeric_limits<int>::min()) return;
    current += fmt::format("{}{} {:.1f}", current.empty() ? "M" : " L", column, value_y(lo));
    if (hi != lo) current += fmt::format(" L{} {:.1f}", column, value_y(hi));
    column = std::numeric_limits<int>::min();
  };
  const auto end_path = [&] {
    flush();
    if (!current.empty()) paths += current + " ";
    current.clear();
  };
  for (const auto* p : s) {
    if (!p->sent) {
      end_path();
      continue;
    }
    const int c = static_cast<int>(std::lround(page.x(p->t_ms)));
    const int v = p->data[byte];
    if (c != column) {
      flush();
      column = c;
      lo = hi = v;
    } else {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  }
  end_path();
  return paths;
}

void draw_drive(Page& page, const std::vector<const PlotSample*>& s) {
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
                       trace(page, s, protocol::kSignals[*drive].byte)));
  page.add(fmt::format("<path d=\"{}\" fill=\"none\" stroke=\"#ff7f0e\" stroke-width=\"1.4\"/>\n",
                       trace(page, s, protocol::kSignals[*pivot].byte)));
  page.line(kRight - 170, kDriveTop - 8, kRight - 150, kDriveTop - 8, "#1f77b4", 2);
  page.text(kRight - 146, kDriveTop - 4, "drive", " font-size=\"10\"");
  page.line(kRight - 90, kDriveTop - 8, kRight - 70, kDriveTop - 8, "#ff7f0e", 2);
  page.text(kRight - 66, kDriveTop - 4, "pivot", " font-size=\"10\"");
  page.text(kLeft, kDriveTop - 4, "frames sent (gaps: none sent); 128 is centre", " font-size=\"10\" fill=\"#555\"");
}

void draw_signals(Page& page, const std::vector<const PlotSample*>& s, const std::vector<std::size_t>& on) {
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
              weapon ? " font-size=\"10\" text-anchor=\"end\" fill=\"#c62828\" font-weight=\"bold\""
                     : " font-size=\"10\" text-anchor=\"end\"");
    const char* colour = weapon ? "#d32f2f" : sig.kind == protocol::SignalKind::kSelector ? "#90a4ae" : "#37474f";
    runs(
        s, page.to(), [&sig](const PlotSample& p) { return p.sent && (p.data[sig.byte] >> sig.bit & 1) != 0; },
        [&](const PlotSample& first, std::int64_t end, bool bit) {
          if (bit) page.rect(page.x(std::max(first.t_ms, page.from())), y + 2, page.x(end), kRowHeight - 4, colour);
        });
  }
  if (shown < on.size()) {
    std::string rest;
    for (std::size_t r = shown; r < on.size(); ++r)
      rest += std::string(r == shown ? "" : ", ") + std::string(protocol::kSignals[on[r]].name);
    page.text(kLeft, kSignalsTop + kRowHeight * static_cast<double>(shown) + 10, "and " + rest, " font-size=\"10\"");
  }
}
}  // namespace

std::string render_plot_svg(const PlotInput& in) {
  const std::int64_t last = in.samples.empty() ? 0 : in.samples.back().t_ms;
  const std::int64_t to = in.to_ms < 0 ? last : in.to_ms;
  Page page(in.from_ms, to);
  std::vector<const PlotSample*> shown;
  std::int64_t ticks = 0;
  for (const auto& s : in.samples) {
    if (s.t_ms < in.from_ms || s.t_ms > to) continue;
    shown.push_back(&s);
    ticks += s.ticks;
  }
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
  draw_bands(page, shown);
  draw_layers(page, shown);
  draw_drive(page, shown);
  draw_signals(page, shown, on);
  page.add("</svg>\n");
  return page.svg();
}

}  // namespace andros::view
