// The plot's state band, layer strip and lanes (view/plot.hpp): each state a
// colour of its own (a stop's by whose it was), named in a legend that holds
// the colours the page uses and only those; who reset a stop, where it was
// reset; the weapons layer in the weapons red; a lane per fact the input
// gives (plot_lanes.cpp), named at its left. Labels are measured, and placed
// only where they overlap no other.
#include <array>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "plot_page.hpp"

namespace andros::view::plot_detail {
namespace {

/// A colour the page uses, and what it stands for.
struct Swatch {
  const char* name;
  const char* colour;
};

/// The operating states as the plot colours them (OpState, and a stop by whose).
constexpr std::array<Swatch, 11> kStates = {{{"no link", "#ffb74d"},
                                             {"no controller", "#fdd835"},
                                             {"not enabled", "#c9c9c9"},
                                             {"enabled", "#4caf50"},
                                             {"stopped by the operator", "#e57373"},
                                             {"stopped by the supervisor", "#d81b60"},
                                             {"stopped by the frame gate", "#880e4f"},
                                             {"stopped (whose: not recorded)", "#f06292"},
                                             {"suspended (Ctrl-Z)", "#90a4ae"},
                                             {"reloading", "#64b5f6"},
                                             {"shutting down", "#424242"}}};

std::size_t state_of(const PlotSample& p) {
  using S = run::OpState;
  switch (p.state) {
    case S::kNoLink: return 0;
    case S::kNoController: return 1;
    case S::kNotEnabled: return 2;
    case S::kEnabled: return 3;
    case S::kStopped:
      return p.stop == to_string(run::StopBy::kOperator)     ? 4
             : p.stop == to_string(run::StopBy::kSupervisor) ? 5
             : p.stop == to_string(run::StopBy::kGate)       ? 6
                                                             : 7;
    case S::kSuspended: return 8;
    case S::kReloading: return 9;
    case S::kShuttingDown: return 10;
  }
  return 2;
}

constexpr const char* kOtherLayer = "#9575cd";

/// The lanes' names and colours, by LaneKind.
constexpr std::array<Swatch, 8> kLanes = {{{"controller (operator)", "#607d8b"},
                                           {"controller (supervisor)", "#8d6e63"},
                                           {"link up", "#00897b"},
                                           {"deadman held", "#2e7d32"},
                                           {"stop button (operator)", "#e57373"},
                                           {"stop button (supervisor)", "#d81b60"},
                                           {"consent (supervisor)", "#f9a825"},
                                           {"arming input held", "#e65100"}}};

/// How wide text is at font_size px, at most, in DejaVu Sans (the page's
/// font): a narrow letter or sign (i, l, t, r, a space...) 0.42 em, a wide
/// one (m, w, M, W, &...) 1 em, a capital 0.8 em, any other 0.64 em (their
/// advance widths: 0.28 to 0.41, 0.78 to 1, at most 0.79, at most 0.64; a
/// byte outside ASCII is drawn as '?'). A narrower font in its place only
/// leaves more room.
double text_width(std::string_view text, double font_size) {
  constexpr std::string_view kNarrow = " !'(),-./:;I[\\]fijlrt|";
  constexpr std::string_view kWide = "#%&+<=>@MW^mw~";
  double em = 0;
  for (const char c : text) {
    if (kNarrow.find(c) != std::string_view::npos) em += 0.42;
    else if (kWide.find(c) != std::string_view::npos) em += 1.0;
    else if (c >= 'A' && c <= 'Z') em += 0.8;
    else em += 0.64;
  }
  return em * font_size;
}

/// A legend entry's width: the swatch, the name at 9 px, a gap.
double entry_width(std::string_view name) { return 13 + text_width(name, 9) + 14; }

/// The extents of the labels placed on one row: a label is placed only where
/// it overlaps none of them.
class LabelRow {
 public:
  /// Whether [x0, x1] is free (within the page's left and right, clear of
  /// every label placed); if so, it is taken.
  bool place(double x0, double x1) {
    if (x0 < kLeft || x1 > kRight) return false;
    for (const auto& [a, b] : taken_) {
      if (x0 < b && a < x1) return false;
    }
    taken_.emplace_back(x0, x1);
    return true;
  }

