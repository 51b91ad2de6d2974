#pragma once
// The fault simulation's oracle: the safety rules (docs/mapping.md, "What a
// mapping cannot change"; docs/safety-states.md) and
// docs/event-scripts.md's fault events, read straight off an event script and
// the frames a replay delivered. It knows nothing of the engine, the Bridge or
// the operating-state machine: from the script alone it says when the bridge
// may be enabled (a fresh deadman press, made after the last event that ends
// "enabled", held since, controller connected, link up, not suspended, not
// stopping, not stopped by a stop button and not reset since, not past the panic
// point of a three-position trigger, not timed out), and when frames may be
// delivered at all; from the mapping only the deadman, the stop button, the
// panic point, the enable timeout and the weapons' arming inputs. It is deliberately more
// permissive than the engine where the engine has further rules (the rest
// rule, layers, a press and a fault within one frame): it never says "may
// not move" where those rules let the bridge move, so a complaint is a
// broken rule, not a difference of detail.

#include <algorithm>
#include <array>
#include <cmath>
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
#include "andros/protocol/frame.hpp"

namespace andros::test {

/// An event that ends "enabled": the last one is what a message names, and
/// the last that is not a deadman release is what the coverage counts motion after.
enum class Ending : std::uint8_t {
  kStart,
  kConnect,
  kDisconnect,
  kRelease,
  kLinkDown,
  kLinkUp,
  kSuspend,
  kResume,
  kReloadSame,
  kReloadGood,
  kReloadBad,
  kStop,
  kStopButton,
  kReset,
  kPanic,
  kTimeout,
  kCount
};

inline const char* to_string(Ending e) {
  constexpr const char* kNames[] = {
      "start",       "connect",    "disconnect",    "deadman release",    "link down",         "link up",
      "suspend",     "resume",     "reload (same)", "reload (good file)", "reload (bad file)", "stop",
      "stop button", "stop reset", "panic squeeze", "enable timeout"};
  return kNames[static_cast<std::size_t>(e)];
}

/// What the frames reached, summed over scripts: a test asserts that each
/// property was really exercised, not vacuously true.
struct OracleCoverage {
  std::int64_t frames = 0;
  std::int64_t motion = 0;  ///< frames with drive/pivot off centre or a motion bit
  /// by the last interruption (an ending event other than a release) before the press that enabled
  std::array<std::int64_t, static_cast<std::size_t>(Ending::kCount)> motion_after{};
  std::int64_t weapons = 0;            ///< frames with a weapon bit
  std::int64_t stops_with_frames = 0;  ///< stops that owed (and got) 3 neutral frames
  std::int64_t suspend_frames = 0;     ///< neutral frames of a suspend
  std::int64_t reload_frames = 0;      ///< neutral frames of a reload
  std::int64_t stop_latches = 0;       ///< stops by a stop button
  std::int64_t panics = 0;             ///< squeezes past the panic point
  std::int64_t timeouts = 0;           ///< enable timeouts that ended motion
  std::int64_t supervisor_stops = 0;   ///< presses of a supervisor's stop button
  std::int64_t operator_resets = 0;    ///< stops reset by the operator's hold
  std::int64_t supervisor_resets = 0;  ///< stops reset by the supervisor's hold
  std::int64_t refused_resets = 0;     ///< the operator's holds done on the supervisor's stop
  std::int64_t supervised_frames = 0;  ///< frames of scripts with a supervisor's controller

  OracleCoverage& operator+=(const OracleCoverage& o) {
    frames += o.frames;
    motion += o.motion;
    for (std::size_t i = 0; i < motion_after.size(); ++i) motion_after[i] += o.motion_after[i];
    weapons += o.weapons;
    stops_with_frames += o.stops_with_frames;
    suspend_frames += o.suspend_frames;
    reload_frames += o.reload_frames;
    stop_latches += o.stop_latches;
    panics += o.panics;
    timeouts += o.timeouts;
    supervisor_stops += o.supervisor_stops;
    operator_resets += o.operator_resets;
    supervisor_resets += o.supervisor_resets;
    refused_resets += o.refused_resets;
    supervised_frames += o.supervised_frames;
    return *this;
  }
};

class SafetyOracle {
 public:
  /// A reload's FILE: the mapping it loads, or nullptr for one that does not.
  using Lookup = std::function<const mapping::Mapping*(const std::string& file)>;

