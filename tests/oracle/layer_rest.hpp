#pragma once
// The rest rule for drive and pivot in the fault simulation's oracle
// (safety_oracle.hpp), layers included: read off the mapping in place, the
// script's inputs and the frame's own `safety` bit (1: the bridge was enabled
// at that tick, which the oracle checks apart). The layer is the mapping's
// rule: a held layer's input held wins (the first in the mapping), else the
// toggled one, which each press of its input flips while enabled and which
// ends whenever the bridge is not. When the binding that drives drive or
// pivot changes (a layer entered or left), or the bridge becomes enabled, the
// byte stays at the mapping's centre (its trim) until that binding's stick is
// seen inside its deadzone at a frame (centre_watch.hpp). The speed level
// (the mapping's `scale:`) likewise: the oracle keeps the levels it may be at
// (SpeedLevels), and where a frame's presses surely changed it, drive and
// pivot wait for their sticks at rest too; at every enabled frame they stay
// within the fastest possible level's range. Lenient where the engine holds
// back more (a stick read by two bindings, a press whose count is in doubt):
// it only ever says "must be at centre" or "no further than that level".

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <variant>
#include <vector>

#include "andros/mapping/model.hpp"
#include "andros/protocol/frame.hpp"
#include "oracle/centre_watch.hpp"

namespace andros::test {

/// The speed levels the engine may be at (docs/mapping.md, `scale`: speed
/// levels), as indices into the mapping's `scale.levels`, from the script's
/// presses: only presses while enabled count, not in the frame of the
/// enabling press, nor of a button held since before it until seen released;
/// `button` steps up and wraps from the fastest to the slowest, `down` steps
/// down and stops at the slowest; a new controller or engine starts at
/// `initial`. Lenient where a count is in doubt (frames missed, a button held
/// through the enabling press): every level it could have reached.
class SpeedLevels {
 public:
  /// At the frame on mapping m: a new engine or controller since the last one starts at the initial level.
  void follow(const mapping::Mapping& m) {
    if (m_ == &m && !afresh_) return;
    m_ = &m;
    afresh_ = false;
    levels_ = 1U << m.scale.initial;
  }
  /// A new controller (either pad) or the mapping read afresh: the initial level at the next frame.
  void afresh() { afresh_ = true; }
  /// A frame while not enabled: the engine may have started afresh (a stop's reset); a release keeps the level.
  void not_enabled(const mapping::Mapping& m) {
    follow(m);
    levels_ |= 1U << m.scale.initial;
  }
  /// An enabled frame: `up` and `down` presses since the last one (in_doubt: whether they counted).
  /// True when the level surely changed.
  bool step(std::uint32_t up, std::uint32_t down, bool in_doubt) {
    const std::size_t n = m_->scale.levels.size();
    const auto next = [n](std::size_t l, std::uint32_t u, std::uint32_t d) {
      l = (l + u) % n;
      return l - std::min<std::size_t>(l, d);
    };
    std::uint32_t after = 0;
    bool changed = true;
    for (std::size_t l = 0; l < n; ++l) {
      if ((levels_ & (1U << l)) == 0) continue;
      if (!in_doubt) {
        const auto to = next(l, up, down);
        after |= 1U << to;
        changed = changed && to != l;
        continue;
      }
      for (std::uint32_t u = 0; u <= up; ++u)
        for (std::uint32_t d = 0; d <= down; ++d) after |= 1U << next(l, u, d);
    }
    levels_ = after;
    return !in_doubt && changed && (up != 0 || down != 0);
  }
  /// The fastest level it may be at, as a fraction of full speed.
  [[nodiscard]] double fastest() const {
    double s = 0.0;
    for (std::size_t l = 0; l < m_->scale.levels.size(); ++l)
      if ((levels_ & (1U << l)) != 0) s = m_->scale.levels[l];
    return s;
  }

 private:
  const mapping::Mapping* m_ = nullptr;
  bool afresh_ = false;
  std::uint32_t levels_ = 0;  ///< bit l: level l possible
};

class LayerRest {
 public:
  static constexpr int kHeldAxis = 16384;  ///< a layer's axis input held: half its travel, as the engine rounds it

  /// A button press on the operator's pad (at an event the loop applies).
  void pressed(input::InputKey key) { ++presses_[key]; }
  /// Anything that makes the engine start afresh or count presses anew (a
  /// controller, the link, a suspend, a reload, a stop): toggles are off and
  /// the presses so far are history.
  void interrupted() {
    presses_.clear();
    toggled_ = -1;
    restart_ = true;
  }
  /// A new controller on either pad, or a reload's engine: the initial speed level.
  void new_session() { speed_.afresh(); }

