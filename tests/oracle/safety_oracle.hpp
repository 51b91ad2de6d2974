#pragma once
// The fault simulation's oracle: the contract's safety rules (section 5;
// docs/mapping.md, docs/safety-states.md) and docs/event-scripts.md's fault
// events, read off an event script and the frames a replay delivered, never
// the engine, the Bridge or the state machine. From the script it says when
// the bridge may be enabled (a fresh deadman press after the last event that
// ends "enabled", held since, pads connected, link up, not suspended or
// stopping, no stop latched (stop_latch.hpp), not past a trigger's panic
// point, not timed out) and when frames may go out (loop_schedule.hpp); from
// the mappings (possible_mappings.hpp) the inputs those need, and the layers
// and trim of the one in place (layer_rest.hpp). Every frame is valid with
// the code and no opposing pair, weapons only when allowed, neutral (drive
// and pivot 128 whatever the trim) when not enabled, drive and pivot at the
// trim after a change of layer until their stick was seen at rest. It is
// more permissive than the engine where the engine has further rules (a
// press and a fault within one frame, how a stop is reset): a complaint is a
// broken rule, not a difference of detail.

#include <algorithm>
#include <cstdint>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "andros/input/events.hpp"
#include "andros/mapping/model.hpp"
#include "andros/protocol/frame.hpp"
#include "oracle/coverage.hpp"
#include "oracle/frame_rules.hpp"
#include "oracle/layer_rest.hpp"
#include "oracle/loop_schedule.hpp"
#include "oracle/pads.hpp"
#include "oracle/possible_mappings.hpp"
#include "oracle/stop_latch.hpp"

namespace andros::test {

class SafetyOracle {
 public:
  /// A reload's FILE: the mapping it loads, or nullptr for one that does not.
  using Lookup = std::function<const mapping::Mapping*(const std::string& file)>;

  struct Options {
    bool weapons = false;      ///< --weapons
    std::uint8_t code = 0x01;  ///< --code
    LoopOptions loop{};        ///< the rate and the neutral frames owed
  };

  SafetyOracle(const mapping::Mapping& initial, std::vector<input::InputEvent> script, Lookup lookup, Options options)
      : script_(std::move(script)), lookup_(std::move(lookup)), options_(options), loop_(options.loop) {
    mappings_.add(initial);
    // A script that addresses the supervisor's controller anywhere is supervised from its start.
    supervised_ = std::any_of(script_.begin(), script_.end(),
                              [](const input::InputEvent& e) { return e.pad == input::Pad::kSupervisor; });
    // The last frame is the first at or after the `end` (or the last event).
    end_tick_ = script_.empty() ? 0 : loop_.tick_of(script_.back().t_ms);
  }

  /// Each delivered frame, in order: empty, or the rule it breaks.
  std::string frame(std::int64_t t, const protocol::DataBytes& data) {
    const std::int64_t period = options_.loop.period_ms;
    ++coverage_.frames;
    if (supervised_) ++coverage_.supervised_frames;
    if (mappings_.known && mappings_.current->center != kNeutralCentre) ++coverage_.trimmed;
    if (t % period != 0) return "a frame off the " + std::to_string(period) + " ms grid";
    if (t <= last_t_) return "frame times not increasing (previous " + std::to_string(last_t_) + ")";
    if (auto missing = missing_before(t); !missing.empty()) return missing;
    advance_to(t);
    at_tick(t);
    last_t_ = t;
    const auto s = protocol::read_signals(data);
    if (auto broken = frame_errors(data, s, options_.code); !broken.empty()) return broken;

    const auto d = loop_.deliver(t, end_tick_);
    if (d.suspend_frame) ++coverage_.suspend_frames;
    if (!d.error.empty()) return d.error;
    if (d.reload_frame) ++coverage_.reload_frames;
    // What must be neutral: a reload's, a suspend's or a stop's frames, past the end, not enabled.
    const std::string why = !d.neutral.empty() ? d.neutral
                            : enabled()        ? std::string()
                                               : "not enabled (" + not_enabled_reason() + ")";
    const auto armed = [this](protocol::SignalId id) { return mappings_.armed(id, pads_); };
    if (auto fired = weapon_errors(s, options_.weapons, why, armed, coverage_.weapons); !fired.empty()) return fired;
    if (const auto moving = motion(s)) {
      if (!why.empty()) return *moving + " while " + why;
      ++coverage_.motion;
      ++coverage_.motion_after[static_cast<std::size_t>(pressed_after_)];
    }
    if (!mappings_.known) return {};
    const auto held = [this](input::InputKey k) { return pads_.held(k); };
    auto rest =
        rest_.frame(t, period, *mappings_.current, s, held, [this](input::InputKey k) { return pads_.axis(k); });
    coverage_.rest_held += rest_.held_at_trim() ? 1 : 0;
    return rest;
  }