  struct Options {
    bool weapons = false;         ///< --weapons
    std::uint8_t code = 0x01;     ///< --code
    std::int64_t period_ms = 40;  ///< 1000 / rate
    int stop_frames = 3;          ///< a stop: neutral frames at its tick and the next two (docs/event-scripts.md)
    int stop_ticks = 8;           ///< the ticks a stop may take when the link refuses some (3 + 5 tries)
  };

  /// Drive and pivot in every neutral frame: the protocol's centre, whatever a mapping says.
  static constexpr std::uint8_t kNeutralCentre = 128;

  SafetyOracle(const mapping::Mapping& initial, std::vector<input::InputEvent> script, Lookup lookup, Options options)
      : script_(std::move(script)), lookup_(std::move(lookup)), options_(options), current_(&initial) {
    add_possible(initial);
    // A script that addresses the supervisor's controller anywhere is supervised from its start.
    supervised_ = std::any_of(script_.begin(), script_.end(),
                              [](const input::InputEvent& e) { return e.pad == input::Pad::kSupervisor; });
    // The last frame is the first at or after the `end` (or the last event).
    end_tick_ = script_.empty() ? 0 : tick_of(script_.back().t_ms);
  }

  /// Each delivered frame, in order: empty, or the rule it breaks.
  std::string frame(std::int64_t t, const protocol::DataBytes& data) {
    ++coverage_.frames;
    if (supervised_) ++coverage_.supervised_frames;
    if (t % options_.period_ms != 0) return "a frame off the " + std::to_string(options_.period_ms) + " ms grid";
    if (t <= last_t_) return "frame times not increasing (previous " + std::to_string(last_t_) + ")";
    if (auto missing = missing_before(t); !missing.empty()) return missing;
    advance_to(t);
    at_tick(t);
    last_t_ = t;
    const auto s = protocol::read_signals(data);
    if (const auto errors = protocol::validation_errors(data); !errors.empty())
      return "invalid frame: " + errors.front();
    if (data[protocol::kCodeByte] != options_.code) return "byte 11 is not the code";

    if (!link_up_) return "delivered while the link is down (script)";
    // Once suspended, stopping or past the end, only the neutral frames still
    // owed go out: 3 for each suspend, reload and stop, one sequence after the other.
    const bool owed = owed_ > 0;
    if (owed) --owed_;
    if (stopped_) {
      if (!owed) return "a frame after a stop's neutral frames";
      if (t >= stop_tick_ && t < stop_tick_ + options_.stop_frames * options_.period_ms) ++stop_frames_on_time_;
    } else if (suspended_) {
      ++coverage_.suspend_frames;
      if (!owed) return "delivered while suspended, after its neutral frames";
    }
    if (t > end_tick_ && !owed) return "a frame past the script's end";

    // What must be neutral: not enabled, a reload's frames, a stop's, a suspend's, past the end.
    const bool in_reload = reloading(t);
    if (in_reload) {
      ++reload_sent_;
      ++coverage_.reload_frames;
    }
    std::string why;
    if (!enabled()) why = "not enabled (" + not_enabled_reason() + ")";
    if (in_reload) why = "a reload's neutral frame";
    if (suspended_) why = "a suspend's neutral frame";
    if (stopped_) why = "a stop's neutral frame";
    if (t > end_tick_) why = "past the script's end";

    for (std::size_t i = 0; i < protocol::kSignalCount; ++i) {
      const auto& sig = protocol::kSignals[i];
      if (sig.kind != protocol::SignalKind::kWeapon || s.values[i] == 0) continue;
      ++coverage_.weapons;
      if (!options_.weapons) return std::string(sig.name) + " = 1 without --weapons";
      if (!enabled()) return std::string(sig.name) + " = 1 while " + why;
      if (!armed(static_cast<protocol::SignalId>(i)))
        return std::string(sig.name) + " = 1 without its arming input held";
    }
    const auto moving = motion(s);
    if (moving) {
      if (!why.empty()) return *moving + " while " + why;
      ++coverage_.motion;
      ++coverage_.motion_after[static_cast<std::size_t>(pressed_after_)];
    }
    return {};
  }

