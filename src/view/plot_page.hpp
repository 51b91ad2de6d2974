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

class Page {
 public:
  Page(std::int64_t from, std::int64_t to) : from_(from), to_(std::max(to, from + 1)) {}
  [[nodiscard]] double x(std::int64_t t_ms) const {
    const auto t = std::clamp(t_ms, from_, to_);
    return kLeft + (kRight - kLeft) * static_cast<double>(t - from_) / static_cast<double>(to_ - from_);
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

/// The colours the state band and the layer strip use, each once, named
/// under the band: what the page shows, and only that.
class Legend {
 public:
  void add(std::string_view name, std::string_view colour);
  void draw(Page& page) const;

 private:
  std::vector<std::pair<std::string, std::string>> entries_;
};

/// The operating state band, who stopped and reset; the layer strip; the lanes.
void draw_states(Page& page, const std::vector<const PlotSample*>& samples, Legend& legend);
void draw_layers(Page& page, const std::vector<const PlotSample*>& samples, const PlotInput& in, Legend& legend);
void draw_lanes(Page& page, const PlotInput& in);

}  // namespace andros::view::plot_detail
