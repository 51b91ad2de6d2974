#pragma once
/// The safety rules of docs/mapping.md ("What a mapping cannot change"), in
/// one place. The engine passes every frame through apply_safety() after the
/// bindings, and every input through a RestRule before them, so no mapping can
/// bypass them.

#include <bitset>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <utility>
#include <vector>

#include "andros/input/input_state.hpp"
#include "andros/mapping/engine_status.hpp"
#include "andros/mapping/model.hpp"
#include "andros/protocol/frame.hpp"

namespace andros::mapping {

struct SafetyContext {
  bool enabled = false;                       ///< connected + deadman held + pressed fresh
  bool weapons = false;                       ///< weapons enabled for the run
  std::bitset<protocol::kSignalCount> armed;  ///< weapon signals whose arming input is held
  int center = kDefaultCenter;  ///< drive and pivot's rest while enabled (the trim): `brake: moving` measures from it
  BrakeMode brake = BrakeMode::kEnabled;
  /// The supervisor's weapons consent counts (RestRule::consent), or the mapping asks for none.
  bool consent = true;
};

/// Not enabled: motion and weapon bits 0, drive/pivot at the protocol's
/// centre (128, whatever the mapping's trim), selectors, levels and constants
/// unchanged. Enabled: safety = 1, drive_brake = 1 (or
/// only while moving), weapons only when enabled for the run, armed and
/// consented to.
/// Always: an opposing pair asked for both ways sends neither.
protocol::ControlState apply_safety(protocol::ControlState state, const SafetyContext& context);

/// No motion from a change of meaning. When the bridge becomes enabled (or a
/// new controller session is enabled), or the active layer changes which
/// bindings read an input, that input is held back until it is seen at rest
/// by every binding now reading it: a button released, an axis inside its
/// deadzone (drive, pivot, a level) or below its threshold (a pair, an axis as
/// a button or arming input). Presses counted up to that frame are dropped; a
/// press after it (released in between) acts. The deadman and the layer
/// buttons are not held back: they change meanings, they do not move anything.
///
/// Speed levels: a new level changes what drive and pivot's sticks mean, so
/// rescale() holds back each one off rest as above. The speed buttons are read
/// in every layer: held when the bridge becomes enabled, they wait too.
///
/// Weapons: a weapon becoming armed (its arming input held) changes what its
/// fire input means too, so a fire input held at that frame waits as above. An
/// arming input itself counts, like the deadman, when it is pressed in the
/// frame of a change; one held since before the change waits until released.
///
/// The supervisor's weapons consent (the mapping's `supervisor:` section) is
/// read the same way: it means something while enabled in a layer with
/// weapons, and it takes on a new meaning when that begins, when the weapons
/// in effect change with the layer, and when either controller is new. A
/// consent pressed in that frame counts; one held since before waits until
/// released (a consent taped down is no second person). Consent given is
/// part of arming: a fire input held when it comes waits too.
class RestRule {
 public:
  explicit RestRule(const Mapping& mapping);

  /// Once per tick, after the enable state and the active layer (-1 = base)
  /// are known and before any binding reads the input. Drops the presses of
  /// each input whose meaning changed by moving its `seen` count up to now.
  void update(const input::InputState& input, int layer, bool enabled, std::map<input::InputKey, std::uint32_t>& seen);

  /// The engine starts afresh (a rebase): the next enabled update is a
  /// change of meaning for every input, as becoming enabled is, whatever the
  /// engine's own steps while the loop sent neutral frames said.
  void restart() { enabled_ = false; }

  /// After the speed level changed (enabled, after update()): every axis
  /// driving drive or pivot in `layer` that is not at rest is held back.
  void rescale(const input::InputState& input, int layer);

  /// True while `key` may not act: its meaning changed and it has not been at rest since.
  [[nodiscard]] bool held_back(input::InputKey key) const { return held_.contains(key); }

  /// The inputs held back now (EngineStatus::held_back).
  [[nodiscard]] std::vector<input::InputKey> held_back_inputs() const;

  /// The supervisor's consent at the last update (kNotAsked without one in the mapping).
  [[nodiscard]] ConsentState consent_state() const { return consent_; }
  /// Weapons may fire as far as the supervisor is concerned: consent given, or none asked.
  [[nodiscard]] bool consent() const { return consent_ == ConsentState::kNotAsked || consent_ == ConsentState::kGiven; }

  /// The same rule in the same state (the engine's test for a step that changed nothing).
  bool operator==(const RestRule&) const = default;

 private:
  /// What "at rest" is for one binding reading one input.
  struct Reader {
    std::pair<int, std::size_t> binding;  ///< layer, index: which binding reads it
    enum class Rest : std::uint8_t { kReleased, kBelow, kInsideBand, kInsideDeadzone, kNotPositive } rest;
    bool invert = false;
    double limit = 0.0;  ///< threshold or deadzone

    bool operator==(const Reader&) const = default;
  };
  using Readers = std::map<input::InputKey, std::vector<Reader>>;

  /// A layer's weapons by arming input: the fire inputs each arming input arms.
  using Arms = std::map<input::InputKey, std::vector<input::InputKey>>;

  [[nodiscard]] static bool at_rest(const input::InputState& input, input::InputKey key,
                                    const std::vector<Reader>& readers);
  void hold_back(const input::InputState& input, int layer, std::map<input::InputKey, std::uint32_t>& seen);
  void hold_back_fire_inputs(const input::InputState& input, int layer, std::map<input::InputKey, std::uint32_t>& seen);
  void update_consent(const input::InputState& input, int layer, bool enabled);
  void hold(const input::InputState& input, input::InputKey key, bool rest);
  [[nodiscard]] bool pressed_this_frame(const input::InputState& input, input::InputKey arm) const;

  std::vector<Readers> readers_;                   ///< [layer + 1]: every input the layer's bindings read
  std::vector<Arms> arms_;                         ///< [layer + 1]
  Readers arm_readers_;                            ///< every arming input of any layer, read as its weapons read it
  std::map<input::InputKey, std::uint32_t> held_;  ///< held-back input -> its press count when held back
  bool enabled_ = false;
  std::uint32_t connection_ = 0;
  int layer_ = -1;
  std::set<input::InputKey> armed_;  ///< arming inputs that armed their weapons at the last enabled frame
  // The arming inputs at the last frame, enabled or not: the triggers held, the buttons' press counts.
  std::set<input::InputKey> arms_down_;
  std::map<input::InputKey, std::uint32_t> arm_presses_;
  std::uint32_t arms_connection_ = 0;  ///< the controller session of that frame
  // The supervisor's weapons consent.
  std::optional<input::InputKey> consent_key_;
  std::vector<std::vector<std::pair<int, std::size_t>>> weapons_;  ///< [layer + 1]: the weapon bindings in effect
  ConsentState consent_ = ConsentState::kNotAsked;
  bool consent_meant_ = false;              ///< consent meant something at the last frame
  std::uint32_t consent_presses_ = 0;       ///< its presses at the last frame
  std::uint32_t consent_hold_presses_ = 0;  ///< and when it was held back
  std::uint32_t consent_connection_ = 0;    ///< the supervisor's controller session of the last frame
};

}  // namespace andros::mapping
