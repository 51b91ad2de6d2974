#include "andros/view/status_board.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cstdio>
#include <tuple>

#include "andros/base/clock.hpp"
#include "andros/base/text.hpp"

namespace andros::view {
namespace {

constexpr const char* kNeutralOnly = "neutral frames only: the server stalled and has not been seen reading since";

/// What a report says that the status's words and the log's lines come
/// from: all of it but the frame, its time and the counters.
auto said(const run::TickReport& r) {
  return std::tie(r.connected, r.controller, r.supervised, r.supervisor_connected, r.supervisor, r.refusal, r.state,
                  r.stopped_by, r.reset_by, r.engine, r.link.state, r.operator_may_reset, r.supervisor_may_reset,
                  r.stopper_pad, r.link.far_end_reading, r.link.detail);
}

bool changed_state(const run::Transition& t) { return t.to != t.from; }

}  // namespace

void FirstCause::follow(const std::vector<run::ReportedTransition>& transitions) {
  using E = run::OpEvent;
  for (const auto& [t, pad] : transitions) {
    const bool up = t.event == E::kLinkUp;
    if ((t.event == E::kLinkDown || t.event == E::kLinkTaken) && t.who != run::Who::kLoop) link_lost_ = true;
    // Only a link that was lost is regained; one that opened leaves the cause what it was.
    if (changed_state(t) && (!up || link_lost_)) cause_ = t;
    if (up) link_lost_ = false;
  }
}

void RunStatusBoard::observe(const run::TickReport& r) {
  // A tick at rest says what the one before said: only the frame, its time
  // and the counters move (the status is copied, its words formed and the
  // log's lines looked for only when something else changed).
  std::optional<RunStatus> before;
  cause_.follow(r.transitions);
  {
    const std::lock_guard lock(mutex_);
    // The rate and jitter are the link's since it came up: a gap while it
    // was down is not a period of the stream.
    if (r.link.state == link::LinkState::kUp && (!said_ || said_->link.state != link::LinkState::kUp)) timing_ = {};
    if (r.result == link::SendResult::kSent) timing_.add(monotonic_ns());
    RunStatus& s = status_;
    s.t_ms = r.t_ms;
    s.sent = r.data;
    s.link = r.link.counters;
    s.gate_trips = r.gate_trips;
    // Words are formed again on the machine's transitions, or when what they are made of changed.
    if (!said_ || !r.transitions.empty() || said(*said_) != said(r)) {
      before = s;
      s.connected = r.connected;
      if (s.connected) s.controller = r.controller.empty() ? "controller" : printable_text(r.controller);
      s.supervised = r.supervised;
      s.supervisor_connected = r.supervisor_connected;
      if (s.supervisor_connected) s.supervisor = r.supervisor.empty() ? "controller" : printable_text(r.supervisor);
      s.supervisor_stop = r.supervisor_connected && r.engine.supervisor_stop;
      s.consent = r.engine.consent;
      s.state = r.state;
      s.stopped_by = stopped_by_text(r);
      s.enable_text = state_text(r, cause_.transition());
      s.held_back = held_back_text(r.engine);
      s.reset_progress = reset_progress_text(r);
      // "deadman released" forever would send the operator looking at the deadman.
      if (const auto note = joystick_note(s.pad_names, s.game_controller);
          !note.empty() && r.connected && r.state == run::OpState::kNotEnabled) {
        s.enable_text = note;
      }
      s.layer = r.engine.layer;
      s.weapons_mode = s.enabled() && r.engine.weapons_mode;
      s.speed = r.engine.speed;
      s.armed = s.weapons_mode && r.engine.armed;
      s.link_state = r.link.state;
      s.far_end_reading = r.link.far_end_reading;
      s.link_detail = s.far_end_reading ? r.link.detail : kNeutralOnly;
      said_ = r;
    }
  }
  // The loop's thread is the status's only writer: read outside the lock, as before.
  if (!r.gate_fault.empty()) {
    spdlog::error(
        "internal error: the frame gate stopped a frame that broke a safety rule ({}): a neutral frame was "
        "sent instead, and the bridge is stopped",
        r.gate_fault);
  }
  if (before) log_changes(*before, status_, r.transitions);
  if (r.skipped > 0) spdlog::warn("clock stalled: {} tick(s) skipped, none sent late in a burst", r.skipped);
  first_tick_ = false;
}

void RunStatusBoard::observe(const run::TickReport& r, const input::InputSource& input) {
  if (r.connected != was_connected_) {
    was_connected_ = r.connected;
    const auto device = r.connected ? input.device() : std::nullopt;
    set_game_controller(device ? std::optional<bool>(device->game_controller) : std::nullopt);
  }
  observe(r);
}

void RunStatusBoard::log_changes(const RunStatus& before, const RunStatus& after,
                                 const std::vector<run::ReportedTransition>& transitions) const {
  const auto any = [&transitions](auto&& what) {
    return std::any_of(transitions.begin(), transitions.end(), [&what](const auto& r) { return what(r.transition); });
  };
  const bool entered = first_tick_ || any(changed_state);
  if (after.shutting_down()) {
    if (any([](const run::Transition& t) { return changed_state(t) && t.to == run::OpState::kShuttingDown; })) {
      spdlog::info("stopping: sending neutral frames");
    }
    return;
  }
  if (before.far_end_reading != after.far_end_reading) {
    if (after.far_end_reading)
      spdlog::info("link {}: the server is reading again: frames follow the controller", after.link_name);
    else spdlog::warn("link {}: {}", after.link_name, kNeutralOnly);
  }
  if (first_tick_ || before.connected != after.connected) {
    if (after.connected) spdlog::info("controller: {}", after.controller);
    else spdlog::info("controller: none connected");
  }
  if (after.supervised && (first_tick_ || before.supervisor_connected != after.supervisor_connected)) {
    if (after.supervisor_connected) spdlog::info("supervisor's controller: {}", after.supervisor);
    else spdlog::warn("supervisor's controller: none connected: nothing moves without it");
  }
  if (after.state == run::OpState::kStopped) {
    // A stop is logged when it latches and when it becomes another's: not
    // when its pad is unplugged, which the controller's line says. What else
    // its words say meanwhile (a stop button held, let go) is information.
    const bool latched = any([](const run::Transition& t) {
      return !t.again && (t.event == run::OpEvent::kOperatorStop || t.event == run::OpEvent::kSupervisorStop ||
                          t.event == run::OpEvent::kGateTrip);
    });
    if (entered || latched) {
      spdlog::warn("STOP: {}", after.enable_text);
    } else if (before.enable_text != after.enable_text) {
      spdlog::info("stopped: {}", after.enable_text);
    }
  } else if (entered || before.enable_text != after.enable_text) {
    if (after.enabled()) spdlog::info("{}", after.enable_text);
    else spdlog::info("{}: {}", run::to_string(after.state), after.enable_text);
  }
  if (!first_tick_ && before.layer != after.layer) {
    spdlog::info("layer: {}", after.layer.empty() ? "base" : after.layer);
  }
  if (shows_speed(after.speed) && (first_tick_ || before.speed != after.speed)) {
    spdlog::info("speed level {}", speed_text(after.speed));
  }
  if (before.weapons_mode != after.weapons_mode) {
    const auto layer = after.layer.empty() ? "base" : after.layer;
    if (after.weapons_mode) spdlog::warn("WEAPONS LAYER on ({}): an armed fire input fires", layer);
    else spdlog::info("weapons layer off");
  }
}

void RunStatusBoard::set_mapping(std::string robot, std::string mapping_file, bool weapons, int center) {
  const std::lock_guard lock(mutex_);
  status_.robot = std::move(robot);
  status_.mapping_file = std::move(mapping_file);
  status_.weapons = weapons;
  status_.center = center;
}

void RunStatusBoard::set_pad_names(bool pad_names) {
  const std::lock_guard lock(mutex_);
  status_.pad_names = pad_names;
  said_.reset();  // the words may be new: a plain joystick's note
}

void RunStatusBoard::set_game_controller(std::optional<bool> game_controller) {
  const std::lock_guard lock(mutex_);
  status_.game_controller = game_controller;
  said_.reset();
}

RunStatus RunStatusBoard::status() const {
  const std::lock_guard lock(mutex_);
  RunStatus status = status_;
  status.sent_timing = timing_.summary(monotonic_ns());
  return status;
}

std::string state_text(const run::TickReport& r, const std::optional<run::Transition>& cause) {
  using run::OpState;
  switch (r.state) {
    case OpState::kNoLink:
      return "nothing reaches the vehicle (link " +
             (r.link.detail.empty() ? std::string("connecting") : r.link.detail) +
             "); once it is up, press the deadman afresh";
    case OpState::kNoController:
      if (!r.refusal.empty()) return printable_line(r.refusal);
      if (r.connected && r.supervised && !r.supervisor_connected) {
        return "connect the supervisor's controller, then press the deadman afresh";
      }
      return "connect a controller, then press the deadman";
    case OpState::kNotEnabled: {
      // The first cause, never its consequence (a deadman held through a
      // link regained reads "held since connect or start-up" to the engine).
      if (r.reset_by) {
        return "stop reset by the " + std::string(run::to_string(*r.reset_by)) + ": press the deadman afresh";
      }
      const auto afresh = [](const std::string& why) { return why + ": press the deadman afresh"; };
      const auto by = cause ? std::optional(cause->event) : std::nullopt;
      if (by == run::OpEvent::kLinkUp) return afresh("link regained");
      if (by == run::OpEvent::kReloadDone) {
        return afresh(cause->refused ? "reload refused, the old settings kept" : "reloaded");
      }
      if (by == run::OpEvent::kResume) return afresh("resumed");
      if (by == run::OpEvent::kControllerUp && cause->who == run::Who::kSupervisor) {
        return afresh("supervisor's controller back");
      }
      // At start-up, or a controller just connected, released is no cause: what enables is.
      if (r.engine.deadman == mapping::DeadmanState::kReleased) {
        if (!by) return "press the deadman to enable";
        if (by == run::OpEvent::kControllerUp) return "controller connected: press the deadman to enable";
      }
      return std::string(describe(r.engine.deadman));
    }
    case OpState::kEnabled: return enable_text(r.engine);
    case OpState::kStopped: return stopped_by_text(r) + ": " + stopped_text(r);
    case OpState::kSuspended: return "neutral frames sent, link closed until resumed";
    case OpState::kReloading: return "neutral frames while the settings are read";
    case OpState::kShuttingDown: return "sending neutral frames";
  }
  return "?";
}

namespace {

/// "hold back+start 2 s": a reset gesture as the operator makes it.
std::string hold_text(const std::string& gesture, std::int64_t hold_ms) {
  char seconds[16];
  std::snprintf(seconds, sizeof seconds, "%g", static_cast<double>(hold_ms) / 1000.0);
  return "hold " + gesture + " " + seconds + " s";
}

}  // namespace

std::string stopped_text(const run::TickReport& r) {
  const auto& e = r.engine;
  const std::int64_t hold_ms = e.reset_hold_ms;
  if (e.stop_held) return "a stop button is held: nothing resets until every stop button is released";
  const bool sup_may = r.supervisor_may_reset && !e.supervisor_reset.empty();
  const std::string sup_way = "the supervisor resets (" + hold_text(e.supervisor_reset, hold_ms) + " on its pad)";
  const std::string then = "; then press the deadman afresh";
  if (r.operator_may_reset && !e.operator_reset.empty()) {
    return "to reset, release the deadman and " + hold_text(e.operator_reset, hold_ms) +
           (sup_may ? " (or " + sup_way + ")" : "") + then;
  }
  if (r.stopped_by == run::StopBy::kSupervisor) {
    return "only the supervisor resets it" +
           (sup_may ? ": " + hold_text(e.supervisor_reset, hold_ms) + " on its pad" + then
                    : std::string(": its pad or the mapping has no reset; restart the bridge"));
  }
  std::string why;
  if (e.operator_reset.empty()) {
    why = "the mapping has no stop_reset";
  } else if (r.connected) {
    why = "this controller (" + printable_text(r.controller) + ") did not stop, " + r.stopper_pad.describe() + " did";
  } else {
    why = "the controller that stopped is gone";
  }
  return why + ": " + (sup_may ? sup_way + then : std::string("restart the bridge to go on"));
}

std::string reset_progress_text(const run::TickReport& r) {
  const auto& e = r.engine;
  if (r.state != run::OpState::kStopped || !e.reset_hold) return {};
  char progress[48];
  std::snprintf(progress, sizeof progress, "%.1f of %.1f s", static_cast<double>(e.reset_hold->held_ms) / 1000.0,
                static_cast<double>(e.reset_hold->hold_ms) / 1000.0);
  const bool sup = e.reset_hold->pad == input::Pad::kSupervisor;
  return std::string("resetting: ") + progress + " (" + (sup ? "the supervisor's " : "") +
         (sup ? e.supervisor_reset : e.operator_reset) + " held; a stop button or the deadman ends it)";
}

std::string stopped_by_text(const run::TickReport& r) {
  if (!r.stopped_by) return {};
  if (*r.stopped_by == run::StopBy::kGate) {
    return "stopped by the frame gate (an internal error: a frame broke a safety rule; see the log)";
  }
  return "stopped by the " + std::string(run::to_string(*r.stopped_by)) + " (" +
         (r.stopper_pad.name.empty() ? std::string("controller") : printable_text(r.stopper_pad.name)) + ")";
}

std::string joystick_note(bool pad_names, std::optional<bool> game_controller) {
  if (!pad_names || game_controller != false) return {};
  return "the controller is a plain joystick to SDL, not a game controller, and the mapping reads game-controller "
         "names (leftshoulder, leftx...): nothing it does reaches the mapping. Give SDL its mapping with "
         "--controller-db FILE (docs/controllers.md), or map its buttons with 'andros-bridge learn'";
}

std::string enable_text(const mapping::EngineStatus& status) {
  std::string text(describe(status.deadman));
  const auto held = held_back_text(status);
  return held.empty() ? text : text + "; at rest first: " + held;
}

std::string held_back_text(const mapping::EngineStatus& status) {
  std::string text;
  if (status.deadman != mapping::DeadmanState::kFreshHold) return text;
  for (const auto key : status.held_back) text += (text.empty() ? "" : " ") + input::input_name(key);
  return text;
}

}  // namespace andros::view
