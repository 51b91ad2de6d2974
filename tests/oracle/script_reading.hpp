#pragma once
// What the fault simulation's oracle (safety_oracle.hpp) reads off an event
// script, event by event and tick by tick, never off the engine, the Bridge or
// the state machine: when the bridge may be enabled (a fresh deadman press
// after the last event that ends "enabled", held since, pads connected, link
// up, not suspended or stopping, no stop latched and not reset since
// (stop_latch.hpp), no deadman let go since the last tick
// (deadman_ticks.hpp), not past a trigger's panic point, not timed out), what
// the loop owes around its faults (loop_schedule.hpp), the mappings
// (possible_mappings.hpp) and the layers of the one in force (layer_rest.hpp).

#include <algorithm>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "andros/input/events.hpp"
#include "andros/mapping/model.hpp"
#include "oracle/axis_activity.hpp"
#include "oracle/coverage.hpp"
#include "oracle/deadman_ticks.hpp"
#include "oracle/layer_rest.hpp"
#include "oracle/loop_schedule.hpp"
#include "oracle/pads.hpp"
#include "oracle/possible_mappings.hpp"
#include "oracle/stop_latch.hpp"

namespace andros::test {

class ScriptReading {
 public:
  /// A reload's FILE: the mapping it loads, or nullptr for one that does not.
  using Lookup = std::function<const mapping::Mapping*(const std::string& file)>;

  /// supervised: the script addresses the supervisor's controller anywhere (supervised from its start).
  ScriptReading(const mapping::Mapping& initial, Lookup lookup, LoopOptions loop, bool supervised)
      : lookup_(std::move(lookup)), loop_(loop), period_ms_(loop.period_ms), supervised_(supervised) {
    mappings_.add(initial);
  }

  // What every tick reads once its events are in: a reload's mapping in
  // force once the reload is done; the stop latch, on the stop buttons and
  // the deadman of the mapping in force; a deadman let go since the last
  // tick; the panic point (reached now, or since the last tick even if back)
  // and the timeout (from the tick of the last change of any input, or the
  // tick that enabled: the next one after a deadman let go and pressed again
  // within a tick) end "enabled". The panic's "fully released" is the replay
  // tests' to check: here a fresh squeeze from below the press point is
  // enough (permissive).
  void at_tick(std::int64_t t) {
    take_up(t);
    const mapping::Mapping& m = *mappings_.current;
    const bool deadman_down = pads_.connected && m.deadman && pads_.down(m.deadman->key);
    // (A resume in this tick: its rebase takes the presses; one during a suspend's neutral frames is answered
    // after them.)
    const bool in_stopped =
        !loop_.suspended() && !loop_.suspending(t) && !loop_.stopped() && !loop_.reloading(t) && !resumed_this_tick_;
    const auto outcome = stop_.at_tick(t, {.reads_stops = !loop_.stopped(),
                                           .in_stopped = in_stopped,
                                           .connected = pads_.connected,
                                           .sup_connected = pads_.sup_connected,
                                           .touched = deadman_.touched(m, deadman_down),
                                           .hold_ms = m.stop_reset_hold_ms});
    switch (outcome) {
      case StopLatch::Outcome::kLatched:
        ++counts_.stop_latches;
        end_enabled(Ending::kStopButton);
        break;
      case StopLatch::Outcome::kOperatorReset:
      case StopLatch::Outcome::kSupervisorReset:
        // A reset: not enabled, afresh (every deadman press so far is history).
        ++(outcome == StopLatch::Outcome::kOperatorReset ? counts_.operator_resets : counts_.supervisor_resets);
        end_enabled(Ending::kReset);
        break;
      case StopLatch::Outcome::kRefused: ++counts_.refused_resets; break;
      case StopLatch::Outcome::kNone: break;
    }
    resumed_this_tick_ = false;
    if (activity_.seen_at_tick(pads_.axes)) last_change_ = std::max(last_change_, t);
    std::set<input::InputKey> held;
    for (const auto k : mappings_.common_deadmen) {
      if (pads_.connected && pads_.down(k)) held.insert(k);
    }
    deadman_.at_tick(deadman_down, std::move(held));
    // Enabling is the first change (at the next tick, at the latest, after a deadman let go since the last one:
    // enabled here by the oracle's reckoning, it may be enabled afresh at the next by the loop's).
    const bool maybe_let_go = deadman_.maybe_let_go_this_tick();
    if (enabled() && (!was_enabled_ || maybe_let_go)) enabled_at_ = t + (maybe_let_go ? period_ms_ : 0);
    // Past the panic point now, or at any moment since the last tick (every change between two ticks counts).
    const bool squeezed = std::exchange(squeezed_since_tick_, false);
    const auto past_panic = [this](input::InputKey k) { return !k.is_button() && pads_.axis(k) >= *mappings_.panic; };
    // [rule: panic]
    if (mappings_.panic && enabled() &&
        (squeezed || std::any_of(mappings_.deadmen.begin(), mappings_.deadmen.end(), past_panic))) {
      ++counts_.panics;
      end_enabled(Ending::kPanic);
    }
    const std::int64_t since = std::max(loop_.tick_of(last_change_), enabled_at_);
    // [rule: timeout]
    if (mappings_.timeout_ms && enabled() && t - since >= *mappings_.timeout_ms) {
      ++counts_.timeouts;
      end_enabled(Ending::kTimeout);
    }
    if (enabled() && !was_enabled_) enabled_since_ = t;
    was_enabled_ = enabled();
  }

