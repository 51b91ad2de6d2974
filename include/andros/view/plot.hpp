#pragma once
/// The plot of a drive (docs/recording.md): drive and pivot over time, the
/// operating state as coloured bands (who stopped, who reset), the active
/// layer (a weapons layer in the weapons red), lanes for the deadman, the
/// stop buttons, the consent, arming, the controllers and the link, and a
/// timeline of every switch signal that was on (weapons in red), on one A4
/// landscape SVG page. Made from a recorded session, or from a replay.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "andros/input/input_state.hpp"
#include "andros/mapping/model.hpp"
#include "andros/protocol/frame.hpp"
#include "andros/record/session.hpp"
#include "andros/run/bridge.hpp"
#include "andros/timing/rate.hpp"

namespace andros::view {

/// One tick of the loop, or, from a session, the first of a run of ticks
/// that repeat it, or the start of ticks the loop did not run (nothing sent).
/// Its frame holds until the next sample's time.
struct PlotSample {
  std::int64_t t_ms = 0;
  protocol::DataBytes data{};
  bool sent = false;  ///< the link took the frame
  run::OpState state = run::OpState::kNoLink;
  std::string layer;           ///< "" for the base layer
  std::string stop;            ///< a stop latched: whose ("operator", "supervisor", "frame gate"); "" when none
  std::string reset;           ///< who reset the last stop, until the next stop or enabled; "" when none
  std::int64_t ticks = 1;      ///< the ticks it stands for: itself and those after it that repeat it (0: ticks not run)
  std::int64_t reset_ms = -1;  ///< when that reset was: where it is drawn (-1: not known, at the run's first sample)
};

/// The lanes under the state band: each a fact, on or off over time.
enum class LaneKind : std::uint8_t {
  kOperatorPad,     ///< the operator's controller connected
  kSupervisorPad,   ///< the supervisor's controller connected
  kLink,            ///< the link up
  kDeadman,         ///< the deadman held
  kOperatorStop,    ///< the operator's stop button (`estop`) held
  kSupervisorStop,  ///< the supervisor's stop button held
  kConsent,         ///< the supervisor's weapons consent held
  kArming,          ///< an arming input held
};

/// From from_ms to to_ms (-1: to the end of the page).
struct PlotSpan {
  std::int64_t from_ms = 0;
  std::int64_t to_ms = -1;
};

struct PlotLane {
  LaneKind kind = LaneKind::kDeadman;
  std::vector<PlotSpan> spans;  ///< when the fact held, in time order
};

struct PlotInput {
  std::string title;     ///< robot and mapping
  std::string settings;  ///< rate, code, weapons, input
  std::string source;    ///< where it came from: a session (when, where, by which version), a replayed script
  std::vector<PlotSample> samples;         ///< in time order
  std::vector<PlotLane> lanes;             ///< those that apply to the run (a supervisor's only when supervised...)
  std::vector<std::string> weapon_layers;  ///< the layers with weapon bindings: drawn in the weapons red
  std::string lanes_missing;               ///< why there are no lanes, when there are none
  std::int64_t rate_millihertz = timing::kDefaultRateMillihertz;  ///< the ticks': a range's are counted
  std::int64_t from_ms = 0;
  std::int64_t to_ms = -1;  ///< -1: to the last sample
};

/// A replay's report as a sample.
PlotSample plot_sample(const run::TickReport& report);

/// A sample's operating state as the plot's band names and colours it
/// ("stopped by the operator", "#e57373"): the trainer's replay draws its
/// state lane with these.
struct StateSwatch {
  std::string_view name;
  std::string_view colour;
};
StateSwatch state_swatch(const PlotSample& sample);

/// The ticks the live loop ran, from the session's records: a sample at each
/// change point and at the last tick each holds to (work and memory as the
/// records', not the ticks').
std::vector<PlotSample> plot_samples(const record::Session& session);

/// The page's time axis, for samples made to its width: from_ms to to_ms (-1:
/// the session's last tick), as PlotInput's.
struct PlotAxis {
  std::int64_t from_ms = 0;
  std::int64_t to_ms = -1;
};

/// As plot_samples(session), sampled to the page's width: of the samples
/// that fall in one pixel column, only those the page draws are kept: the
/// column's first and last; each where the frame's sending, the state, the
/// layer, a stop or a switch signal's bit changes; and one at the lowest and
/// one at the highest drive and pivot (a trace draws a column's first,
/// lowest, highest and last). Each stands for the ticks of those dropped
/// after it. The page drawn from them is the one every sample draws, byte
/// for byte; a stick moving on every tick leaves at most 6 samples a column
/// (945 columns) of its changes, and a column's samples are held only while
/// it is made. Switch signals are kept at each change: a bit that changes on
/// every tick keeps a sample a tick, as the page draws it.
std::vector<PlotSample> plot_samples(const record::Session& session, const PlotAxis& axis);

/// Builds the lanes from what the input did (plot_lanes.cpp): the controllers'
/// events read with the mapping in effect (its deadman, stop buttons,
/// consent and arming inputs), and the link's changes.
class LaneBuilder {
 public:
  /// supervised: a supervisor's controller is configured (its lanes are drawn).
  LaneBuilder(const mapping::Mapping& mapping, bool supervised);
  /// A reload put this mapping in place at t_ms.
  void use_mapping(std::int64_t t_ms, const mapping::Mapping& mapping);
  /// A controller's event (connect, disconnect, button, axis, hat); a fault event is ignored.
  void event(const input::InputEvent& event);
  /// The link went up or down at t_ms (up from the start until told otherwise).
  void link(std::int64_t t_ms, bool up);
  [[nodiscard]] std::vector<PlotLane> lanes() const;

 private:
  void set(LaneKind kind, std::int64_t t_ms, bool on);
  void read_inputs(std::int64_t t_ms);

  mapping::Mapping mapping_;
  bool supervised_;
  input::InputState input_;
  std::vector<PlotLane> lanes_;
  std::vector<bool> on_;
};

/// A session's lanes and weapon layers: its events read with the recorded
/// mapping (each ok reload's from its time), its link records. None, and
/// lanes_missing saying why, when the recorded mapping cannot be read.
void add_lanes(PlotInput& in, const record::Session& session);

/// The layers of the mapping with weapon bindings (in effect in the layer).
std::vector<std::string> weapon_layers(const mapping::Mapping& mapping);

/// The page: 297 x 210 mm.
std::string render_plot_svg(const PlotInput& input);

}  // namespace andros::view