  /// After the replay: what the end lacks. A stop owes its neutral frames at
  /// the tick that sees it and the next two, when the link is up for them.
  std::string finish() {
    if (auto missing = missing_before(end_tick_ + options_.period_ms); !missing.empty()) return missing;
    advance_to(end_tick_);
    if (!stopped_ || stop_tick_ > end_tick_) return {};
    for (int i = 0; i < options_.stop_frames; ++i) {
      if (!link_up_at(stop_tick_ + i * options_.period_ms)) return {};
    }
    ++coverage_.stops_with_frames;
    if (stop_frames_on_time_ < options_.stop_frames) {
      return "a stop at tick " + std::to_string(stop_tick_) + " with the link up got " +
             std::to_string(stop_frames_on_time_) + " of its " + std::to_string(options_.stop_frames) +
             " neutral frames at that tick and the next ones";
    }
    return {};
  }

  [[nodiscard]] const OracleCoverage& coverage() const { return coverage_; }

 private:
  /// One pad's stop button, as a reset hold reads it (the mapping in force's).
  struct Hold {
    bool down = false;
    bool pressed = false;               ///< since the last tick
    bool let_go = false;                ///< since the last tick
    bool from_reset = false;            ///< held on since a reset hold completed: no stop until let go
    std::optional<std::int64_t> since;  ///< a hold under way since this tick
  };

  [[nodiscard]] std::int64_t tick_of(std::int64_t t) const {
    return (t + options_.period_ms - 1) / options_.period_ms * options_.period_ms;
  }

  void advance_to(std::int64_t t) {
    while (next_ < script_.size() && script_[next_].t_ms <= t) apply(script_[next_++]);
  }

  // Every tick up to the script's end gets a frame while the link is up and
  // nothing holds the loop (a suspend, a stop): none is lost on the way.
  std::string missing_before(std::int64_t t) {
    const std::int64_t first = last_t_ < 0 ? 0 : last_t_ + options_.period_ms;
    for (std::int64_t u = first; u < t && u <= end_tick_; u += options_.period_ms) {
      advance_to(u);
      at_tick(u);
      if (link_up_ && !suspended_ && !stopped_) {
        return "no frame at t=" + std::to_string(u) + " (the link up, not suspended, not stopping)";
      }
    }
    return {};
  }

