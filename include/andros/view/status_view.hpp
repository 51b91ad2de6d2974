#pragma once
/// The operator's screens, as text: what `run` shows on a terminal and what
/// `monitor` shows from the vehicle's side. Pure formatting, no I/O: each
/// screen is a function of a value it is handed (docs/architecture.md).

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "andros/link/link_status.hpp"
#include "andros/link/vehicle_snapshot.hpp"
#include "andros/mapping/model.hpp"
#include "andros/protocol/frame.hpp"
#include "andros/timing/frame_timing.hpp"

namespace andros::view {

/// The switches grouped by function, as the view lists them.
struct SignalGroup {
  std::string_view title;
  std::vector<protocol::SignalId> signals;
};
const std::vector<SignalGroup>& signal_groups();

/// Switch groups and gauges (drive, pivot, arm speed, light) for one frame;
/// the drive and pivot gauges grow from center (the mapping's rest value).
/// With ansi, active switches are shown in reverse video and idle ones dim;
/// without, active ones are upper case.
std::string render_frame_panel(const protocol::DataBytes& data, int center, bool ansi);

/// What `run` knows at one moment.
struct RunStatus {
  std::string robot;
  std::uint8_t code = 0;
  int center = mapping::kDefaultCenter;  ///< the mapping's rest value of drive and pivot
  double rate_hz = 0;            ///< the configured rate
  std::int64_t t_ms = 0;
  std::string input;             ///< "sdl" or the script's path
  std::string controller;        ///< its name; empty when none is connected
  bool connected = false;
  bool enabled = false;
  std::string enable_text;
  std::string layer;             ///< the mapping layer in use, "" for the base
  bool shutting_down = false;
  std::string link_name;
  link::LinkState link_state = link::LinkState::kConnecting;
  std::string link_detail;
  bool motion_allowed = true;    ///< false: the link gets neutral frames only (Link::motion_allowed)
  link::LinkCounters link;
  timing::TimingSummary sent_timing;     ///< frames handed to the link
  protocol::DataBytes sent{};              ///< the last frame computed
  std::optional<link::VehicleSnapshot> vehicle;  ///< the simulated vehicle's view
};

std::string render_run_view(const RunStatus& status, bool ansi);

/// `monitor`'s view of a port or capture. A frame does not say which mapping
/// made it: drive and pivot are drawn around the default centre.
std::string render_monitor_view(std::string_view source, const link::VehicleSnapshot& vehicle, bool live,
                                bool ansi);

}  // namespace andros::view