  /// After the replay: what the end lacks. A stop owes its neutral frames at
  /// the tick that sees it and the next two, when the link is up for them.
  std::string finish() {
    if (auto missing = missing_before(end_tick_ + options_.loop.period_ms); !missing.empty()) return missing;
    advance_to(end_tick_);
    const bool owed = loop_.stop_owed_frames(script_, end_tick_);
    if (owed) ++coverage_.stops_with_frames;
    return owed ? loop_.stop_frames_missing() : std::string();
  }

  [[nodiscard]] const OracleCoverage& coverage() const { return coverage_; }

 private:
  void advance_to(std::int64_t t) {
    while (next_ < script_.size() && script_[next_].t_ms <= t) apply(script_[next_++]);
  }

  // Every tick up to the script's end gets a frame while the link is up and
  // nothing holds the loop (a suspend, a stop): none is lost on the way.
  std::string missing_before(std::int64_t t) {
    const std::int64_t period = options_.loop.period_ms;
    for (std::int64_t u = last_t_ < 0 ? 0 : last_t_ + period; u < t && u <= end_tick_; u += period) {
      advance_to(u);
      at_tick(u);
      if (loop_.link_up() && !loop_.suspended() && !loop_.stopped())
        return "no frame at t=" + std::to_string(u) + " (the link up, not suspended, not stopping)";
    }
    return {};
  }

  // What every tick reads once its events are in: the stop latch; the panic point and the timeout
  // (from the tick of the last change of any input) end "enabled" (a squeeze and back within a tick is not seen).
  void at_tick(std::int64_t t) {
    const bool may_clear = pads_.connected && !loop_.suspended() && !loop_.stopped() && !loop_.reloading(t) &&
                           std::none_of(mappings_.common_deadmen.begin(), mappings_.common_deadmen.end(),
                                        [this](input::InputKey k) { return pads_.down(k); });
    const bool held = (mappings_.estop && pads_.held(*mappings_.estop)) || pads_.sup_held(mappings_.sup_stop);
    if (stop_.at_tick(t, held, may_clear)) {
      ++coverage_.stop_latches;
      end_enabled(Ending::kStopButton);
    }
    if (mappings_.panic && enabled()) {
      for (const auto k : mappings_.deadmen) {
        if (!k.is_button() && pads_.axis(k) >= *mappings_.panic) {
          ++coverage_.panics;
          end_enabled(Ending::kPanic);
          break;
        }
      }
    }
    if (mappings_.timeout_ms && enabled() && t - loop_.tick_of(last_change_) >= *mappings_.timeout_ms) {
      ++coverage_.timeouts;
      end_enabled(Ending::kTimeout);
    }
  }

  // Every event that ends "enabled": the press that enables must come after it.
  void end_enabled(Ending why) {
    fresh_.clear();
    last_ending_ = why;
    last_interruption_ = why;
    rest_.interrupted();
  }

  void apply(const input::InputEvent& e) {
    using T = input::InputEvent::Type;
    if (e.type == T::kLinkDown || e.type == T::kLinkTaken || e.type == T::kLinkUp) {
      // A link that comes back is a new link.
      if (loop_.link(e.type)) end_enabled(e.type == T::kLinkUp ? Ending::kLinkUp : Ending::kLinkDown);
      return;
    }
    if (loop_.stopped()) return;  // nothing else is answered once a stop is in
    if (e.pad == input::Pad::kSupervisor) return apply_supervisor(e);
    switch (e.type) {
      case T::kConnect:
      case T::kDisconnect:
        end_enabled(e.type == T::kConnect ? Ending::kConnect : Ending::kDisconnect);
        pads_.connect(e.type == T::kConnect, e.t_ms);
        stop_.pending = false;  // a stop tapped on the old session since the last tick went with it
        stop_.released = true;  // and a stop button held goes with its pad
        last_change_ = e.t_ms;
        break;
      case T::kButton: {
        if (!pads_.connected) break;  // a lost controller's stale events
        const bool was = pads_.buttons[e.key];
        const bool now = e.value != 0;
        pads_.buttons[e.key] = now;
        if (was != now) last_change_ = e.t_ms;
        // Stamped with the connect's time: the state the pad had when it appeared, not a press.
        const bool press = now && !was && e.t_ms != pads_.connect_t;
        if (press) rest_.pressed(e.key);
        if (e.key == mappings_.estop && press) stop_.pending = true;
        if (e.key == mappings_.estop && was && !now) stop_.released = true;
        if (mappings_.deadmen.contains(e.key)) deadman_moved(e.key, was, now, e.t_ms);
        break;
      }
      case T::kAxis: {
        if (!pads_.connected) break;
        const bool was = pads_.down(e.key);
        if (pads_.axis(e.key) != e.value) last_change_ = e.t_ms;
        pads_.axes[e.key] = e.value;
        if (mappings_.deadmen.contains(e.key)) deadman_moved(e.key, was, pads_.down(e.key), e.t_ms);
        break;
      }
      case T::kSuspend:
        end_enabled(Ending::kSuspend);
        loop_.suspend(e.t_ms);
        break;
      case T::kResume:
        end_enabled(Ending::kResume);
        loop_.resume(e.t_ms);
        break;
      case T::kReload: {
        const mapping::Mapping* loaded = e.name.empty() ? nullptr : lookup_(e.name);
        end_enabled(e.name.empty()      ? Ending::kReloadSame
                    : loaded != nullptr ? Ending::kReloadGood
                                        : Ending::kReloadBad);
        if (mappings_.reload(loaded, loop_.reload_pending(e.t_ms))) stop_.released = true;  // a stop button unknown now
        loop_.reload(e.t_ms);
        break;
      }
      case T::kStop:
        end_enabled(Ending::kStop);
        loop_.stop(e.t_ms);
        break;
      default: break;  // hats: the generator sends none; `end`
    }
  }

