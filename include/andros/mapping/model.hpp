#pragma once
/// A robot's mapping: which controller input drives which switchbox signal.
/// Plain data, filled by the YAML loader (loader.hpp) or by hand in a test;
/// validate() checks it once and hands back a ValidMapping, the only kind an
/// Engine runs.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "andros/base/error.hpp"
#include "andros/input/input_state.hpp"
#include "andros/mapping/feedback.hpp"
#include "andros/protocol/signals.hpp"

namespace andros::mapping {

inline constexpr int kDefaultCenter = protocol::kNeutralCentre;
/// `center:` only trims drive and pivot's rest while enabled, within
/// 128 +- 8 (docs/mapping.md): enough for a vehicle whose rest point is a few
/// units off, never enough to drive. Neutral frames carry 128 whatever it is.
inline constexpr int kCenterTrimMin = kDefaultCenter - 8;
inline constexpr int kCenterTrimMax = kDefaultCenter + 8;
inline constexpr std::uint8_t kDefaultByte12 = 0x00;
inline constexpr std::uint8_t kDefaultBattery = 0xCC;
inline constexpr double kDefaultThreshold = 0.5;
inline constexpr int kMaxKnobRate = 25500;  ///< units per second: 0 to 255 in 10 ms
/// `deadman_panic:` lies above the trigger deadman's press point and below
/// full travel (docs/mapping.md, "Three-position trigger").
inline constexpr double kDeadmanPanicMin = kDefaultThreshold;
/// After a panic the trigger counts as fully released below this travel.
inline constexpr double kDeadmanFullyReleased = 0.1;
/// `stop_reset_hold:` in seconds: how long the reset gesture is held to reset a stop.
inline constexpr double kStopResetHoldMinS = 1.0;
inline constexpr double kStopResetHoldMaxS = 10.0;
inline constexpr std::int64_t kStopResetHoldDefaultMs = 2000;
/// A reset gesture is one button, or a chord of at most this many held together.
inline constexpr std::size_t kMaxResetChord = 2;
/// `enable_timeout:` in seconds: at least one frame period, at most an hour.
inline constexpr double kEnableTimeoutMinS = 1.0;
inline constexpr double kEnableTimeoutMaxS = 3600.0;

/// How a stick or trigger value becomes a number in [-1, 1] (docs/mapping.md).
struct AxisShape {
  bool invert = false;
  double deadzone = 0.0;
  double expo = 0.0;
};

/// A bit signal that is 1 while a button is held (or, with toggle, flips on
/// each press). The input may be an axis: held when its value >= threshold
/// (after invert).
struct ButtonBinding {
  protocol::SignalId signal = 0;
  input::InputKey input{};
  bool toggle = false;
  bool invert = false;
  double threshold = kDefaultThreshold;
};

/// A weapon signal: 1 while the button and the arming input are both held
/// (and weapons are enabled for the run, and the deadman is held).
struct WeaponBinding {
  protocol::SignalId signal = 0;
  input::InputKey input{};
  std::optional<input::InputKey> arm;  ///< required; validate() rejects a missing one
};

/// One axis drives two signals: the first at value <= -threshold, the second
/// at value >= +threshold.
struct PairBinding {
  std::array<protocol::SignalId, 2> signals{};
  input::InputKey axis{};
  bool invert = false;
  double threshold = kDefaultThreshold;
};

/// An axis drives a whole byte: drive/pivot around the centre, or a
/// trigger spanning arm_speed/light from 0 to 255.
struct AxisBinding {
  protocol::SignalId analog = 0;
  input::InputKey axis{};
  AxisShape shape{};
};

/// Two buttons move a level byte (arm_speed, light) at rate units per second.
struct KnobBinding {
  protocol::SignalId analog = 0;
  input::InputKey increase{};
  input::InputKey decrease{};
  int rate = 0;
  std::optional<int> initial;  ///< the byte's value at start-up
};

/// A rotary switch: each press of next (or prev) moves to the next (previous)
/// position, wrapping; each position sets its selector signals.
struct SelectorBinding {
  std::string name;
  input::InputKey next{};
  std::optional<input::InputKey> prev;
  std::vector<std::vector<protocol::SignalId>> positions;
  int initial = 0;
};

using BindingRule = std::variant<ButtonBinding, WeaponBinding, PairBinding, AxisBinding, KnobBinding, SelectorBinding>;

/// An input a binding reads, and where the file names it (for errors).
struct InputUse {
  input::InputKey key{};
  SourcePos pos;
};

struct Binding {
  BindingRule rule;
  SourcePos pos;                 ///< the binding's first line
  SourcePos target_pos;          ///< where its signal/analog/selector is named
  std::vector<InputUse> inputs;  ///< inputs it is triggered by (not `arm`)
  std::optional<InputUse> arm;   ///< a weapon's arming input
};

/// A second set of bindings, active while its button is held (hold) or after
/// it was pressed (toggle; pressed again returns to the base layer). Its
/// bindings replace the base bindings that use the same inputs or drive the
/// same analog byte; the other base bindings stay active.
struct Layer {
  std::string name;
  SourcePos pos;
  InputUse input{};
  bool toggle = false;
  std::vector<Binding> bindings;
};

/// At most this many speed levels: a change of level is counted out in as
/// many rumble pulses as the level's number (docs/mapping.md, `scale`).
inline constexpr std::size_t kMaxSpeedLevels = static_cast<std::size_t>(input::kMaxFeedbackPulses);

/// Speed levels (`scale:`): while enabled, drive and pivot move `level` times
/// their distance from rest. Absent from a mapping: the one level 1.0.
struct SpeedScale {
  std::vector<double> levels{1.0};  ///< fractions in (0, 1], strictly increasing
  std::size_t initial = 0;          ///< the level a controller session and a restart begin at
  std::optional<InputUse> up;       ///< steps up; after the highest, back to the lowest
  std::optional<InputUse> down;     ///< steps down; stops at the lowest
  SourcePos pos;                    ///< where `scale:` is
};

/// When drive_brake is 1 (it is always 0 while not enabled).
enum class BrakeMode : std::uint8_t {
  kEnabled,  ///< released whenever the engine is enabled (the default)
  kMoving,   ///< released only while drive or pivot is off centre
};

/// The supervisor's controller (`supervisor:`, docs/mapping.md): buttons
/// read on the second pad (`run --supervisor`), never on the operator's.
struct SupervisorButtons {
  SourcePos pos;  ///< the section
  InputUse stop;  ///< latches the stop, as the operator's `estop` does
  /// `reset:`, one button or a chord held together: resets any stop (none: the supervisor resets nothing)
  std::vector<InputUse> reset;
  std::optional<InputUse> weapons_consent;  ///< with it, a weapon fires only while it is held too
};

struct Mapping {
  std::string file;                  ///< the file it was loaded from
  std::vector<std::string> chain;    ///< the files read, canonical: this one, then each it extends
  std::optional<std::string> robot;  ///< canonical robot type; none for a base file
  SourcePos robot_pos;
  int center = kDefaultCenter;  ///< drive and pivot's rest while enabled: a trim, kCenterTrimMin..kCenterTrimMax
  std::uint8_t byte12 = kDefaultByte12;
  std::uint8_t battery = kDefaultBattery;
  std::optional<InputUse> deadman;
  /// The operator's latching stop button (`estop:`): its press stops the
  /// vehicle until it and the deadman are released and the deadman is pressed
  /// afresh. Bound to nothing else in any layer.
  std::optional<InputUse> estop;
  /// The operator's reset (`stop_reset:`): one button, or a chord held
  /// together, never a stop button. Held stop_reset_hold_ms with the deadman
  /// and every stop button released, on the pad that stopped, it resets the
  /// operator's stop (none: only the supervisor resets).
  std::vector<InputUse> stop_reset;
  /// How long a reset gesture is held (`stop_reset_hold:`, in ms here).
  std::int64_t stop_reset_hold_ms = kStopResetHoldDefaultMs;
  /// A trigger deadman squeezed to this fraction or past it is off, and stays
  /// off until fully released (`deadman_panic:`); none: no panic position.
  std::optional<double> deadman_panic;
  SourcePos deadman_panic_pos;
  /// Enabled with no change of any input the mapping reads for this long ends
  /// "enabled" (`enable_timeout:`, in ms here); none: no timeout.
  std::optional<std::int64_t> enable_timeout_ms;
  std::optional<SupervisorButtons> supervisor;
  BrakeMode brake = BrakeMode::kEnabled;
  SpeedScale scale;
  FeedbackTable feedback = default_feedback();  ///< rumble and light per event
  std::vector<Binding> bindings;                ///< the base layer
  std::vector<Layer> layers;
};

class ValidMapping;

/// The error for a `center:` outside kCenterTrimMin..kCenterTrimMax, `value`
/// as written: names the band and why it is narrow.
std::string center_out_of_band(std::string_view value);

/// What a trim does, for `check` ("center 124: drive and pivot rest at 124
/// while enabled; neutral frames carry 128"); empty for the default 128.
std::string center_effect(int center);

/// Checks the rules that span bindings (docs/mapping.md): an input bound
/// twice in a layer, two bindings on one analog byte, a weapon without arm,
/// targets a binding kind cannot drive, a signal both toggled and momentary
/// (anywhere in the mapping), a missing deadman or robot. Throws
/// InputError at the offending FILE:LINE:COL. A base mapping (require_robot
/// false) may lack robot and deadman.
ValidMapping validate(Mapping mapping, bool require_robot = true);

/// A mapping that passed validate(), read-only. validate() is the one way to
/// make one, so a mapping reaches an Engine checked exactly once, whether it
/// was loaded or built by hand.
class ValidMapping {
 public:
  [[nodiscard]] const Mapping& operator*() const { return mapping_; }
  [[nodiscard]] const Mapping* operator->() const { return &mapping_; }