  // What every tick of the loop reads, once its events are in. The stop
  // button: a press since the last tick latches (but one made just before a
  // new controller session: the loop cannot see it); the stop is the
  // supervisor's once the supervisor's stop is pressed. A latch is reset
  // only by a reset hold (docs/safety-states.md), read tick by tick as the
  // loop reads it (hold_tick), on the stop buttons and the deadman of the
  // mapping in force: the supervisor's resets any stop, the operator's only
  // the operator's. A deadman every possible mapping has, let go since the
  // last tick, makes the tick's frame neutral. The panic point and the
  // timeout end "enabled" at a tick (the timeout runs from the tick of the
  // last change of any input). The panic's "fully released" is the replay
  // tests' to check: here a fresh squeeze from below the press point is
  // enough (permissive).
  void at_tick(std::int64_t t) {
    // A reload's mapping is the loop's once the reload is done.
    take_up_pending(t);
    const bool reads_stops = !stopped_;  // every tick but a shutdown's reads the stop buttons
    const bool sup_stop = sup_connected_ && (sup_hold_.pressed || (sup_hold_.down && !sup_hold_.from_reset));
    const bool op_stop = connected_ && (op_hold_.pressed || (op_hold_.down && !op_hold_.from_reset));
    if (stop_latched_) {
      // The loop reads the holds only at ticks it spends in "stopped"; a
      // suspend's or a reload's ticks, or a lost pad, end a hold (and read
      // the stop buttons as a stop: the supervisor's makes it the supervisor's).
      // (A resume in this tick: its rebase takes the presses.)
      const bool in_stopped = t > latch_tick_ && !suspended_ && !stopped_ && !reloading(t) && !resumed_this_tick_;
      if (in_stopped ? sup_connected_ && sup_hold_.pressed : reads_stops && sup_stop) {
        stopper_ = input::Pad::kSupervisor;
      }
      const bool touched = deadman_touched();
      const bool sup_done = hold_tick(sup_hold_, in_stopped && sup_connected_, touched, t);
      const bool op_done = hold_tick(op_hold_, in_stopped && connected_, touched, t);
      if (sup_done) {
        reset(t);
        ++coverage_.supervisor_resets;
      } else if (op_done && stopper_ == input::Pad::kOperator) {
        reset(t);
        ++coverage_.operator_resets;
      } else if (op_done) {
        ++coverage_.refused_resets;
      }
    } else if (reads_stops && (op_stop || sup_stop)) {
      // A stop button pressed since the last tick or held (not held on from a reset) latches.
      stop_latched_ = true;
      stopper_ = sup_stop ? input::Pad::kSupervisor : input::Pad::kOperator;
      latch_tick_ = t;
      ++coverage_.stop_latches;
      end_enabled(Ending::kStopButton);
    }
    op_hold_.pressed = op_hold_.let_go = sup_hold_.pressed = sup_hold_.let_go = false;
    resumed_this_tick_ = false;
    deadman_pressed_ = false;
    deadman_was_down_ = current_deadman_down();
    down_at_tick_.clear();
    for (const auto k : common_deadmen_) {
      if (connected_ && down(k)) down_at_tick_.insert(k);
    }
    // A deadman every possible mapping has, let go since the last tick (even
    // if pressed again since): this tick's frame is neutral.
    let_go_this_tick_ = std::exchange(let_go_since_tick_, false);
    if (panic_ && enabled()) {
      for (const auto k : deadmen_) {
        const auto it = axes_.find(k);
        if (!k.is_button() && it != axes_.end() && it->second >= *panic_) {
          ++coverage_.panics;
          end_enabled(Ending::kPanic);
          break;
        }
      }
    }
    if (timeout_ms_ && enabled() && t - tick_of(last_change_) >= *timeout_ms_) {
      ++coverage_.timeouts;
      end_enabled(Ending::kTimeout);
    }
  }

  // A reload's mapping, in force from the first tick after the reload's
  // frames: its stop buttons are read as they are held now.
  void take_up_pending(std::int64_t tick) {
    // (Asked for while suspended, it is read after the resume.)
    if (pending_ == nullptr || reloading(tick) || reload_after_resume_ || suspended_) return;
    current_ = std::exchange(pending_, nullptr);
    const auto held_now = [](const std::map<input::InputKey, bool>& buttons,
                             const std::optional<mapping::InputUse>& use) {
      const auto it = use ? buttons.find(use->key) : buttons.end();
      return it != buttons.end() && it->second;
    };
    op_hold_.down = held_now(buttons_, current_->estop);
    sup_hold_.down =
        held_now(sup_buttons_, current_->supervisor ? std::optional(current_->supervisor->stop) : std::nullopt);
    op_hold_.from_reset = sup_hold_.from_reset = false;
  }

  // A reset: not enabled, afresh (every deadman press so far is history).
  void reset(std::int64_t t) {
    stop_latched_ = false;
    op_hold_.since.reset();
    sup_hold_.since.reset();
    reset_tick_ = t;
    end_enabled(Ending::kReset);
  }

  // One pad's reset hold at a tick, as the loop reads it (exactly: a reset
  // the loop did not make would make a later press of the stop button a new
  // stop here, a press of the reset there): the stop button pressed since the
  // last tick and held, the deadman neither held nor pressed, begins it; let
  // go or the deadman touched ends it; true once it has lasted the hold.
  bool hold_tick(Hold& h, bool reading, bool touched, std::int64_t t) const {
    if (!reading || h.let_go || !h.down || touched) h.since.reset();
    if (reading && h.pressed && h.down && !touched) h.since = t;
    if (!h.since || t - *h.since < current_->stop_reset_hold_ms) return false;
    h.since.reset();
    h.from_reset = true;  // held on after it, it stops nothing until let go
    return true;
  }

