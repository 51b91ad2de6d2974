#pragma once
/// The mapping engine: a pure function of (input state, its own previous
/// state, tick time, whether motion is allowed) to the frame's data bytes. No
/// SDL, no clock reads, no I/O. It decides nothing about whether the vehicle
/// may move: the run loop's guards read the deadman and the stop buttons the
/// mapping names (run/drive_guard.hpp), its operating-state machine decides,
/// and the engine is told (step()'s motion_allowed). The safety rules (docs/mapping.md) are applied in one
/// place, the rest rule before the bindings and apply_safety() after them,
/// so that no mapping can bypass them.

#include <bitset>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "andros/input/input_state.hpp"
#include "andros/mapping/engine_status.hpp"
#include "andros/mapping/frame_source.hpp"
#include "andros/mapping/model.hpp"
#include "andros/mapping/safety.hpp"
#include "andros/protocol/frame.hpp"

namespace andros::mapping {

struct EngineOptions {
  bool weapons = false;      ///< --weapons / weapons=enabled
  std::uint8_t code = 0x01;  ///< byte 11, the dip-switch code
  /// A step from the controllers as they were at a step that changed nothing
  /// is that step again: its frame is reused (Engine::step). False: every
  /// step is computed afresh (the tests' reference for the reuse).
  bool reuse_settled = true;
};

class Engine final : public FrameSource {
 public:
  /// Levels (arm_speed, light) are kept in 1/kMilli units.
  static constexpr std::int64_t kMilli = 1000;

  /// Runs a validated mapping (validate(), load_mapping()).
  Engine(ValidMapping mapping, EngineOptions options);

  /// One tick at time now_ms (ms since start, non-decreasing; the first
  /// step is start-up: presses counted before it are history):
  /// the data bytes of the frame to send, the bindings applied only
  /// when motion_allowed (the operating state is enabled); otherwise the
  /// neutral frame. Always a frame that passes validation. While nothing
  /// changes (the controllers and motion_allowed as at the last step, which
  /// found them as at the one before and changed none of the engine's
  /// state), the last frame is given again without computing it: the same
  /// frame and status that computing would give (see step()).
  Step step(const input::InputState& input, std::int64_t now_ms, bool motion_allowed) override;

  /// Starts afresh from the input as it is now (the run loop's rebase: after
  /// a link regained, a reload, a resume): every press it has counted is
  /// history, the deadman needs a fresh press, toggles and a toggled layer (a weapons one above all) are off,
  /// and the speed level is the mapping's initial one.
  void rebase(const input::InputState& now) override;

  /// The neutral frame for the current analog/selector state (shutdown, link
  /// loss): every motion and weapon bit 0, drive and pivot at the protocol's
  /// 128 (never the mapping's `center:` trim). Kept from one computed step to
  /// the next (the loop asks for it on every tick that is not enabled).
  [[nodiscard]] protocol::DataBytes neutral() const override;

  [[nodiscard]] const EngineStatus& status() const;
  [[nodiscard]] const Mapping& mapping() const override;
  /// The last step found the controllers as the one before did and changed
  /// nothing: until they (or motion_allowed) change, a step gives its frame again.
  [[nodiscard]] bool settled() const { return settled_; }

 private:
  /// What a step carries to the next (but the last step's time), as one
  /// value: a step that leaves it as it found it is settled.
  struct Carried {
    explicit Carried(const Mapping& mapping) : rest(mapping) {}

    bool started = false;
    std::uint32_t connection = 0;
    std::uint32_t supervisor_connection = 0;                ///< the supervisor's controller session
    std::map<input::InputKey, std::uint32_t> seen_presses;  ///< presses already acted on (or ignored)
    int layer = -1;                                         ///< active layer, -1 = base
    int toggled_layer = -1;                                 ///< layer switched on by a toggle button
    std::bitset<protocol::kSignalCount> toggled;            ///< one toggle state per signal, whichever input flips it
    RestRule rest;
    std::vector<int> selector;                                       ///< per binding slot: a selector's position
    std::array<std::int64_t, protocol::kSignalCount> level_milli{};  ///< arm_speed/light in 1/1000 units
    EngineStatus status;

    bool operator==(const Carried&) const = default;
  };

  /// The step, computed.
  protocol::DataBytes compute(const input::InputState& input, std::int64_t now_ms, bool enabled);
  /// Start-up, or a controller's new session (the operator's, the supervisor's): afresh.
  void follow_sessions(const input::InputState& input, std::int64_t now_ms);
  void start_session(const input::InputState& input, bool at_start_up);
  void clear_toggles();
  [[nodiscard]] bool held(const input::InputState& input, input::InputKey key, bool invert = false,
                          double threshold = kDefaultThreshold) const;
  [[nodiscard]] std::uint32_t new_presses(const input::InputState& input, input::InputKey key) const;
  void update_layer(const input::InputState& input, bool enabled);
  /// The speed buttons' presses (enabled only); a new level holds drive and pivot's sticks back.
  void update_speed(const input::InputState& input);
  void set_speed(std::size_t index);
  void apply(const input::InputState& input, BindingRef ref, std::int64_t dt_ms, protocol::ControlState& out,
             std::bitset<protocol::kSignalCount>& armed);
  [[nodiscard]] std::size_t slot(BindingRef ref) const;
  /// Before the bindings: drive and pivot at the mapping's trim (their rest
  /// while enabled), levels, selectors and constants as they stand.
  /// apply_safety() puts drive and pivot back at 128 in a neutral frame.
  [[nodiscard]] protocol::ControlState resting_state() const;

  ValidMapping mapping_;
  EngineOptions options_;
  protocol::FrameBuilder builder_;
  EngineStatus status_;
  std::vector<BindingRef> all_;                     ///< every binding; its slot is its index here
  std::vector<std::vector<BindingRef>> effective_;  ///< [layer + 1]
  std::vector<std::size_t> slot_base_;              ///< [layer + 1]: first slot of its bindings
  std::vector<input::InputKey> buttons_;            ///< every button the mapping reads
  std::vector<bool> weapons_layer_;                 ///< [layer + 1]: a weapon binding is in effect there
  Carried c_;                                       ///< carried from step to step
  std::int64_t last_ms_ = 0;

  // The last step, for the next one (step()).
  input::PadState stepped_operator_;  ///< the controllers it read
  input::PadState stepped_supervisor_;
  bool stepped_motion_ = false;                         ///< and whether motion was allowed
  protocol::DataBytes stepped_frame_{};                 ///< its frame
  mutable std::optional<protocol::DataBytes> neutral_;  ///< neutral() since the last computed step
  bool stepped_ = false;
  bool settled_ = false;  ///< it found the controllers as the one before did, and changed nothing in c_
};

}  // namespace andros::mapping