 private:
  friend ValidMapping validate(Mapping mapping, bool require_robot);
  explicit ValidMapping(Mapping mapping) : mapping_(std::move(mapping)) {}
  Mapping mapping_;
};

/// The rule that a mapping names each layer once: throws InputError at
/// layer.pos when `names` (the layers seen so far) already holds its name.
void check_layer_name(std::set<std::string>& names, const Layer& layer);

/// A binding by position: layer -1 is the base list, else mapping.layers[layer].
struct BindingRef {
  int layer = -1;
  std::size_t index = 0;
};

const Binding& binding_at(const Mapping& mapping, BindingRef ref);

/// Every binding, base first, then each layer's in order.
std::vector<BindingRef> all_bindings(const Mapping& mapping);

/// Every input a mapping reads, each once: its buttons and its axes (a
/// deadman, layer key or binding input given as either counts as both).
struct ReadInputs {
  std::vector<input::InputKey> buttons;
  std::vector<input::InputKey> axes;
};
ReadInputs read_inputs(const Mapping& mapping);

/// The analog byte a binding drives, if it drives one.
std::optional<protocol::SignalId> analog_target(const Binding& binding);

/// True when b replaces a (or a b): they share an input or drive the same analog byte.
bool bindings_conflict(const Binding& a, const Binding& b);

/// The bindings in effect in a layer (-1 = base): the layer's own, then the
/// base bindings it does not replace.
std::vector<BindingRef> effective_bindings(const Mapping& mapping, int layer);

}  // namespace andros::mapping