  /// A toggle's signal may be 1: its mapping in force toggles it (it is
  /// toggled only: docs/mapping.md refuses a signal both toggled and
  /// momentary) and one of its toggle inputs was pressed since the tick that
  /// enabled (docs/mapping.md, Toggle: "until pressed again or the deadman is
  /// released"; presses while not enabled are ignored), or it is no toggle's.
  [[nodiscard]] bool toggle_may_be_on(protocol::SignalId id) const {
    bool toggled = false;
    bool pressed = false;
    const auto look = [&](const std::vector<mapping::Binding>& bindings) {
      for (const auto& b : bindings) {
        const auto* button = std::get_if<mapping::ButtonBinding>(&b.rule);
        if (button == nullptr || !button->toggle || button->signal != id) continue;
        toggled = true;
        const auto it = pressed_at_.find(button->input);
        pressed = pressed || (it != pressed_at_.end() && it->second > enabled_since_ - period_ms_);
      }
    };
    look(mappings_.current->bindings);
    for (const auto& layer : mappings_.current->layers) look(layer.bindings);
    return !toggled || pressed;
  }

  /// The time of the operator's last press of a button, or squeeze of an axis past half way (-1: none yet).
  [[nodiscard]] std::int64_t pressed_at(input::InputKey key) const {
    const auto it = pressed_at_.find(key);
    return it == pressed_at_.end() ? -1 : it->second;
  }

  /// The time of the supervisor's last press of a button on its pad (-1: none yet).
  [[nodiscard]] std::int64_t sup_pressed_at(input::InputKey key) const {
    const auto it = sup_pressed_at_.find(key);
    return it == sup_pressed_at_.end() ? -1 : it->second;
  }

  void apply(const input::InputEvent& e) {
    using T = input::InputEvent::Type;
    take_up(loop_.tick_of(e.t_ms));  // a reload done at an earlier tick
    if (e.type == T::kLinkDown || e.type == T::kLinkTaken || e.type == T::kLinkUp || e.type == T::kLinkStalled ||
        e.type == T::kLinkReading) {
      // A link that comes back is a new link.
      if (loop_.link(e.type)) {
        if (loop_.carries_motion()) rest_.new_session();  // driving afresh: the initial speed level
        end_enabled(loop_.carries_motion() ? Ending::kLinkUp
                    : loop_.stalled()      ? Ending::kLinkStalled
                                           : Ending::kLinkDown);
      }
      return;
    }
    if (loop_.stopped()) return;  // nothing else is answered once a stop is in
    if (e.pad == input::Pad::kSupervisor) return apply_supervisor(e);
    switch (e.type) {
      case T::kConnect:
      case T::kDisconnect:
        end_enabled(e.type == T::kConnect ? Ending::kConnect : Ending::kDisconnect);
        pads_.connect(e.type == T::kConnect, e.t_ms);
        activity_.at_rest();
        stop_.op = StopInput{};  // a stop tapped on the old session since the last tick went with it
        stop_.op_name = e.type == T::kConnect ? e.name : std::string();
        set_gesture(stop_.op_reset, mappings_.current->stop_reset, {});
        stop_.op_reset.new_session = true;
        if (e.type == T::kConnect) {
          deadman_.new_session();
          rest_.new_session();
        }
        squeezed_since_tick_ = false;  // what the old session did is gone
        last_change_ = e.t_ms;
        break;
      case T::kButton: {
        if (!pads_.connected) break;  // a lost controller's stale events
        const bool was = pads_.buttons[e.key];
        const bool now = e.value != 0;
        pads_.buttons[e.key] = now;
        if (was != now) last_change_ = e.t_ms;
        // Stamped with the connect's time: the state the pad had when it appeared, not a press.
        const bool initial = e.t_ms == pads_.connect_t;
        if (now && !was && !initial) {
          rest_.pressed(e.key);
          pressed_at_[e.key] = e.t_ms;
        }
        const auto& estop = mappings_.current->estop;
        if (estop && e.key == estop->key) stop_.op.moved(now, was, initial);
        stop_.op_reset.moved(e.key, now);
        if (mappings_.deadmen.contains(e.key)) deadman_moved(e.key, was, now, e.t_ms);
        break;
      }
      case T::kAxis: {
        if (!pads_.connected) break;
        const bool was = pads_.down(e.key);
        const bool was_held = pads_.held(e.key);
        pads_.axes[e.key] = e.value;
        if (!was_held && pads_.held(e.key)) pressed_at_[e.key] = e.t_ms;  // an arming trigger squeezed
        if (activity_.moved(e.key, e.value)) last_change_ = e.t_ms;
        if (!mappings_.deadmen.contains(e.key)) break;
        deadman_moved(e.key, was, pads_.down(e.key), e.t_ms);
        if (!e.key.is_button() && mappings_.panic && e.value >= *mappings_.panic) squeezed_since_tick_ = true;
        break;
      }
      case T::kSuspend:
        end_enabled(Ending::kSuspend);
        loop_.suspend(e.t_ms);
        break;
      case T::kResume:
        end_enabled(Ending::kResume);
        resumed_this_tick_ = true;
        if (loop_.suspended()) {
          mappings_.resumed();
          rest_.new_session();  // driving afresh: the initial speed level
        }
        loop_.resume(e.t_ms);
        break;
      case T::kReload: {
        const mapping::Mapping* loaded = e.name.empty() ? nullptr : lookup_(e.name);
        end_enabled(e.name.empty()      ? Ending::kReloadSame
                    : loaded != nullptr ? Ending::kReloadGood
                                        : Ending::kReloadBad);
        // In force once the reload is done; asked for while suspended, it waits for the resume.
        const bool queue = loop_.suspended() && !loop_.reloading(loop_.tick_of(e.t_ms));
        mappings_.reload(loaded, e.name.empty(), queue);
        loop_.reload(e.t_ms);
        break;
      }
      case T::kShutdown:
        end_enabled(Ending::kStop);
        loop_.stop(e.t_ms);
        break;
      default: break;  // hats: the generator sends none; `end`
    }
  }

