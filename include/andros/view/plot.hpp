#pragma once
/// The plot of a drive (docs/recording.md): drive and pivot over time, the
/// operating state as coloured bands, the active layer, and a timeline of
/// every switch signal that was on (weapons in red), on one A4 landscape SVG
/// page. Made from a recorded session, or from a replay's reports.

#include <cstdint>
#include <string>
#include <vector>

#include "andros/protocol/frame.hpp"
#include "andros/record/session.hpp"
#include "andros/run/bridge.hpp"

namespace andros::view {

/// One tick of the loop, or, from a session, the first of a run of ticks
/// that repeat it.
struct PlotSample {
  std::int64_t t_ms = 0;
  protocol::DataBytes data{};
  bool sent = false;  ///< the link took the frame
  run::OpState state = run::OpState::kNoLink;
  std::string layer;       ///< "" for the base layer
  std::string stop;        ///< a stop latched: whose ("operator", "supervisor", "frame gate"); "" when none
  std::int64_t ticks = 1;  ///< the ticks it stands for: itself and those after it that repeat it
};

struct PlotInput {
  std::string title;     ///< robot and mapping
  std::string settings;  ///< rate, code, weapons, input
  std::string source;    ///< where it came from: a session (when, where, by which version), a replayed script
  std::vector<PlotSample> samples;  ///< in time order
  std::int64_t from_ms = 0;
  std::int64_t to_ms = -1;  ///< -1: to the last sample
};

/// A replay's report as a sample.
PlotSample plot_sample(const run::TickReport& report);

/// The ticks the live loop ran, from the session's records: a sample at each
/// change point and at the last tick each holds to (work and memory as the
/// records', not the ticks').
std::vector<PlotSample> plot_samples(const record::Session& session);

/// The page: 297 x 210 mm.
std::string render_plot_svg(const PlotInput& input);

}  // namespace andros::view
