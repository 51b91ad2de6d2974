#pragma once
/// The controller as the mapping sees it: named inputs, the events that move
/// them (from SDL or an event script), and the input state they build.

#include <array>
#include <compare>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "andros/input/pad_identity.hpp"

namespace andros::input {

/// SDL game-controller button names, in SDL_GameControllerButton order.
inline constexpr std::array<std::string_view, 21> kPadButtonNames = {"a",
                                                                     "b",
                                                                     "x",
                                                                     "y",
                                                                     "back",
                                                                     "guide",
                                                                     "start",
                                                                     "leftstick",
                                                                     "rightstick",
                                                                     "leftshoulder",
                                                                     "rightshoulder",
                                                                     "dpup",
                                                                     "dpdown",
                                                                     "dpleft",
                                                                     "dpright",
                                                                     "misc1",
                                                                     "paddle1",
                                                                     "paddle2",
                                                                     "paddle3",
                                                                     "paddle4",
                                                                     "touchpad"};

/// SDL game-controller axis names, in SDL_GameControllerAxis order.
inline constexpr std::array<std::string_view, 6> kPadAxisNames = {"leftx",  "lefty",       "rightx",
                                                                  "righty", "lefttrigger", "righttrigger"};

/// Hat directions, in the order of the bits of SDL_HAT_* (up 1, right 2, down 4, left 8).
inline constexpr std::array<std::string_view, 4> kHatDirectionNames = {"up", "right", "down", "left"};

inline constexpr int kMaxJoystickIndex = 255;
/// A hat's four directions are buttons hat * 4 + direction, within kMaxJoystickIndex.
inline constexpr int kMaxHatIndex = kMaxJoystickIndex / 4;

/// An axis's range as SDL reports it (Sint16): -32768 is one end, 32767 the
/// other, so that the two halves differ by one (docs/mapping.md).
inline constexpr int kAxisMin = -32768;
inline constexpr int kAxisMax = 32767;

enum class InputKind : std::uint8_t {
  kPadButton,  ///< index into kPadButtonNames
  kPadAxis,    ///< index into kPadAxisNames
  kJoyButton,  ///< a plain joystick's button number
  kJoyAxis,    ///< a plain joystick's axis number
  kHat,        ///< a hat direction as a button: index = hat * 4 + direction
};

/// One physical input. Hat directions are buttons, so that every binding that
/// takes a button (momentary, toggle, deadman...) can take a hat direction.
struct InputKey {
  InputKind kind = InputKind::kPadButton;
  std::uint16_t index = 0;

  auto operator<=>(const InputKey&) const = default;
  [[nodiscard]] bool is_button() const {
    return kind == InputKind::kPadButton || kind == InputKind::kJoyButton || kind == InputKind::kHat;
  }
};

/// "a" / "dpup" -> pad button, "3" -> joystick button 3, "hat0up" -> hat direction.
std::optional<InputKey> parse_button_name(std::string_view name);
/// "leftx" -> pad axis, "2" -> joystick axis 2.
std::optional<InputKey> parse_axis_name(std::string_view name);
/// The name parse_*_name reads back ("a", "3", "hat0up", "leftx").
std::string input_name(InputKey key);

/// Whose controller an event is for.
enum class Pad : std::uint8_t {
  kOperator,    ///< the operator's: the one that drives
  kSupervisor,  ///< the supervisor's (`run --supervisor`; a script's `T supervisor EVENT`): a stop, a consent
};

struct InputEvent {
  enum class Type : std::uint8_t {
    kConnect,
    kDisconnect,
    kButton,
    kAxis,
    kHat,
    kEnd,
    // Fault events (docs/event-scripts.md): what happens around the
    // controller, for the run loop to answer as it answers the real thing.
    kLinkDown,     ///< `link down`: the link is lost
    kLinkUp,       ///< `link up`: it is back
    kLinkTaken,    ///< `link taken`: another program holds the port
    kLinkStalled,  ///< `link stalled`: a TCP server that stopped reading (neutral frames only, through resets)
    kLinkReading,  ///< `link reading`: the server seen reading again
    kSuspend,      ///< `suspend`: job control (Ctrl-Z)
    kResume,       ///< `resume`: fg after it
    kReload,       ///< `reload [FILE]`: SIGHUP; name = the mapping file to load (empty: the same one)
    kShutdown,     ///< `stop`: as SIGINT/SIGTERM, the run shuts down on neutral frames
  };
  /// A fault event: one no controller's state takes.
  [[nodiscard]] bool is_fault() const { return type >= Type::kLinkDown; }

  std::int64_t t_ms = 0;
  Type type = Type::kEnd;
  InputKey key{};    ///< button or axis; for kHat, {kHat, hat * 4}
  int value = 0;     ///< button 0/1, axis -32768..32767, hat SDL_HAT_* bit mask
  std::string name;  ///< controller name, for kConnect; the mapping file, for kReload
  int line = 0;      ///< source line in an event script, 0 when live
  /// Whose controller a connect, disconnect, button, axis or hat event is
  /// for; always the operator's for the others (they are the run's, not a pad's).
  Pad pad = Pad::kOperator;
  /// kConnect: which physical pad (PadIdentity::fields(): "path=P serial=S guid=G"); "" when unknown.
  std::string device{};
};

struct ButtonState {
  bool down = false;
  /// Presses (0 -> 1) since this connection began, not counting buttons held
  /// at connect: a tap between two frames still shows, and a deadman held at
  /// connect is not a fresh press.
  std::uint32_t presses = 0;
  /// Releases (1 -> 0), counted as presses are: a button released and
  /// pressed again between two frames still shows as a release.
  std::uint32_t releases = 0;

