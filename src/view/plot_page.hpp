#pragma once
// What the plot's parts share (view/plot.hpp): the page's layout, the SVG
// writer with its time axis, and runs of equal values over the samples.

#include <spdlog/fmt/fmt.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "andros/base/sink_text.hpp"
#include "andros/protocol/signals.hpp"
#include "andros/timing/rate.hpp"
#include "andros/view/plot.hpp"
#include "sheet_layout.hpp"

namespace andros::view::plot_detail {

// The page, in CSS px at 96 per inch: A4 landscape.
inline constexpr double kWidth = 1123;
inline constexpr double kHeight = 794;
inline constexpr double kLeft = 150;  // signal names left of it
inline constexpr double kRight = 1095;
inline constexpr double kBandTop = 74;
inline constexpr double kBandHeight = 20;
inline constexpr double kLegendTop = 98;  // two rows of the state band's legend
inline constexpr double kLegendRow = 13;
inline constexpr double kLayerTop = 128;
inline constexpr double kLayerHeight = 14;
inline constexpr double kLanesTop = 148;
inline constexpr double kLaneHeight = 11;
inline constexpr double kDriveTop = 256;  // below the most lanes there can be (8)
inline constexpr double kDriveHeight = 150;
inline constexpr double kSignalsTop = 462;
inline constexpr double kRowHeight = 13;
inline constexpr double kLastRow = 752;  // the signals' rows end above it

/// The y of a byte's value (0..255) in the drive box.
inline double value_y(int v) { return kDriveTop + kDriveHeight - kDriveHeight * v / protocol::kWholeByteMax; }

/// Where a time falls on the page, and the page's SVG as it is written.
/// Drawn between left and right (the page's own by default; a test draws
/// the lines at other widths).
class Page {
 public:
  Page(std::int64_t from, std::int64_t to, double left = kLeft, double right = kRight)
      : from_(from), to_(std::max(to, from + 1)), left_(left), right_(right) {}
  [[nodiscard]] double x(std::int64_t t_ms) const {
    const auto t = std::clamp(t_ms, from_, to_);
    return left_ + (right_ - left_) * static_cast<double>(t - from_) / static_cast<double>(to_ - from_);
  }
  void add(const std::string& element) { out_ += element; }
  /// title: the tooltip a browser shows over it ("": none).
  void rect(double x0, double y, double x1, double h, std::string_view fill, std::string_view extra = "",
            std::string_view title = "") {
    out_ += fmt::format("<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.2f}\" height=\"{:.1f}\" fill=\"{}\"{}", x0, y,
                        std::max(x1 - x0, 0.6), h, fill, extra);
    close(title, "rect");
  }
  void text(double x, double y, std::string_view text, std::string_view attrs = "") {
    out_ += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\"{}>{}</text>\n", x, y, attrs, svg_text(text));
  }
  void line(double x0, double y0, double x1, double y1, std::string_view stroke, double width = 1,
            std::string_view title = "") {
    out_ +=
        fmt::format("<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"{}\" stroke-width=\"{}\"",
                    x0, y0, x1, y1, stroke, width);
    close(title, "line");
  }
  [[nodiscard]] const std::string& svg() const { return out_; }
  [[nodiscard]] std::int64_t from() const { return from_; }
  [[nodiscard]] std::int64_t to() const { return to_; }

 private:
  void close(std::string_view title, std::string_view element) {
    if (title.empty()) out_ += "/>\n";
    else out_ += fmt::format("><title>{}</title></{}>\n", svg_text(title), element);
  }

  std::int64_t from_;
  std::int64_t to_;
  double left_;
  double right_;
  std::string out_;
};

/// The samples the page draws: those from its start to its end, after the
/// one in effect at its start when that began before it (its run is drawn
/// from the left edge: a range starts at the time asked).
std::vector<const PlotSample*> window(const std::vector<PlotSample>& samples, const Page& page);

/// A time as the page's tooltips say it: seconds, to the millisecond, no trailing zeros.
std::string exact_seconds(std::int64_t t_ms);

/// The first tick at or after t_ms.
std::int64_t tick_at_or_after(const timing::FrameClock& clock, std::int64_t t_ms);

/// Runs of equal values over the samples: calls draw(first, end_t, value) per
/// run, end_t the next run's start, or end_t after the last.
template <typename Value, typename Draw>
void runs(const std::vector<const PlotSample*>& samples, std::int64_t end_t, Value value, Draw draw) {
  for (std::size_t i = 0; i < samples.size();) {
    std::size_t j = i + 1;
    while (j < samples.size() && value(*samples[j]) == value(*samples[i])) ++j;
    draw(*samples[i], j < samples.size() ? samples[j]->t_ms : end_t, value(*samples[i]));
    i = j;
  }
}

/// The colours the state band and the layer strip use, each once, named
/// under the band: what the page shows, and only that.
class Legend {
 public:
  void add(std::string_view name, std::string_view colour);
  void draw(Page& page) const;

 private:
  std::vector<std::pair<std::string, std::string>> entries_;
};

/// The operating state band, who stopped and reset; the layer strip; the
/// lanes. Each from the samples' first time (the first may be before the
/// page's: it is drawn from the left edge) to end (the last sample's time,
/// or the page's end when it was in effect there).
void draw_states(Page& page, const std::vector<const PlotSample*>& samples, std::int64_t end, Legend& legend);
void draw_layers(Page& page, const std::vector<const PlotSample*>& samples, std::int64_t end, const PlotInput& in,
                 Legend& legend);
void draw_lanes(Page& page, const PlotInput& in, std::int64_t end);

/// One byte's line over the samples (plot_trace.cpp): SVG path data, each
/// frame sent holding its value until the next tick's (a step), broken where
/// none was sent, the last to end.
std::string trace(const Page& page, const std::vector<const PlotSample*>& samples, std::int64_t end, std::size_t byte);

}  // namespace andros::view::plot_detail
