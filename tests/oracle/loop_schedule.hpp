#pragma once
// What the run loop owes around its faults, read off the script for the
// fault simulation's oracle (safety_oracle.hpp): the link up or down, a
// suspend and its resume, a reload and its neutral frames, the script's
// stop; how many neutral frames are still owed (3 for each suspend, reload
// and stop, one sequence after the other), and when a reload's frames go out.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "andros/input/events.hpp"

namespace andros::test {

struct LoopOptions {
  std::int64_t period_ms = 40;  ///< 1000 / rate
  int stop_frames = 3;          ///< a stop: neutral frames at its tick and the next two (docs/event-scripts.md)
  int stop_ticks = 8;           ///< the ticks a stop may take when the link refuses some (3 + 5 tries)
};

class LoopSchedule {
 public:
  explicit LoopSchedule(LoopOptions options) : o_(options) {}

  [[nodiscard]] std::int64_t tick_of(std::int64_t t) const {
    return (t + o_.period_ms - 1) / o_.period_ms * o_.period_ms;
  }

  // A reload sends its neutral frames from its tick on until the link took
  // 3, or for as long as a stop may take when it refuses them.
  [[nodiscard]] bool reloading(std::int64_t t) const {
    return reload_tick_ && t >= *reload_tick_ && reload_sent_ < o_.stop_frames &&
           t < *reload_tick_ + o_.stop_ticks * o_.period_ms;
  }

  /// At a tick: a suspend's neutral frames still going out (resumed or not:
  /// the loop answers a resume after them), until the link took 3 or for as
  /// long as a stop may take. Unknown (false) for a suspend that waits for a reload.
  [[nodiscard]] bool suspending(std::int64_t t) const {
    return suspend_tick_ && t >= *suspend_tick_ && suspend_sent_ < o_.stop_frames &&
           t < *suspend_tick_ + o_.stop_ticks * o_.period_ms;
  }

  /// At a tick: a reload under way (its neutral frames going out, or to go out once a suspend's are).
  [[nodiscard]] bool reload_under_way(std::int64_t tick) const {
    return reloading(tick) || (reload_tick_ && tick < *reload_tick_);
  }

  /// Link events; true when the event changed whether the link carries
  /// motion (a link lost or stalled, or back: a new link). A stalled server
  /// (`link stalled`) gets frames, neutral ones, through its resets (`link
  /// down`, `link up`) until `link reading`.
  bool link(input::InputEvent::Type type) {
    using T = input::InputEvent::Type;
    const bool carried = carries_motion();
    if (type == T::kLinkStalled || type == T::kLinkReading) {
      stalled_ = type == T::kLinkStalled;
    } else {
      link_up_ = type == T::kLinkUp;
    }
    return carried != carries_motion();
  }

  void suspend(std::int64_t t) {
    if (suspended_) return;
    suspended_ = true;
    // Asked for while the last one's neutral frames still go out (resumed
    // meanwhile: the loop answers that resume after them), it is that suspend still.
    if (suspending(tick_of(t))) return;
    // One asked for during a reload waits for it: its frames' tick is not known
    // here, nor whether a suspend soon after (a resume between) is the same one.
    const bool unknown = reloading(tick_of(t)) || (waited_t_ && t - *waited_t_ < 2 * o_.stop_ticks * o_.period_ms);
    if (reloading(tick_of(t))) waited_t_ = t;
    suspend_tick_ = unknown ? std::nullopt : std::optional(tick_of(t));
    suspend_sent_ = 0;
    owed_ += o_.stop_frames;
  }

  void resume(std::int64_t t) {
    // A reload asked for while suspended is answered after the resume, as
    // a SIGHUP to a stopped process is once it goes on.
    if (suspended_ && reload_after_resume_) start_reload(tick_of(t));
    reload_after_resume_ = false;
    suspended_ = false;
  }

  void reload(std::int64_t t) {
    // Answered at once; while suspended, after the resume.
    const std::int64_t tick = tick_of(t);
    const std::int64_t suspend_end = suspend_tick_ ? *suspend_tick_ + o_.stop_frames * o_.period_ms : -1;
    if (reloading(tick)) {
      // The files read again: its neutral frames count afresh from here.
      owed_ += reload_sent_;
      reload_tick_ = tick;
      reload_sent_ = 0;
    } else if (suspended_) {
      reload_after_resume_ = true;
    } else if (tick < suspend_end) {
      // Resumed, but the suspend's neutral frames still go out: the loop
      // answers the resume after them, and the reload after the resume.
      start_reload(suspend_end);
    } else {
      start_reload(tick);
    }
  }

  void stop(std::int64_t t) {
    stopped_ = true;
    stop_tick_ = tick_of(t);
    owed_ += o_.stop_frames;
  }