  // The mapping in force's deadman (the one a reset hold needs released): held
  // now, pressed since the last tick, or (a trigger) held at the last tick.
  [[nodiscard]] bool deadman_touched() const {
    if (!current_->deadman) return false;
    const bool trigger = !current_->deadman->key.is_button();
    return current_deadman_down() || deadman_pressed_ || (trigger && deadman_was_down_);
  }
  [[nodiscard]] bool current_deadman_down() const {
    return connected_ && current_->deadman && down(current_->deadman->key);
  }

  // A stop button of the mapping in force moved (a press not at the connect's instant).
  static void stop_moved(Hold& h, bool now, bool was, bool initial) {
    h.down = now;
    if (!now) h.from_reset = false;
    if (initial) return;
    if (now && !was) h.pressed = true;
    if (!now && was) h.let_go = true;
  }

  void add_possible(const mapping::Mapping& m) {
    // Permissive over every mapping the script may have loaded: a stop button
    // only when all have that one, a panic point and a timeout only when all
    // have one (the most lenient of them).
    const auto lenient = [this](auto& have, auto value) {
      if (!value || (!first_mapping_ && !have)) have.reset();
      else have = have && !first_mapping_ ? std::max(*have, *value) : *value;
    };
    const std::optional<input::InputKey> sup_stop = m.supervisor ? std::optional(m.supervisor->stop.key) : std::nullopt;
    sup_stop_ = first_mapping_ || sup_stop_ == sup_stop ? sup_stop : std::nullopt;
    lenient(timeout_ms_, m.enable_timeout_ms);
    std::optional<int> panic;
    if (m.deadman_panic) panic = static_cast<int>(std::ceil(*m.deadman_panic * 32767.0));
    lenient(panic_, panic);
    std::set<input::InputKey> mine;
    if (m.deadman) mine.insert(m.deadman->key);
    if (first_mapping_) {
      common_deadmen_ = mine;
    } else {
      std::erase_if(common_deadmen_, [&mine](input::InputKey k) { return !mine.contains(k); });
    }
    first_mapping_ = false;
    if (m.deadman) deadmen_.insert(m.deadman->key);
    const auto weapons = [this](const std::vector<mapping::Binding>& bindings) {
      for (const auto& b : bindings) {
        const auto* w = std::get_if<mapping::WeaponBinding>(&b.rule);
        if (w != nullptr && w->arm) arms_[w->signal].insert(*w->arm);
      }
    };
    weapons(m.bindings);
    for (const auto& layer : m.layers) weapons(layer.bindings);
  }

  // Every event that ends "enabled": the press that enables must come after it.
  void end_enabled(Ending why) {
    fresh_.clear();
    last_ending_ = why;
    last_interruption_ = why;
  }