  /// One delivered frame at tick t of a script on mapping m: empty, or the rule it breaks.
  template <typename Held, typename AxisValue>
  std::string frame(std::int64_t t, std::int64_t period, const mapping::Mapping& m, const protocol::ControlState& s,
                    const Held& held, const AxisValue& axis_value) {
    const bool enabled = s[protocol::signal_id("safety")] != 0;
    const bool enabling = restart_ || !was_enabled_;
    const bool restart = enabling || t != last_t_ + period;
    // [rule: speed-rest] a change of level is a change of meaning: drive and pivot wait for their sticks at rest
    const bool new_level = enabled && speed_levels(m, enabling, restart, held);
    if (!enabled) speed_.not_enabled(m);
    if (enabled) {
      for (std::size_t i = 0; i < m.layers.size(); ++i) {
        const auto& layer = m.layers[i];
        if (!layer.toggle || !layer.input.key.is_button()) continue;
        for (auto n = presses_[layer.input.key]; n > 0; --n)
          toggled_ = toggled_ == static_cast<int>(i) ? -1 : static_cast<int>(i);
      }
    } else {
      toggled_ = -1;
    }
    presses_.clear();
    int layer = toggled_;
    for (std::size_t i = 0; i < m.layers.size(); ++i) {
      const auto key = m.layers[i].input.key;
      if (!m.layers[i].toggle && (key.is_button() ? held(key) : axis_value(key) >= kHeldAxis)) {
        layer = static_cast<int>(i);
        break;
      }
    }
    if (enabled && (restart || layer != layer_)) changed_t_ = t;
    layer_ = enabled ? layer : -1;
    const std::string name = layer < 0 ? "" : m.layers[static_cast<std::size_t>(layer)].name;
    std::string broken;
    held_at_trim_ = false;
    for (std::size_t k = 0; k < kCentred.size(); ++k) {
      const auto id = kCentred[k];
      const mapping::Binding* driver = enabled ? centre_driver(m, name, id) : nullptr;
      const bool must = watch_[k].must_centre(driver, restart || new_level, axis_value);
      if (enabled && broken.empty()) broken = within_level(m, id, s[id]);
      if (!enabled || !must) continue;
      if (driver != nullptr) held_at_trim_ = true;
      if (s[id] != m.center && broken.empty()) {
        broken = std::string(protocol::info(id).name) + " = " + std::to_string(s[id]) + ", not the centre " +
                 std::to_string(m.center) + ", before its stick was seen at rest (layer \"" + name +
                 "\", just enabled, or a new speed level)";
      }
    }
    was_enabled_ = enabled;
    restart_ = false;
    last_t_ = t;
    return broken;
  }

  /// The last frame had drive or pivot held at the centre by the rule.
  [[nodiscard]] bool held_at_trim() const { return held_at_trim_; }
  /// The layer in force at the last frame (its index in the mapping's layers; -1: the base layer, or not enabled).
  [[nodiscard]] int layer() const { return layer_; }
  /// The tick of the last change of meaning: the bridge enabled, or the layer in force changed.
  [[nodiscard]] std::int64_t changed_at() const { return changed_t_; }

 private:
  static constexpr std::array<protocol::SignalId, 2> kCentred = {protocol::signal_id("drive"),
                                                                 protocol::signal_id("pivot")};

  // The speed level at an enabled frame: the presses of its buttons since the
  // last frame count unless this frame enables (enabling) or a button was held
  // since the enabling press; restart: frames missed, the counts in doubt.
  // True when the level surely changed.
  template <typename Held>
  bool speed_levels(const mapping::Mapping& m, bool enabling, bool restart, const Held& held) {
    speed_.follow(m);
    const std::array<std::optional<mapping::InputUse>, 2> keys = {m.scale.up, m.scale.down};
    std::array<std::uint32_t, 2> n{};
    bool in_doubt = restart && !enabling;
    if (enabling) speed_held_.clear();
    for (std::size_t i = 0; i < keys.size(); ++i) {
      if (!keys[i]) continue;
      const auto key = keys[i]->key;
      if (enabling && held(key)) speed_held_.insert(key);
      if (!held(key) && speed_held_.erase(key) != 0 && presses_[key] != 0) in_doubt = true;
      if (speed_held_.contains(key) && presses_[key] != 0) in_doubt = true;
      n[i] = enabling ? 0 : presses_[key];
    }
    return speed_.step(n[0], n[1], in_doubt);
  }
  // [rule: speed-levels] drive or pivot no further from the trim than the fastest level the engine may be at
  // (c + round(s (255 - c)) forward, c - round(s c) back: docs/mapping.md, `scale`).
  std::string within_level(const mapping::Mapping& m, protocol::SignalId id, std::uint8_t value) const {
    const double s = speed_.fastest();
    const int c = m.center;
    const int high = c + static_cast<int>(std::round(s * (255 - c)));
    const int low = c - static_cast<int>(std::round(s * c));
    if (value <= high && value >= low) return {};
    return std::string(protocol::info(id).name) + " = " + std::to_string(value) + ", beyond the speed level " +
           std::to_string(s) + "'s range " + std::to_string(low) + ".." + std::to_string(high) +
           " (up wraps to the slowest, down stops there, a new controller or engine starts at the initial level)";
  }