  // [rule: fresh-press] [rule: stalled-link]
  [[nodiscard]] bool enabled() const {
    if (!pads_.connected || !loop_.carries_motion() || loop_.suspended() || loop_.stopped() || stop_.latched())
      return false;
    if (deadman_.let_go_this_tick()) return false;
    if (supervised_ && !pads_.sup_connected) return false;
    return std::any_of(fresh_.begin(), fresh_.end(), [this](input::InputKey k) { return pads_.down(k); });
  }

  [[nodiscard]] std::string not_enabled_reason() const {
    if (loop_.stopped()) return "stopping";
    if (stop_.latched()) return "stopped by the stop button, not reset";
    if (deadman_.let_go_this_tick()) return "the deadman let go since the last tick";
    if (supervised_ && !pads_.sup_connected) return "no supervisor's controller";
    if (loop_.suspended()) return "suspended";
    if (!loop_.link_up()) return "link down";
    if (loop_.stalled()) return "link stalled (neutral frames only)";
    if (!pads_.connected) return "no controller";
    const auto held = [this](input::InputKey k) { return pads_.held(k); };
    if (std::none_of(mappings_.deadmen.begin(), mappings_.deadmen.end(), held)) return "deadman not held";
    return "deadman held but not pressed since the last " + std::string(to_string(last_ending_));
  }

  /// The loop's schedule (a delivered frame takes one of the neutral frames owed).
  [[nodiscard]] LoopSchedule& loop() { return loop_; }
  [[nodiscard]] const PossibleMappings& mappings() const { return mappings_; }
  [[nodiscard]] const OraclePads& pads() const { return pads_; }
  /// The rest rule, read frame by frame on the mapping in force.
  [[nodiscard]] LayerRest& rest() { return rest_; }
  [[nodiscard]] bool stop_latched() const { return stop_.latched(); }
  /// A stop button of the mapping in force pressed since the last tick, or held, on a connected pad.
  [[nodiscard]] bool stop_actuated() const { return stop_.actuated(); }
  /// The last interruption before the press that enabled.
  [[nodiscard]] Ending pressed_after() const { return pressed_after_; }
  /// What the script reached: stop latches, resets, panics, timeouts, the supervisor's stop presses.
  [[nodiscard]] const OracleCoverage& counts() const { return counts_; }

 private:
  // A reload's mapping is the loop's from the first tick after the reload's
  // frames (asked for while suspended, after the resume): its stop buttons
  // are read as they are held now, by a new engine (nothing held on from a reset).
  void take_up(std::int64_t tick) {
    if (loop_.reload_under_way(tick) || !mappings_.take_up()) return;
    rest_.new_session();  // a new engine
    const auto& m = *mappings_.current;
    stop_.op.down = m.estop && pads_.held(m.estop->key);
    stop_.sup.down = pads_.sup_held(m.supervisor ? std::optional(m.supervisor->stop.key) : std::nullopt);
    set_gesture(stop_.op_reset, m.stop_reset, [this](input::InputKey k) { return pads_.held(k); });
    set_gesture(stop_.sup_reset, m.supervisor ? m.supervisor->reset : std::vector<mapping::InputUse>{},
                [this](input::InputKey k) { return pads_.sup_held(k); });
  }

