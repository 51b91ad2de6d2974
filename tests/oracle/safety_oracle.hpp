#pragma once
// The fault simulation's oracle: the contract's safety rules (section 5;
// docs/mapping.md, docs/safety-states.md) and docs/event-scripts.md's fault
// events, read off an event script and the frames a replay delivered, never
// the engine, the Bridge or the state machine. From the script
// (script_reading.hpp) it says when the bridge may be enabled (a fresh
// deadman press after the last event that ends "enabled", held since, pads
// connected, link up, not suspended or stopping, no stop latched and not
// reset since (stop_latch.hpp), no deadman let go since the last tick
// (deadman_ticks.hpp), not past a trigger's panic point, not timed out) and
// when frames may go out (loop_schedule.hpp); from the mappings
// (possible_mappings.hpp) the inputs those need, and the stop buttons,
// deadman, reset hold, layers and trim of the one in force (layer_rest.hpp).
// Every frame is valid with the code and no opposing pair, weapons only when
// allowed, neutral (drive and pivot 128 whatever the trim) when not enabled,
// drive and pivot at the trim after a change of layer until their stick was
// seen at rest. It is more permissive than the engine where the engine has
// further rules (a trigger's full release after a panic, a press and a fault
// within one frame): a complaint is a broken rule, not a difference of detail.

#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "andros/input/events.hpp"
#include "andros/mapping/model.hpp"
#include "andros/protocol/frame.hpp"
#include "oracle/coverage.hpp"
#include "oracle/frame_rules.hpp"
#include "oracle/script_reading.hpp"

namespace andros::test {

class SafetyOracle {
 public:
  using Lookup = ScriptReading::Lookup;

  struct Options {
    bool weapons = false;      ///< --weapons
    std::uint8_t code = 0x01;  ///< --code
    LoopOptions loop{};        ///< the rate and the neutral frames owed
  };

  SafetyOracle(const mapping::Mapping& initial, std::vector<input::InputEvent> script, Lookup lookup, Options options)
      : script_(std::move(script)),
        options_(options),
        // A script that addresses the supervisor's controller anywhere is supervised from its start.
        supervised_(std::any_of(script_.begin(), script_.end(),
                                [](const input::InputEvent& e) { return e.pad == input::Pad::kSupervisor; })),
        reading_(initial, std::move(lookup), options.loop, supervised_) {
    // The last frame is the first at or after the `end` (or the last event).
    end_tick_ = script_.empty() ? 0 : reading_.loop().tick_of(script_.back().t_ms);
  }