  // The supervisor's controller: driving needs it there (a script that
  // addresses it is supervised), its coming and going ends "enabled" (the
  // engine starts afresh), and its stop button latches as the operator's does.
  void apply_supervisor(const input::InputEvent& e) {
    using T = input::InputEvent::Type;
    if (e.type == T::kConnect || e.type == T::kDisconnect) {
      end_enabled(e.type == T::kConnect ? Ending::kConnect : Ending::kDisconnect);
      pads_.connect_supervisor(e.type == T::kConnect, e.t_ms);
      stop_.released = true;
    } else if (e.type == T::kButton && pads_.sup_connected) {
      const bool was = pads_.sup_buttons[e.key];
      pads_.sup_buttons[e.key] = e.value != 0;
      if (e.key != mappings_.sup_stop) return;
      const bool press = e.value != 0 && !was && e.t_ms != pads_.sup_connect_t;
      stop_.pending = stop_.pending || press;
      coverage_.supervisor_stops += press ? 1 : 0;
      if (was && e.value == 0) stop_.released = true;
    }
  }

  // A deadman pressed or released (button) or moved across its press point (trigger).
  void deadman_moved(input::InputKey key, bool was, bool now, std::int64_t t) {
    if (now && !was && t != pads_.connect_t && !stop_.latched) {
      fresh_.insert(key);
      pressed_after_ = last_interruption_;
    }
    if (!now && was) {
      fresh_.erase(key);
      last_ending_ = Ending::kRelease;
    }
  }

  [[nodiscard]] bool enabled() const {
    if (!pads_.connected || !loop_.link_up() || loop_.suspended() || loop_.stopped() || stop_.latched) return false;
    if (supervised_ && !pads_.sup_connected) return false;
    return std::any_of(fresh_.begin(), fresh_.end(), [this](input::InputKey k) { return pads_.down(k); });
  }

  [[nodiscard]] std::string not_enabled_reason() const {
    if (loop_.stopped()) return "stopping";
    if (stop_.latched) return "stopped by the stop button";
    if (supervised_ && !pads_.sup_connected) return "no supervisor's controller";
    if (loop_.suspended()) return "suspended";
    if (!loop_.link_up()) return "link down";
    if (!pads_.connected) return "no controller";
    const auto held = [this](input::InputKey k) { return pads_.held(k); };
    if (std::none_of(mappings_.deadmen.begin(), mappings_.deadmen.end(), held)) return "deadman not held";
    return "deadman held but not pressed since the last " + std::string(to_string(last_ending_));
  }

  std::vector<input::InputEvent> script_;
  Lookup lookup_;
  Options options_;
  LoopSchedule loop_;
  PossibleMappings mappings_;
  OraclePads pads_;
  LayerRest rest_;
  std::size_t next_ = 0;
  std::int64_t end_tick_ = 0;
  std::int64_t last_t_ = -1;
  bool supervised_ = false;
  StopLatch stop_;
  std::int64_t last_change_ = 0;     ///< the last event that changed an input
  std::set<input::InputKey> fresh_;  ///< deadmen pressed since the last ending event
  Ending last_ending_ = Ending::kStart;
  Ending last_interruption_ = Ending::kStart;
  Ending pressed_after_ = Ending::kStart;
  OracleCoverage coverage_;
};

}  // namespace andros::test
