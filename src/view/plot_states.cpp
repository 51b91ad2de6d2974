// The plot's state band, layer strip and lanes (view/plot.hpp): each state a
// colour of its own (a stop's by whose it was), named in a legend that holds
// the colours the page uses and only those; who reset a stop, where it was
// reset; the weapons layer in the weapons red; a lane per fact the input
// gives (plot_lanes.cpp), named at its left.
#include <array>
#include <set>

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
    case S::kStopping: return 10;
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

/// A legend entry's width: the swatch, the name at 9 px, a gap.
double entry_width(std::string_view name) { return 13 + 5.4 * static_cast<double>(name.size()) + 14; }

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

void draw_states(Page& page, const std::vector<const PlotSample*>& s, Legend& legend) {
  page.text(kLeft - 8, kBandTop + 14, "state", " font-size=\"11\" text-anchor=\"end\"");
  std::set<std::size_t> used;
  runs(s, page.to(), state_of, [&](const PlotSample& first, std::int64_t end, std::size_t state) {
    page.rect(page.x(first.t_ms), kBandTop, page.x(end), kBandHeight, kStates[state].colour);
    used.insert(state);
  });
  // Who stopped, at the start of each stop; who reset it, where it was reset.
  runs(
      s, page.to(), [](const PlotSample& p) { return p.stop; },
      [&](const PlotSample& first, std::int64_t, const std::string& by) {
        if (!by.empty())
          page.text(page.x(first.t_ms) + 2, kBandTop + 13, "stopped by the " + by, " font-size=\"9\" fill=\"white\"");
      });
  runs(
      s, page.to(), [](const PlotSample& p) { return p.reset; },
      [&](const PlotSample& first, std::int64_t, const std::string& by) {
        if (by.empty()) return;
        const double x = page.x(first.t_ms);
        page.line(x, kBandTop - 3, x, kBandTop + kBandHeight, "#212121", 1.2);
        const bool near_the_end = x > kRight - 100;  // the label ends at the tick, not past the page
        page.text(near_the_end ? x - 2 : x + 2, kBandTop - 2, "reset by the " + by,
                  near_the_end ? " font-size=\"8\" fill=\"#212121\" text-anchor=\"end\""
                               : " font-size=\"8\" fill=\"#212121\"");
      });
  for (const auto state : used) legend.add(kStates[state].name, kStates[state].colour);  // in the table's order
}

void draw_layers(Page& page, const std::vector<const PlotSample*>& s, const PlotInput& in, Legend& legend) {
  page.text(kLeft - 8, kLayerTop + 11, "layer", " font-size=\"11\" text-anchor=\"end\"");
  page.rect(kLeft, kLayerTop, kRight, kLayerHeight, "#f4f4f4");
  bool weapons_used = false;
  bool other_used = false;
  runs(
      s, page.to(), [](const PlotSample& p) -> const std::string& { return p.layer; },
      [&](const PlotSample& first, std::int64_t end, const std::string& layer) {
        if (layer.empty()) return;
        const bool weapons =
            std::find(in.weapon_layers.begin(), in.weapon_layers.end(), layer) != in.weapon_layers.end();
        (weapons ? weapons_used : other_used) = true;
        const double x0 = page.x(first.t_ms);
        const double x1 = page.x(end);
        page.rect(x0, kLayerTop, x1, kLayerHeight, weapons ? sheet_detail::kWeaponRed : kOtherLayer);
        if (x1 - x0 > 7.0 * static_cast<double>(layer.size())) {
          page.text(x0 + 3, kLayerTop + 11, layer, " font-size=\"10\" fill=\"white\"");
        }
      });
  if (weapons_used) legend.add("weapons layer", sheet_detail::kWeaponRed);
  if (other_used) legend.add("other layer", kOtherLayer);
  page.text(kRight, kLayerTop + 11, "(blank: base layer)", " font-size=\"9\" fill=\"#777\" text-anchor=\"end\"");
}

void draw_lanes(Page& page, const PlotInput& in) {
  if (in.lanes.empty() && !in.lanes_missing.empty()) {
    page.text(kLeft, kLanesTop + 9, "no lanes: " + in.lanes_missing, " font-size=\"10\" fill=\"#b71c1c\"");
  }
  double y = kLanesTop;
  for (const auto& lane : in.lanes) {
    const auto& swatch = kLanes[static_cast<std::size_t>(lane.kind)];
    page.text(kLeft - 8, y + 9, swatch.name, " font-size=\"9\" text-anchor=\"end\"");
    page.rect(kLeft, y + 1, kRight, kLaneHeight - 2, "#f4f4f4");
    for (const auto& span : lane.spans) {
      const std::int64_t to = span.to_ms < 0 ? page.to() : span.to_ms;
      if (to < page.from() || span.from_ms > page.to()) continue;
      page.rect(page.x(span.from_ms), y + 1, page.x(to), kLaneHeight - 2, swatch.colour);
    }
    y += kLaneHeight;
  }
}

}  // namespace andros::view::plot_detail
