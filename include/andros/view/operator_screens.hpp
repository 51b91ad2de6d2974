#pragma once
/// The operator's screens, as text: what `run` shows on a terminal
/// (render_run_screen, run_screen.cpp) and what `monitor` shows from the
/// vehicle's side (render_monitor_screen). Pure formatting, no I/O: each
/// screen is a function of a value it is handed (docs/architecture.md); a
/// TerminalDisplay (terminal_display.hpp) puts it on the terminal.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "andros/link/link_status.hpp"
#include "andros/link/vehicle_status.hpp"
#include "andros/mapping/engine_status.hpp"
#include "andros/mapping/model.hpp"
#include "andros/protocol/frame.hpp"
#include "andros/run/operating_state.hpp"
#include "andros/timing/frame_timing.hpp"
#include "andros/view/screen.hpp"

namespace andros::view {

/// The switches grouped by function, as the view lists them.
struct SignalGroup {
  std::string_view title;
  std::vector<protocol::SignalId> signals;
};
const std::vector<SignalGroup>& signal_groups();

/// How switch_lines names a switch.
enum class SwitchNames : std::uint8_t {
  kSignal,    ///< the protocol's name (`zoom_down`): `monitor`, the vehicle's side
  kOperator,  ///< the operator's words (protocol/words.hpp, "zoom out"): `run`
};

/// The switch groups of a frame, wrapped to width: active switches in upper
/// case (reverse video in colour; a weapon white on red), idle ones lower
/// case (dim). compact: only the active ones, one line a group, for a small
/// terminal.
std::vector<Line> switch_lines(const protocol::DataBytes& data, std::size_t width, bool compact,
                               SwitchNames names = SwitchNames::kSignal);

/// The selectors' positions a frame sets, a position without a bit too:
/// "speed medium   main video 1   inset off".
Line selector_line(const protocol::DataBytes& data);

/// The drive, pivot, arm speed and light gauges, and the frame in hex; drive
/// and pivot grow from center (the mapping's rest while enabled) in a frame
/// with safety 1, from the protocol's 128 in a neutral one.
std::vector<Line> gauge_lines(const protocol::DataBytes& data, int center);

/// What `run` knows at one moment.
struct RunStatus {
  std::string robot;
  std::string mapping_file;  ///< the mapping the run uses
  bool weapons = false;      ///< weapon signals may be sent in this run (--weapons)
  std::uint8_t code = 0;
  int center = mapping::kDefaultCenter;  ///< the mapping's rest of drive and pivot while enabled (its trim)
  double rate_hz = 0;                    ///< the configured rate
  std::int64_t t_ms = 0;
  std::string input;       ///< "sdl" or the script's path
  std::string controller;  ///< its name; empty when none is connected
  bool connected = false;
  bool supervised = false;  ///< a supervisor's controller is configured
  std::string supervisor;   ///< its name; empty when none is connected
  bool supervisor_connected = false;
  bool supervisor_stop = false;                                      ///< the supervisor holds its stop
  mapping::ConsentState consent = mapping::ConsentState::kNotAsked;  ///< the supervisor's weapons consent
  /// The live controller is a game controller to SDL (false: a plain
  /// joystick, numbered inputs only); nullopt: none connected, or a script.
  std::optional<bool> game_controller;
  bool pad_names = true;                       ///< the mapping reads game-controller names (leftshoulder, leftx...)
  run::OpState state = run::OpState::kNoLink;  ///< the operating state: what is sent follows it
  std::string stopped_by;                      ///< a stop latched: "stopped by the supervisor (NAME)" (stopped_by_text)
  std::string enable_text;  ///< the state in words: why not enabled, or what enabled still holds back
  std::string held_back;    ///< enabled: the inputs the rest rule still holds back ("lefty a"); "" when none is
  /// Stopped, a reset gesture under way: its progress ("resetting: 1.2 of 2.0 s ..."), shown in place of
  /// enable_text (never logged: it moves every tick).
  std::string reset_progress;
  std::string layer;          ///< the mapping layer in use, "" for the base
  bool weapons_mode = false;  ///< enabled in a layer with weapons: the WEAPONS LAYER banner
  mapping::SpeedLevel speed;  ///< the speed level (the mapping's `scale:`)
  bool armed = false;         ///< in a weapons mode, an arming input held: a fire button fires
  std::string link_name;
  link::LinkState link_state = link::LinkState::kConnecting;
  std::string link_detail;
  bool far_end_reading = true;  ///< false: the link gets neutral frames only (Link::far_end_reading)
  link::LinkCounters link;
  timing::TimingSummary sent_timing;           ///< frames handed to the link
  protocol::DataBytes sent{};                  ///< the last frame computed
  std::optional<link::VehicleStatus> vehicle;  ///< the simulated vehicle's view
  std::string recorder;                        ///< the flight recorder: its session, or what it dropped; "" when off
  bool recorder_failing = false;               ///< records were dropped: the session is incomplete
  std::int64_t gate_trips = 0;                 ///< frames the frame gate replaced (each an internal error)
  /// `trainer`: what the page is (its address, or why there is none); empty in `run`.
  std::string trainer;

  [[nodiscard]] bool enabled() const { return state == run::OpState::kEnabled; }
  [[nodiscard]] bool shutting_down() const { return state == run::OpState::kShuttingDown; }
};

/// The operating state in the screen's words: "ENABLED", "STOPPED: ...",
/// "SHUTTING DOWN: sending neutral frames" (the trainer's page says the same).
std::string state_words(const RunStatus& status);

/// A speed level as the screen and the log give it: "2/3 (50%)".
std::string speed_text(const mapping::SpeedLevel& speed);

/// Whether a mapping's speed levels are worth showing: anything but the
/// default, one level of 1.0.
bool shows_speed(const mapping::SpeedLevel& speed);

/// `run`'s screen for a terminal of this size: pinned first (the WEAPONS
/// banner when weapons are enabled, saying WEAPONS LAYER in a weapons mode;
/// title and measured rate, state, link, controller, the supervisor's
/// controller when one is configured, mapping file), then
/// counters, switch groups and gauges while rows are left (docs/running.md,
/// "What the operator sees").
Screen render_run_screen(const RunStatus& status, TermSize size);

/// `monitor`'s view of a port or capture: pinned source, rate (live),
/// counts and the last frame's validity, then its switches and gauges. A
/// frame does not say which mapping made it: drive and pivot are drawn around
/// the default centre.
Screen render_monitor_screen(std::string_view source, const link::VehicleStatus& vehicle, bool live, TermSize size);

}  // namespace andros::view