  /// What a frame delivered at t may be.
  struct Delivery {
    std::string error;           ///< why it may not go out at all; empty: it may
    std::string neutral;         ///< why it must be neutral (a reload's, suspend's or stop's, past the end); or empty
    bool suspend_frame = false;  ///< one of a suspend's
    bool reload_frame = false;   ///< one of a reload's
  };
  /// Once suspended, stopping or past the end, only the neutral frames still owed go out.
  // [rule: delivery]
  Delivery deliver(std::int64_t t, std::int64_t end_tick) {
    Delivery d;
    if (!link_up_) {
      d.error = "delivered while the link is down (script)";
      return d;
    }
    d.reload_frame = reloading(t);
    const bool owed = take_owed(t);
    d.suspend_frame = !stopped_ && suspended_;
    if (stopped_ && !owed) d.error = "a frame after a stop's neutral frames";
    else if (d.suspend_frame && !owed) d.error = "delivered while suspended, after its neutral frames";
    else if (t > end_tick && !owed) d.error = "a frame past the script's end";
    if (d.reload_frame) d.neutral = "a reload's neutral frame";
    if (suspended_) d.neutral = "a suspend's neutral frame";
    if (stopped_) d.neutral = "a stop's neutral frame";
    if (t > end_tick) d.neutral = "past the script's end";
    return d;
  }

 private:
  /// A frame delivered at t: whether it was one of the neutral frames owed.
  bool take_owed(std::int64_t t) {
    const bool owed = owed_ > 0;
    if (owed) --owed_;
    if (stopped_ && owed && t >= stop_tick_ && t < stop_tick_ + o_.stop_frames * o_.period_ms) ++stop_frames_on_time_;
    if (reloading(t)) ++reload_sent_;
    if (suspending(t)) ++suspend_sent_;
    return owed;
  }

 public:
  /// Frames go out (a stalled link's too).
  [[nodiscard]] bool link_up() const { return link_up_; }
  /// The link up and not stalled: what being enabled needs.
  [[nodiscard]] bool carries_motion() const { return link_up_ && !stalled_; }
  [[nodiscard]] bool stalled() const { return stalled_; }
  [[nodiscard]] bool suspended() const { return suspended_; }
  [[nodiscard]] bool stopped() const { return stopped_; }

  /// A script's stop before its end, with the link up for its frames, owes
  /// them at the tick that sees it and the next ones.
  [[nodiscard]] bool stop_owed_frames(const std::vector<input::InputEvent>& script, std::int64_t end_tick) const {
    if (!stopped_ || stop_tick_ > end_tick) return false;
    for (int i = 0; i < o_.stop_frames; ++i) {
      if (!link_up_at(script, stop_tick_ + i * o_.period_ms)) return false;
    }
    return true;
  }
  /// Empty, or how many of the owed frames came on time.
  [[nodiscard]] std::string stop_frames_missing() const {
    if (stop_frames_on_time_ >= o_.stop_frames) return {};
    return "a stop at tick " + std::to_string(stop_tick_) + " with the link up got " +
           std::to_string(stop_frames_on_time_) + " of its " + std::to_string(o_.stop_frames) +
           " neutral frames at that tick and the next ones";
  }

  /// Whether the link was up at t, by the script alone.
  static bool link_up_at(const std::vector<input::InputEvent>& script, std::int64_t t) {
    bool up = true;
    for (const auto& e : script) {
      if (e.t_ms > t) break;
      if (e.type == input::InputEvent::Type::kLinkUp) up = true;
      if (e.type == input::InputEvent::Type::kLinkDown || e.type == input::InputEvent::Type::kLinkTaken) up = false;
    }
    return up;
  }

 private:
  void start_reload(std::int64_t tick) {
    reload_tick_ = tick;
    reload_sent_ = 0;
    owed_ += o_.stop_frames;
  }

  LoopOptions o_;
  bool link_up_ = true;   ///< replay's sink is there from the start
  bool stalled_ = false;  ///< a `link stalled` not yet answered by `link reading`
  bool suspended_ = false;
  std::optional<std::int64_t> suspend_tick_;  ///< the tick of the last suspend's first neutral frame
  std::optional<std::int64_t> waited_t_;      ///< the last suspend asked for during a reload
  int suspend_sent_ = 0;                      ///< its neutral frames delivered so far
  std::optional<std::int64_t> reload_tick_;
  int reload_sent_ = 0;               ///< its neutral frames delivered so far
  bool reload_after_resume_ = false;  ///< a reload asked for while suspended
  bool stopped_ = false;
  std::int64_t stop_tick_ = 0;
  int owed_ = 0;  ///< neutral frames of suspends, reloads and a stop still to go out
  int stop_frames_on_time_ = 0;
};

}  // namespace andros::test