 private:
  std::vector<std::pair<double, double>> taken_;
};

constexpr double kStopFont = 9;
constexpr double kResetFont = 8;

}  // namespace

void Legend::add(std::string_view name, std::string_view colour) {
  const std::pair<std::string, std::string> entry{name, colour};
  if (std::find(entries_.begin(), entries_.end(), entry) == entries_.end()) entries_.push_back(entry);
}

void Legend::draw(Page& page) const {
  double x = kLeft;
  double y = kLegendTop;
  for (const auto& [name, colour] : entries_) {
    if (x + entry_width(name) - 14 > kRight) {
      x = kLeft;
      y += kLegendRow;
    }
    page.rect(x, y, x + 10, 9, colour);
    page.text(x + 13, y + 8, name, " font-size=\"9\"");
    x += entry_width(name);
  }
}

void draw_states(Page& page, const std::vector<const PlotSample*>& s, std::int64_t end, Legend& legend) {
  page.text(kLeft - 8, kBandTop + 14, "state", " font-size=\"11\" text-anchor=\"end\"");
  std::set<std::size_t> used;
  // Each band: its colour, what it is in a tooltip, and for a stop whose it
  // was, inside it: in full, as "supervisor" alone, or not at all when even
  // that does not fit (the colour, the legend and the tooltip still say it).
  runs(s, end, state_of, [&](const PlotSample& first, std::int64_t to, std::size_t state) {
    const std::int64_t from = std::max(first.t_ms, page.from());
    const double x0 = page.x(from);
    const double x1 = page.x(to);
    page.rect(x0, kBandTop, x1, kBandHeight, kStates[state].colour, "",
              fmt::format("{}, {} to {} s", kStates[state].name, exact_seconds(from), exact_seconds(to)));
    used.insert(state);
    if (first.stop.empty() || first.state != run::OpState::kStopped) return;
    for (const auto& label : {"stopped by the " + first.stop, first.stop}) {
      if (x0 + 2 + text_width(label, kStopFont) + 2 <= x1) {
        page.text(x0 + 2, kBandTop + 13, label, " font-size=\"9\" fill=\"white\"");
        break;
      }
    }
  });
  // Who reset a stop, where it was reset (a reset before the page's start is
  // not drawn at it): a tick, and beside it, right or else left, "reset by
  // the operator", or "reset" alone, where it overlaps no other label; the
  // tick's tooltip says it all the same.
  LabelRow resets;
  runs(
      s, end, [](const PlotSample& p) { return p.reset; },
      [&](const PlotSample& first, std::int64_t, const std::string& by) {
        // Where the reset was: the run's first sample is the page's first
        // when a sample falls on the page's start, whenever the reset was.
        const std::int64_t at = first.reset_ms >= 0 ? first.reset_ms : first.t_ms;
        if (by.empty() || at < page.from()) return;
        const double x = page.x(at);
        page.line(x, kBandTop - 3, x, kBandTop + kBandHeight, "#212121", 1.2,
                  fmt::format("reset by the {} at {} s", by, exact_seconds(at)));
        for (const auto& label : {"reset by the " + by, std::string("reset")}) {
          const double w = text_width(label, kResetFont);
          if (resets.place(x + 2, x + 2 + w)) {
            page.text(x + 2, kBandTop - 2, label, " font-size=\"8\" fill=\"#212121\"");
            return;
          }
          if (resets.place(x - 2 - w, x - 2)) {
            page.text(x - 2, kBandTop - 2, label, " font-size=\"8\" fill=\"#212121\" text-anchor=\"end\"");
            return;
          }
        }
      });
  for (const auto state : used) legend.add(kStates[state].name, kStates[state].colour);  // in the table's order
}

void draw_layers(Page& page, const std::vector<const PlotSample*>& s, std::int64_t end, const PlotInput& in,
                 Legend& legend) {
  page.text(kLeft - 8, kLayerTop + 11, "layer", " font-size=\"11\" text-anchor=\"end\"");
  page.rect(kLeft, kLayerTop, kRight, kLayerHeight, "#f4f4f4");
  bool weapons_used = false;
  bool other_used = false;
  runs(
      s, end, [](const PlotSample& p) -> const std::string& { return p.layer; },
      [&](const PlotSample& first, std::int64_t to, const std::string& layer) {
        if (layer.empty()) return;
        const bool weapons =
            std::find(in.weapon_layers.begin(), in.weapon_layers.end(), layer) != in.weapon_layers.end();
        (weapons ? weapons_used : other_used) = true;
        const double x0 = page.x(first.t_ms);
        const double x1 = page.x(to);
        page.rect(x0, kLayerTop, x1, kLayerHeight, weapons ? sheet_detail::kWeaponRed : kOtherLayer, "", layer);
        if (x0 + 3 + text_width(layer, 10) + 2 <= x1) {
          page.text(x0 + 3, kLayerTop + 11, layer, " font-size=\"10\" fill=\"white\"");
        }
      });
  if (weapons_used) legend.add("weapons layer", sheet_detail::kWeaponRed);
  if (other_used) legend.add("other layer", kOtherLayer);
  page.text(kRight, kLayerTop + 11, "(blank: base layer)", " font-size=\"9\" fill=\"#777\" text-anchor=\"end\"");
}

void draw_lanes(Page& page, const PlotInput& in, std::int64_t end) {
  if (in.lanes.empty() && !in.lanes_missing.empty()) {
    page.text(kLeft, kLanesTop + 9, "no lanes: " + in.lanes_missing, " font-size=\"10\" fill=\"#b71c1c\"");
  }
  // A press shorter than a pixel (a stop tapped between two ticks) is drawn
  // this wide, never lost.
  constexpr double kShortest = 2;
  double y = kLanesTop;
  for (const auto& lane : in.lanes) {
    const auto& swatch = kLanes[static_cast<std::size_t>(lane.kind)];
    page.text(kLeft - 8, y + 9, swatch.name, " font-size=\"9\" text-anchor=\"end\"");
    page.rect(kLeft, y + 1, kRight, kLaneHeight - 2, "#f4f4f4");
    for (const auto& span : lane.spans) {
      const std::int64_t to = span.to_ms < 0 ? end : std::min(span.to_ms, end);
      if (to < page.from() || span.from_ms > end) continue;
      const double x0 = std::min(page.x(span.from_ms), kRight - kShortest);
      page.rect(x0, y + 1, std::max(page.x(to), x0 + kShortest), kLaneHeight - 2, swatch.colour, "",
                fmt::format("{}, {} to {} s", swatch.name, exact_seconds(span.from_ms), exact_seconds(to)));
    }
    y += kLaneHeight;
  }
}

}  // namespace andros::view::plot_detail

namespace andros::view {

StateSwatch state_swatch(const PlotSample& sample) {
  const auto& s = plot_detail::kStates[plot_detail::state_of(sample)];
  return {s.name, s.colour};
}

}  // namespace andros::view