  // A reset gesture's buttons as the mapping in force has them, each held as
  // `held` says (none: released); the gesture made before is not made afresh.
  static void set_gesture(ResetGesture& g, const std::vector<mapping::InputUse>& uses,
                          const std::function<bool(input::InputKey)>& held) {
    g.keys.clear();
    g.down.clear();
    for (const auto& u : uses) {
      g.keys.push_back(u.key);
      g.down.push_back(held && held(u.key));
    }
    g.close();
    g.let_go = false;
  }

  // Every event that ends "enabled": the press that enables must come after it.
  void end_enabled(Ending why) {
    fresh_.clear();
    last_ending_ = why;
    last_interruption_ = why;
    rest_.interrupted();
  }

  // The supervisor's controller: driving needs it there (a script that
  // addresses it is supervised), its coming and going ends "enabled" (the
  // engine starts afresh), and its stop button latches as the operator's does.
  void apply_supervisor(const input::InputEvent& e) {
    using T = input::InputEvent::Type;
    if (e.type == T::kConnect || e.type == T::kDisconnect) {
      end_enabled(e.type == T::kConnect ? Ending::kConnect : Ending::kDisconnect);
      pads_.connect_supervisor(e.type == T::kConnect, e.t_ms);
      if (e.type == T::kConnect) rest_.new_session();
      stop_.sup = StopInput{};
      stop_.sup_name = e.type == T::kConnect ? e.name : std::string();
      const auto& sup = mappings_.current->supervisor;
      set_gesture(stop_.sup_reset, sup ? sup->reset : std::vector<mapping::InputUse>{}, {});
      stop_.sup_reset.new_session = true;
    } else if (e.type == T::kButton && pads_.sup_connected) {
      const bool was = pads_.sup_buttons[e.key];
      const bool now = e.value != 0;
      pads_.sup_buttons[e.key] = now;
      const bool initial = e.t_ms == pads_.sup_connect_t;
      if (now && !was && !initial) sup_pressed_at_[e.key] = e.t_ms;
      counts_.supervisor_stops += e.key == mappings_.sup_stop && now && !was && !initial ? 1 : 0;
      const auto& sup = mappings_.current->supervisor;
      if (sup && e.key == sup->stop.key) stop_.sup.moved(now, was, initial);
      stop_.sup_reset.moved(e.key, now);
    }
  }

  // A deadman pressed or released (button) or moved across its press point
  // (trigger). A press is fresh made after the last reset, not while stopped.
  void deadman_moved(input::InputKey key, bool was, bool now, std::int64_t t) {
    const bool initial = t == pads_.connect_t;
    if (was != now && !initial) deadman_.moved(key, now, *mappings_.current, mappings_.common_deadmen);
    if (now && !was && !initial && !stop_.latched() && stop_.after_reset(t)) {
      fresh_.insert(key);
      pressed_after_ = last_interruption_;
    }
    if (!now && was) {
      fresh_.erase(key);
      last_ending_ = Ending::kRelease;
    }
  }

  Lookup lookup_;
  LoopSchedule loop_;
  std::int64_t period_ms_;
  PossibleMappings mappings_;
  OraclePads pads_;
  LayerRest rest_;
  bool supervised_ = false;
  StopLatch stop_;
  DeadmanTicks deadman_;
  bool resumed_this_tick_ = false;    ///< a resume since the last tick (its rebase takes the presses)
  AxisActivity activity_;             ///< which axis moves are changes for the timeout
  std::int64_t last_change_ = 0;      ///< the last event that changed an input
  bool squeezed_since_tick_ = false;  ///< a trigger deadman past the panic point since the last tick
  bool was_enabled_ = false;          ///< at the last tick
  std::int64_t enabled_at_ = 0;       ///< the tick that enabled, the last time
  std::int64_t enabled_since_ = 0;    ///< the first tick of the last stretch the oracle found enabled
  std::map<input::InputKey, std::int64_t>
      pressed_at_;  ///< the operator's last press of each button, or squeeze of each axis past half way
  std::map<input::InputKey, std::int64_t> sup_pressed_at_;  ///< the supervisor's last press of each button
  std::set<input::InputKey> fresh_;                         ///< deadmen pressed since the last ending event
  Ending last_ending_ = Ending::kStart;
  Ending last_interruption_ = Ending::kStart;
  Ending pressed_after_ = Ending::kStart;
  OracleCoverage counts_;
};

}  // namespace andros::test