  SpeedLevels speed_;
  std::set<input::InputKey> speed_held_;  ///< speed buttons held since the enabling press, not yet seen released
  std::map<input::InputKey, std::uint32_t> presses_;  ///< since the last frame
  int toggled_ = -1;
  int layer_ = -1;
  std::int64_t changed_t_ = -1;
  bool restart_ = true;
  bool was_enabled_ = false;
  bool held_at_trim_ = false;
  std::int64_t last_t_ = -1;
  std::array<CentreWatch, 2> watch_{};
};

/// The signals of a frame come from the layer in force (docs/mapping.md,
/// Layers: one layer is active at a time, its bindings plus the base ones):
/// a momentary bit (a button's or a pair's, not a toggle's) that is 1 has a
/// binding in the base layer or in the layer in force (layer, as
/// LayerRest::layer() says). Lenient: any base binding counts, replaced or
/// not. Empty, or the rule broken.
inline std::string layer_signal_errors(const mapping::Mapping& m, int layer, const protocol::ControlState& s) {
  std::array<bool, protocol::kSignalCount> momentary{};  // bound momentarily anywhere in the mapping
  std::array<bool, protocol::kSignalCount> in_force{};   // bound so in the base layer or the layer in force
  const auto mark = [](const std::vector<mapping::Binding>& bindings, std::array<bool, protocol::kSignalCount>& into) {
    for (const auto& b : bindings) {
      if (const auto* button = std::get_if<mapping::ButtonBinding>(&b.rule); button != nullptr && !button->toggle)
        into[button->signal] = true;
      if (const auto* pair = std::get_if<mapping::PairBinding>(&b.rule); pair != nullptr)
        for (const auto id : pair->signals) into[id] = true;
    }
  };
  mark(m.bindings, momentary);
  for (const auto& l : m.layers) mark(l.bindings, momentary);
  mark(m.bindings, in_force);
  if (layer >= 0) mark(m.layers[static_cast<std::size_t>(layer)].bindings, in_force);
  for (std::size_t i = 0; i < protocol::kSignalCount; ++i) {
    if (s.values[i] == 0 || !momentary[i] || in_force[i]) continue;
    const std::string name =
        layer < 0 ? "the base layer" : "layer \"" + m.layers[static_cast<std::size_t>(layer)].name + "\"";
    return std::string(protocol::kSignals[i].name) + " = 1, bound in no binding of " + name +
           ", the layer in force (a toggled layer ends with the deadman)";
  }
  return {};
}

/// Of an opposing pair asked for both, neither is sent (docs/mapping.md,
/// the safety rules: "when both are asked for, neither is sent"). Asked: a
/// button binding of the signal active in the layer in force (the layer's
/// bindings and the base ones whose inputs it does not take), its button held
/// and pressed after the last change of meaning (changed_at: the rest rule
/// holds back a button held through one). Lenient: bindings of axes are left
/// out. Empty, or the rule broken.
template <typename Held, typename PressedAt>
std::string pair_neither_errors(const mapping::Mapping& m, int layer, std::int64_t changed_at,
                                const protocol::ControlState& s, const Held& held, const PressedAt& pressed_at) {
  std::array<bool, protocol::kSignalCount> asked{};
  const std::vector<mapping::Binding>* own = layer < 0 ? nullptr : &m.layers[static_cast<std::size_t>(layer)].bindings;
  const auto taken = [own](input::InputKey key) {
    return own != nullptr && std::any_of(own->begin(), own->end(), [key](const mapping::Binding& b) {
             return (b.arm && b.arm->key == key) ||
                    std::any_of(b.inputs.begin(), b.inputs.end(),
                                [key](const mapping::InputUse& u) { return u.key == key; });
           });
  };
  const auto ask = [&](const mapping::Binding& b, bool base) {
    const auto* button = std::get_if<mapping::ButtonBinding>(&b.rule);
    if (button == nullptr || button->toggle || button->invert || !button->input.is_button()) return;
    if (base && taken(button->input)) return;
    if (held(button->input) && pressed_at(button->input) > changed_at) asked[button->signal] = true;
  };
  for (const auto& b : m.bindings) ask(b, true);
  if (own != nullptr)
    for (const auto& b : *own) ask(b, false);
  for (std::size_t i = 0; i < protocol::kSignalCount; ++i) {
    const auto partner = protocol::partner_of(static_cast<protocol::SignalId>(i));
    if (!partner || !asked[i] || !asked[*partner] || (s.values[i] == 0 && s.values[*partner] == 0)) continue;
    return std::string(protocol::kSignals[i].name) + " and " + std::string(protocol::kSignals[*partner].name) +
           " both asked for, and one of them sent (an opposing pair: neither)";
  }
  return {};
}

/// A weapon fires only on a press of its fire button after the weapon became
/// possible (docs/mapping.md, Weapon: a button already held when the bridge
/// becomes enabled, when a layer with the weapon is entered, or when `arm` is
/// pressed does nothing until released and pressed again): a weapon bit that
/// is 1 has a binding in the base layer or the layer in force whose fire
/// button was pressed after the last change of meaning (changed_at) and
/// after its arming input was last pressed or squeezed. Lenient: a press in
/// the same frame as the arming's counts whichever came first (the engine
/// reads the arming input at the tick: an arming trigger let go and squeezed
/// again within one frame is no new arming to it). Empty, or the rule broken.
template <typename PressedAt>
std::string fire_fresh_errors(const mapping::Mapping& m, int layer, std::int64_t changed_at, std::int64_t period,
                              const protocol::ControlState& s, const PressedAt& pressed_at) {
  const auto tick_of = [period](std::int64_t t) { return (t + period - 1) / period; };
  for (std::size_t i = 0; i < protocol::kSignalCount; ++i) {
    if (protocol::kSignals[i].kind != protocol::SignalKind::kWeapon || s.values[i] == 0) continue;
    bool bound = false;
    bool fresh = false;
    const auto look = [&](const std::vector<mapping::Binding>& bindings) {
      for (const auto& b : bindings) {
        const auto* w = std::get_if<mapping::WeaponBinding>(&b.rule);
        if (w == nullptr || w->signal != i || !w->arm) continue;
        bound = true;
        const auto fired = pressed_at(w->input);
        const auto armed = pressed_at(*w->arm);
        fresh = fresh || (fired > changed_at && (fired > armed || tick_of(fired) == tick_of(armed)));
      }
    };
    look(m.bindings);
    if (layer >= 0) look(m.layers[static_cast<std::size_t>(layer)].bindings);
    if (bound && !fresh)
      return std::string(protocol::kSignals[i].name) +
             " = 1 with its fire button not pressed after the weapon became possible (enabled, its layer entered, "
             "armed)";
  }
  return {};
}

/// The supervisor's consent is fresh and held, never latched (docs/mapping.md,
/// The supervisor's controller: a consent held since before the bridge
/// became enabled in a layer with weapons, such a layer was entered or either
/// controller came counts only once released and pressed again; pressed in
/// the frame of that change it counts; consent is part of arming, so a fire
/// button held when the consent comes waits until released): with the
/// mapping's `weapons_consent`, a weapon bit that is 1 has the consent last
/// pressed after the tick before the last change of meaning (changed_at,
/// which a controller's coming precedes), and a binding in the base layer or
/// the layer in force whose fire button was pressed at or after that press.
/// Empty, or the rule broken.
template <typename PressedAt>
std::string consent_fresh_errors(const mapping::Mapping& m, int layer, std::int64_t changed_at, std::int64_t period,
                                 const protocol::ControlState& s, const PressedAt& pressed_at,
                                 std::int64_t consent_at) {
  if (!m.supervisor || !m.supervisor->weapons_consent) return {};
  for (std::size_t i = 0; i < protocol::kSignalCount; ++i) {
    if (protocol::kSignals[i].kind != protocol::SignalKind::kWeapon || s.values[i] == 0) continue;
    const std::string name(protocol::kSignals[i].name);
    if (consent_at <= changed_at - period)
      return name +
             " = 1 with the supervisor's consent held since before the weapon became possible (not pressed "
             "afresh)";
    bool fresh = false;
    const auto look = [&](const std::vector<mapping::Binding>& bindings) {
      for (const auto& b : bindings) {
        const auto* w = std::get_if<mapping::WeaponBinding>(&b.rule);
        if (w != nullptr && w->signal == i && pressed_at(w->input) >= consent_at) fresh = true;
      }
    };
    look(m.bindings);
    if (layer >= 0) look(m.layers[static_cast<std::size_t>(layer)].bindings);
    if (!fresh) return name + " = 1 with its fire button held when the supervisor's consent came";
  }
  return {};
}

}  // namespace andros::test