  bool operator==(const ButtonState&) const = default;
};

/// The values an axis took since the tick began (InputState::begin_tick):
/// a trigger squeezed and let go between two frames still shows.
struct AxisSpan {
  std::int16_t low = 0;
  std::int16_t high = 0;

  bool operator==(const AxisSpan&) const = default;
};

/// One controller's state: its buttons, axes and hats as the events left them.
class PadState {
 public:
  /// Applies a connect, disconnect, button, axis or hat event (whoever's
  /// pad it names). Button, axis and hat events stamped with the same time as
  /// the connect before them are the controller's state when it appeared,
  /// not presses.
  void apply(const InputEvent& event);

  [[nodiscard]] bool connected() const { return connected_; }
  /// Counts connects; a new value means a new controller session.
  [[nodiscard]] std::uint32_t connection() const { return connection_; }
  [[nodiscard]] const std::string& name() const { return name_; }
  /// Which physical controller this session is (empty when none is connected).
  [[nodiscard]] const PadIdentity& identity() const { return identity_; }

  [[nodiscard]] ButtonState button(InputKey key) const;
  [[nodiscard]] std::int16_t axis(InputKey key) const;
  /// Every value the axis took since the tick began, its value then included.
  [[nodiscard]] AxisSpan axis_span(InputKey key) const;
  /// The hat's SDL_HAT_* mask (0 = centred).
  [[nodiscard]] int hat(int hat_index) const;
  /// A new tick: each axis's span is its value now.
  void begin_tick() { spans_.clear(); }

  /// The same controller session in the same state: every read above gives the same answer.
  bool operator==(const PadState&) const = default;

 private:
  void set_button(InputKey key, bool down, bool initial);

  bool connected_ = false;
  std::uint32_t connection_ = 0;
  std::int64_t connect_t_ = -1;
  std::string name_;
  PadIdentity identity_;
  std::map<InputKey, ButtonState> buttons_;
  std::map<InputKey, std::int16_t> axes_;
  std::map<InputKey, AxisSpan> spans_;  ///< the axes moved since the tick began
};

/// The input state a frame is computed from: the operator's controller (read
/// through the members below, which are its PadState's) and the
/// supervisor's (supervisor()). It holds the controllers only: an event
/// script's fault events go to the run loop beside it (TickInput).
class InputState {
 public:
  /// Applies a controller's event to the pad it names (InputEvent::pad).
  void apply(const InputEvent& event);

  [[nodiscard]] bool connected() const { return operator_pad_.connected(); }
  /// Counts the operator's connects; a new value means a new controller session.
  [[nodiscard]] std::uint32_t connection() const { return operator_pad_.connection(); }
  [[nodiscard]] const std::string& name() const { return operator_pad_.name(); }
  [[nodiscard]] ButtonState button(InputKey key) const { return operator_pad_.button(key); }
  [[nodiscard]] std::int16_t axis(InputKey key) const { return operator_pad_.axis(key); }
  [[nodiscard]] AxisSpan axis_span(InputKey key) const { return operator_pad_.axis_span(key); }
  /// The hat's SDL_HAT_* mask (0 = centred).
  [[nodiscard]] int hat(int hat_index) const { return operator_pad_.hat(hat_index); }

  /// The supervisor's controller: never connected in a run without one.
  [[nodiscard]] const PadState& supervisor() const { return supervisor_pad_; }
  /// The operator's controller, whole (what the members above read).
  [[nodiscard]] const PadState& operator_pad() const { return operator_pad_; }

  /// A new tick (the run loop, before each pump): the events applied from
  /// now on are this tick's. Presses and releases are counted whatever the
  /// tick; an axis's span (axis_span) starts again from its value now.
  void begin_tick() {
    operator_pad_.begin_tick();
    supervisor_pad_.begin_tick();
  }

 private:
  PadState operator_pad_;
  PadState supervisor_pad_;
};

/// One tick's input as a source hands it to the run loop
/// (InputSource::pump): a controller's event goes to the input state the
/// guards and the mapping stage read; an event around the controllers (an
/// event script's fault event: the link, a suspend, a resume, a reload, the
/// shutdown) is kept apart, for the loop to turn into the machine's event
/// (run/bridge_requests.cpp).
class TickInput {
 public:
  /// Applies one event: a fault is kept for take_faults(), any other goes to state().
  void apply(const InputEvent& event);

  [[nodiscard]] InputState& state() { return state_; }
  [[nodiscard]] const InputState& state() const { return state_; }

  /// The fault events applied since the last call, in order.
  [[nodiscard]] std::vector<InputEvent> take_faults() { return std::exchange(faults_, {}); }

  /// Also keeps every event applied from now on, faults included, in the
  /// order they came, for take_applied(): what the flight recorder writes
  /// (docs/recording.md).
  void keep_applied(bool on) { keep_applied_ = on; }
  [[nodiscard]] std::vector<InputEvent> take_applied() { return std::exchange(applied_, {}); }

 private:
  InputState state_;
  std::vector<InputEvent> faults_;
  bool keep_applied_ = false;
  std::vector<InputEvent> applied_;
};

}  // namespace andros::input