  void apply(const input::InputEvent& e) {
    using T = input::InputEvent::Type;
    // A reload's mapping is the loop's from the first tick after the reload's frames.
    take_up_pending(tick_of(e.t_ms));
    if (e.type == T::kLinkDown || e.type == T::kLinkTaken) {
      if (link_up_) end_enabled(Ending::kLinkDown);
      link_up_ = false;
      return;
    }
    if (e.type == T::kLinkUp) {
      if (!link_up_) end_enabled(Ending::kLinkUp);  // a link that comes back is a new link
      link_up_ = true;
      return;
    }
    if (stopped_) return;  // nothing else is answered once a stop is in
    if (e.pad == input::Pad::kSupervisor) {
      apply_supervisor(e);
      return;
    }
    switch (e.type) {
      case T::kConnect:
        end_enabled(Ending::kConnect);
        connected_ = true;
        connect_t_ = e.t_ms;
        op_hold_ = Hold{};
        let_go_since_tick_ = false;  // a new session: what the old one did is gone
        down_at_tick_.clear();
        deadman_pressed_ = false;
        buttons_.clear();
        axes_.clear();
        last_change_ = e.t_ms;
        break;
      case T::kDisconnect:
        end_enabled(Ending::kDisconnect);
        connected_ = false;
        op_hold_ = Hold{};
        buttons_.clear();
        axes_.clear();
        break;
      case T::kButton: {
        if (!connected_) break;  // a lost controller's stale events
        const bool was = buttons_[e.key];
        buttons_[e.key] = e.value != 0;
        if (was != (e.value != 0)) last_change_ = e.t_ms;
        // Stamped with the connect's time: the state the pad had when it appeared, not a press.
        // Stamped with the connect's time: the state the pad had when it appeared, not a press.
        const bool initial = e.t_ms == connect_t_;
        if (current_->estop && e.key == current_->estop->key) stop_moved(op_hold_, e.value != 0, was, initial);
        if (deadmen_.contains(e.key)) deadman_moved(e.key, was, e.value != 0, e.t_ms);
        break;
      }
      case T::kAxis: {
        if (!connected_) break;
        const bool was = down(e.key);
        if (axes_[e.key] != e.value) last_change_ = e.t_ms;
        axes_[e.key] = e.value;
        if (deadmen_.contains(e.key)) deadman_moved(e.key, was, down(e.key), e.t_ms);
        break;
      }
      case T::kSuspend:
        end_enabled(Ending::kSuspend);
        if (!suspended_) {
          suspended_ = true;
          // (One asked for during a reload waits for it: its frames' tick is not known here.)
          suspend_tick_ = reloading(tick_of(e.t_ms)) ? std::nullopt : std::optional(tick_of(e.t_ms));
          owed_ += options_.stop_frames;
        }
        break;
      case T::kResume:
        end_enabled(Ending::kResume);
        resumed_this_tick_ = true;
        // A reload asked for while suspended is answered after the resume, as
        // a SIGHUP to a stopped process is once it goes on.
        if (suspended_ && reload_after_resume_) {
          reload_tick_ = tick_of(e.t_ms);
          reload_sent_ = 0;

          owed_ += options_.stop_frames;
        }
        reload_after_resume_ = false;
        suspended_ = false;
        break;
      case T::kReload: {
        const mapping::Mapping* loaded = e.name.empty() ? nullptr : lookup_(e.name);
        end_enabled(e.name.empty()      ? Ending::kReloadSame
                    : loaded != nullptr ? Ending::kReloadGood
                                        : Ending::kReloadBad);
        if (loaded != nullptr) {
          add_possible(*loaded);
          pending_ = loaded;  // in force once the reload is done
        } else {
          // The file in force read again (a reload under way gives way to it), or a bad one: the
          // mapping in force stays.
          pending_ = e.name.empty() ? current_ : nullptr;
        }
        // Answered at once; while suspended, after the resume.
        const std::int64_t tick = tick_of(e.t_ms);
        if (reloading(tick)) {
          // The files read again: its neutral frames count afresh from here.
          owed_ += reload_sent_;
          reload_tick_ = tick;
          reload_sent_ = 0;
        } else if (suspended_) {
          reload_after_resume_ = true;
        } else if (suspend_tick_ && tick < *suspend_tick_ + options_.stop_frames * options_.period_ms) {
          // Resumed, but the suspend's neutral frames still go out: the loop
          // answers the resume after them, and the reload after the resume.
          reload_tick_ = *suspend_tick_ + options_.stop_frames * options_.period_ms;
          reload_sent_ = 0;
          owed_ += options_.stop_frames;
        } else {
          reload_tick_ = tick;
          reload_sent_ = 0;
          owed_ += options_.stop_frames;
        }
        break;
      }
      case T::kStop:
        end_enabled(Ending::kStop);
        stopped_ = true;
        stop_tick_ = tick_of(e.t_ms);
        owed_ += options_.stop_frames;
        break;
      default: break;  // hats: the generator sends none; `end`
    }
  }

  // A reload sends its neutral frames from its tick on until the link took
  // 3, or for as long as a stop may take when it refuses them.
  [[nodiscard]] bool reloading(std::int64_t t) const {
    return reload_tick_ && t >= *reload_tick_ && reload_sent_ < options_.stop_frames &&
           t < *reload_tick_ + options_.stop_ticks * options_.period_ms;
  }