  /// Each delivered frame, in order: empty, or the rule it breaks.
  std::string frame(std::int64_t t, const protocol::DataBytes& data) {
    const std::int64_t period = options_.loop.period_ms;
    ++coverage_.frames;
    if (supervised_) ++coverage_.supervised_frames;
    if (reading_.mappings().current->center != kNeutralCentre) ++coverage_.trimmed;
    // [rule: grid]
    if (t % period != 0) return "a frame off the " + std::to_string(period) + " ms grid";
    if (t <= last_t_) return "frame times not increasing (previous " + std::to_string(last_t_) + ")";
    if (auto missing = missing_before(t); !missing.empty()) return missing;
    advance_to(t);
    reading_.at_tick(t);
    last_t_ = t;
    const auto s = protocol::read_signals(data);
    if (auto broken = frame_errors(data, s, options_.code); !broken.empty()) return broken;

    const auto d = reading_.loop().deliver(t, end_tick_);
    if (d.suspend_frame) ++coverage_.suspend_frames;
    if (!d.error.empty()) return d.error;
    if (d.reload_frame) ++coverage_.reload_frames;
    // What must be neutral: a reload's, a suspend's or a stop's frames, past the end, not enabled.
    const std::string why = !d.neutral.empty()   ? d.neutral
                            : reading_.enabled() ? std::string()
                                                 : "not enabled (" + reading_.not_enabled_reason() + ")";
    const auto& pads = reading_.pads();
    const auto armed = [this, &pads](protocol::SignalId id) { return reading_.mappings().armed(id, pads); };
    // [rule: neutral-unless-enabled]
    const auto& sup = reading_.mappings().current->supervisor;
    const bool consent = !sup || !sup->weapons_consent || pads.sup_held(sup->weapons_consent->key);
    if (auto fired = weapon_errors(s, options_.weapons, why, armed, consent, coverage_.weapons); !fired.empty())
      return fired;
    if (const auto moving = motion(s)) {
      // [rule: stop-actuated] ISO 13850: a stop device stops whenever it is actuated, whatever came before.
      if (reading_.stop_actuated()) return *moving + " while a stop button is pressed or held";
      if (!why.empty()) return *moving + " while " + why;
      ++coverage_.motion;
      ++coverage_.motion_after[static_cast<std::size_t>(reading_.pressed_after())];
    }
    // [rule: toggles]
    for (std::size_t i = 0; i < protocol::kSignalCount; ++i) {
      if (s.values[i] == 0 || reading_.toggle_may_be_on(static_cast<protocol::SignalId>(i))) continue;
      return std::string(protocol::kSignals[i].name) +
             " = 1 with no press of its toggle since the bridge became enabled (a toggle ends with the deadman)";
    }
    const auto held = [&pads](input::InputKey k) { return pads.held(k); };
    const auto axis = [&pads](input::InputKey k) { return pads.axis(k); };
    auto& rest = reading_.rest();
    const auto& m = *reading_.mappings().current;
    // [rule: rest]
    auto broken = rest.frame(t, period, m, s, held, axis);
    coverage_.rest_held += rest.held_at_trim() ? 1 : 0;
    if (!broken.empty()) return broken;
    // [rule: layer-in-force]
    if (auto wrong = layer_signal_errors(m, rest.layer(), s); !wrong.empty()) return wrong;
    // [rule: pairs-neither]
    const auto pressed_at = [this](input::InputKey k) { return reading_.pressed_at(k); };
    if (auto both = pair_neither_errors(m, rest.layer(), rest.changed_at(), s, held, pressed_at); !both.empty())
      return both;
    // [rule: fire-fresh]
    if (auto early = fire_fresh_errors(m, rest.layer(), rest.changed_at(), period, s, pressed_at); !early.empty())
      return early;
    // [rule: consent-fresh]
    const auto consent_at = m.supervisor && m.supervisor->weapons_consent
                                ? reading_.sup_pressed_at(m.supervisor->weapons_consent->key)
                                : std::int64_t{-1};
    return consent_fresh_errors(m, rest.layer(), rest.changed_at(), period, s, pressed_at, consent_at);
  }

  /// After the replay: what the end lacks. A stop owes its neutral frames at
  /// the tick that sees it and the next two, when the link is up for them.
  std::string finish() {
    if (auto missing = missing_before(end_tick_ + options_.loop.period_ms); !missing.empty()) return missing;
    advance_to(end_tick_);
    // [rule: stop-frames]
    const bool owed = reading_.loop().stop_owed_frames(script_, end_tick_);
    if (owed) ++coverage_.stops_with_frames;
    return owed ? reading_.loop().stop_frames_missing() : std::string();
  }

  /// After a frame at t: a stop latched at t and not reset.
  [[nodiscard]] bool stop_latched() const { return reading_.stop_latched(); }

  /// The frames' counts and the script's (its stop latches, resets, panics, timeouts).
  [[nodiscard]] OracleCoverage coverage() const {
    OracleCoverage all = coverage_;
    all += reading_.counts();
    return all;
  }

 private:
  void advance_to(std::int64_t t) {
    while (next_ < script_.size() && script_[next_].t_ms <= t) reading_.apply(script_[next_++]);
  }

  // Every tick up to the script's end gets a frame while the link is up and
  // nothing holds the loop (a suspend once its neutral frames are out, a
  // stop): none is lost on the way, a suspend's own neutral frames included.
  std::string missing_before(std::int64_t t) {
    const std::int64_t period = options_.loop.period_ms;
    for (std::int64_t u = last_t_ < 0 ? 0 : last_t_ + period; u < t && u <= end_tick_; u += period) {
      advance_to(u);
      reading_.at_tick(u);
      const auto& loop = reading_.loop();
      // [rule: suspend-frames]
      if (loop.link_up() && loop.suspending(u) && !loop.stopped())
        return "no frame at t=" + std::to_string(u) + " (the link up, one of a suspend's neutral frames owed)";
      // [rule: no-frame-lost]
      if (loop.link_up() && !loop.suspended() && !loop.stopped())
        return "no frame at t=" + std::to_string(u) + " (the link up, not suspended, not stopping)";
    }
    return {};
  }

  std::vector<input::InputEvent> script_;
  Options options_;
  bool supervised_ = false;
  ScriptReading reading_;
  std::size_t next_ = 0;
  std::int64_t end_tick_ = 0;
  std::int64_t last_t_ = -1;
  OracleCoverage coverage_;  ///< the frames' (the script's are the reading's)
};

}  // namespace andros::test