  // The supervisor's controller: driving needs it there (a script that
  // addresses it is supervised), its coming and going ends "enabled" (the
  // engine starts afresh), and its stop button latches as the operator's does.
  void apply_supervisor(const input::InputEvent& e) {
    using T = input::InputEvent::Type;
    switch (e.type) {
      case T::kConnect:
        end_enabled(Ending::kConnect);
        sup_connected_ = true;
        sup_connect_t_ = e.t_ms;
        sup_hold_ = Hold{};
        sup_buttons_.clear();
        break;
      case T::kDisconnect:
        end_enabled(Ending::kDisconnect);
        sup_connected_ = false;
        sup_hold_ = Hold{};
        sup_buttons_.clear();
        break;
      case T::kButton: {
        if (!sup_connected_) break;
        const bool was = sup_buttons_[e.key];
        sup_buttons_[e.key] = e.value != 0;
        const bool initial = e.t_ms == sup_connect_t_;
        if (e.key == sup_stop_ && e.value != 0 && !was && !initial) ++coverage_.supervisor_stops;
        if (current_->supervisor && e.key == current_->supervisor->stop.key) {
          stop_moved(sup_hold_, e.value != 0, was, initial);
        }
        break;
      }
      default: break;
    }
  }

  [[nodiscard]] bool supervisor_stop_held() const {
    if (!sup_stop_) return false;
    const auto it = sup_buttons_.find(*sup_stop_);
    return it != sup_buttons_.end() && it->second;
  }

  // A deadman pressed or released (button) or moved across its press point (trigger).
  void deadman_moved(input::InputKey key, bool was, bool now, std::int64_t t) {
    if (now && !was && t != connect_t_ && current_->deadman && key == current_->deadman->key) deadman_pressed_ = true;
    if (now && !was && t != connect_t_ && !stop_latched_ && t > reset_tick_) {
      fresh_.insert(key);
      pressed_after_ = last_interruption_;
    }
    if (!now && was) {
      // Held at the last tick and let go since (the loop may count more: a release between two presses).
      if (common_deadmen_.contains(key) && t != connect_t_ && down_at_tick_.contains(key)) let_go_since_tick_ = true;
      fresh_.erase(key);
      last_ending_ = Ending::kRelease;
    }
  }

  [[nodiscard]] bool enabled() const {
    if (!connected_ || !link_up_ || suspended_ || stopped_ || stop_latched_ || let_go_this_tick_) return false;
    if (supervised_ && !sup_connected_) return false;
    return std::any_of(fresh_.begin(), fresh_.end(), [this](input::InputKey k) { return down(k); });
  }

  // A deadman down as the engine reads it: a button held, a trigger at half its travel (16384 of 32767) or past.
  [[nodiscard]] bool down(input::InputKey key) const {
    if (key.is_button()) return held(key);
    const auto it = axes_.find(key);
    return it != axes_.end() && it->second >= kTriggerPressed;
  }

  [[nodiscard]] std::string not_enabled_reason() const {
    if (stopped_) return "stopping";
    if (stop_latched_) return "stopped by the stop button, not reset";
    if (let_go_this_tick_) return "the deadman let go since the last tick";
    if (supervised_ && !sup_connected_) return "no supervisor's controller";
    if (suspended_) return "suspended";
    if (!link_up_) return "link down";
    if (!connected_) return "no controller";
    for (const auto k : deadmen_) {
      if (held(k)) return "deadman held but not pressed since the last " + std::string(to_string(last_ending_));
    }
    return "deadman not held";
  }

  [[nodiscard]] bool held(input::InputKey key) const {
    if (key.is_button()) {
      const auto it = buttons_.find(key);
      return it != buttons_.end() && it->second;
    }
    const auto it = axes_.find(key);
    // The engine's threshold is 0.5 of the range; one step below it, to stay on the permissive side.
    return it != axes_.end() && it->second >= 16383;
  }

  [[nodiscard]] bool armed(protocol::SignalId id) const {
    const auto it = arms_.find(id);
    if (it == arms_.end()) return false;
    return std::any_of(it->second.begin(), it->second.end(), [this](input::InputKey k) { return held(k); });
  }

  // Motion: drive or pivot off centre, or any bit that is not selector-like (safety and drive_brake included).
  [[nodiscard]] static std::optional<std::string> motion(const protocol::ControlState& s) {
    for (std::size_t i = 0; i < protocol::kSignalCount; ++i) {
      const auto& sig = protocol::kSignals[i];
      if (sig.kind == protocol::SignalKind::kCentred && s.values[i] != kNeutralCentre) {
        return std::string(sig.name) + " = " + std::to_string(s.values[i]);
      }
      if (sig.is_bit() && sig.kind != protocol::SignalKind::kSelector && s.values[i] != 0) {
        return std::string(sig.name) + " = 1";
      }
    }
    return std::nullopt;
  }

  [[nodiscard]] bool link_up_at(std::int64_t t) const {
    bool up = true;
    for (const auto& e : script_) {
      if (e.t_ms > t) break;
      if (e.type == input::InputEvent::Type::kLinkUp) up = true;
      if (e.type == input::InputEvent::Type::kLinkDown || e.type == input::InputEvent::Type::kLinkTaken) up = false;
    }
    return up;
  }

  std::vector<input::InputEvent> script_;
  Lookup lookup_;
  Options options_;
  std::size_t next_ = 0;
  std::int64_t end_tick_ = 0;
  std::int64_t last_t_ = -1;

  std::set<input::InputKey> deadmen_;         ///< every possible mapping's
  std::set<input::InputKey> common_deadmen_;  ///< the deadmen every possible mapping has (the stop's clearing)
  std::map<protocol::SignalId, std::set<input::InputKey>> arms_;

  static constexpr int kTriggerPressed = 16384;  ///< 0.5 of 32767, as the engine rounds it

  std::optional<input::InputKey> sup_stop_;  ///< the supervisor's stop button every possible mapping has
  bool supervised_ = false;
  bool sup_connected_ = false;
  std::int64_t sup_connect_t_ = -1;
  std::map<input::InputKey, bool> sup_buttons_;
  std::optional<std::int64_t> timeout_ms_;
  std::optional<int> panic_;  ///< the raw trigger value of the panic point
  bool first_mapping_ = true;
  bool let_go_since_tick_ = false;  ///< a deadman let go since the last tick
  bool let_go_this_tick_ = false;   ///< and so at this tick
  bool stop_latched_ = false;
  input::Pad stopper_ = input::Pad::kOperator;  ///< whose the latched stop is
  std::int64_t latch_tick_ = 0;
  std::int64_t reset_tick_ = -1;               ///< the last reset's tick: the presses up to it are history
  const mapping::Mapping* current_;            ///< the mapping in force (the last that loaded)
  const mapping::Mapping* pending_ = nullptr;  ///< a reload's, in force once the reload is done
  Hold op_hold_;
  Hold sup_hold_;
  bool deadman_pressed_ = false;            ///< the mapping in force's deadman, since the last tick
  bool resumed_this_tick_ = false;          ///< a resume since the last tick (its rebase takes the presses)
  bool deadman_was_down_ = false;           ///< and held at the last tick
  std::set<input::InputKey> down_at_tick_;  ///< the common deadmen held at the last tick
  std::int64_t last_change_ = 0;            ///< the last event that changed an input

  bool connected_ = false;
  std::int64_t connect_t_ = -1;
  std::map<input::InputKey, bool> buttons_;
  std::map<input::InputKey, int> axes_;
  std::set<input::InputKey> fresh_;  ///< deadmen pressed since the last ending event
  Ending last_ending_ = Ending::kStart;
  Ending last_interruption_ = Ending::kStart;
  Ending pressed_after_ = Ending::kStart;

  bool link_up_ = true;  ///< replay's sink is there from the start
  bool suspended_ = false;
  std::optional<std::int64_t> suspend_tick_;  ///< the tick of the last suspend's first neutral frame
  std::optional<std::int64_t> reload_tick_;
  int reload_sent_ = 0;               ///< its neutral frames delivered so far
  bool reload_after_resume_ = false;  ///< a reload asked for while suspended
  bool stopped_ = false;
  std::int64_t stop_tick_ = 0;
  int owed_ = 0;  ///< neutral frames of suspends, reloads and a stop still to go out
  int stop_frames_on_time_ = 0;

  OracleCoverage coverage_;
};

}  // namespace andros::test
