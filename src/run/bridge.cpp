#include "andros/run/bridge.hpp"

#include <algorithm>
#include <utility>

namespace andros::run {

Bridge::Bridge(Clock& clock, input::InputSource& input, FrameSource& frames, link::Link& link, BridgeOptions options)
    : clock_(clock),
      input_(input),
      frames_(frames),
      link_(link),
      options_(options),
      schedule_(options.rate_millihertz),
      machine_(link_up()),
      gate_(options.rules) {}

void Bridge::run(const StopCheck& stop, const Observer& observe) {
  RunControl control;
  control.poll = [&stop] { return stop() ? Request::kStop : Request::kNone; };
  run(control, observe);
}

void Bridge::run(const RunControl& control, const Observer& observe) {
  start_ = clock_.now();
  tick_ = 0;
  skipped_ = 0;
  input_failed_ = false;
  try {
    while (tick(control, observe)) {
    }
  } catch (...) {
    // A script's bad line: the neutral frames still go first, without the input.
    input_failed_ = true;
    apply(OpEvent::kShutdown);
    while (tick(control, observe)) {
    }
    throw;
  }
}

bool Bridge::tick(const RunControl& control, const Observer& observe) {
  clock_.sleep_until(start_ + Nanos(schedule_.tick_ns(tick_)));
  const std::int64_t t_ms = schedule_.tick_ms(tick_);
  if (!input_failed_) {
    // The input is read right after the tick's time: never older than the
    // frame; every change since the last tick counts, not only where it ended.
    state_.begin_tick();
    input_.pump(state_, t_ms);
    on_request(control.poll(), control);
    for (const auto& fault : state_.take_faults()) on_fault(fault, control);
    // Every configured controller: losing the supervisor's stops motion as losing the operator's does.
    const bool controllers_up = state_.connected() && (!input_.supervised() || state_.supervisor().connected());
    if (controllers_up != machine_.controller_up()) {
      apply(controllers_up ? OpEvent::kControllerUp : OpEvent::kControllerDown);
    }
  }

  // A suspend's and a reload's ticks do not step the engine: a stop button
  // pressed in them latches for when they end (the latch only: no row there).
  if (machine_.state() == OpState::kSuspended || machine_.state() == OpState::kReloading) {
    answer_stops(frames_.take_stop(state_));
  }
  switch (machine_.state()) {
    case OpState::kStopping:
      if (neutral_frame(observe)) {
        close();
        return false;
      }
      break;
    case OpState::kSuspended:
      if (!suspend_frames_due_) {
        // Suspended by a script: nothing is sent until its resume.
        observe(report(frames_.neutral(), link::SendResult::kDown, false));
      } else if (neutral_frame(observe)) {
        close();
        suspend_frames_due_ = false;
        if (std::exchange(resume_pending_, false)) {
          // Continued (fg, SIGCONT, a script's resume) during the frames: no stop.
          resumed(control);
        } else if (pause_after_suspend_) {
          pause(control);
          return true;
        }
      }
      break;
    case OpState::kStopped: {
      // The engine is not stepped: nothing the hands do while stopped acts
      // (a selector, a knob), and nothing held enables. Reset by a reset
      // hold on the pad that stopped (or the supervisor's); a press of the
      // supervisor's stop while stopped makes the stop the supervisor's.
      const auto stops = frames_.stopped(state_, t_ms);
      answer_stops(stops.pressed);
      if (stops.reset) {
        apply(*stops.reset == input::Pad::kSupervisor ? OpEvent::kSupervisorReset : OpEvent::kOperatorReset);
      }
      frames_.held_stops(state_, engine_status_);  // what the screen says is held, now
      send(frames_.neutral(), observe);
      break;
    }
    case OpState::kReloading:
      if (const auto outcome = neutral_frame(observe) ? control.finish_reload() : std::nullopt) {
        if (outcome->ok) gate_.set_weapons(outcome->weapons);
        apply(OpEvent::kReloadDone);
        if (std::exchange(suspend_pending_, false)) begin_suspend();
      }
      break;
    default: {
      Step step = frames_.step(state_, t_ms);
      engine_status_ = std::move(step.status);
      // A link known to be down (a fault, a stalled server) is so before the frame is chosen.
      if (machine_.link_up() && !link_up()) apply(link_lost_event());
      answer_engine();
      send(machine_.motion_allowed() ? step.data : frames_.neutral(), observe);
      break;
    }
  }
  advance();
  if (!input_failed_ && machine_.state() != OpState::kStopping && input_.finished(t_ms)) {
    if (!options_.neutral_tail_at_end) return false;
    apply(OpEvent::kShutdown);
  }
  return true;
}

void Bridge::answer_engine() {
  using mapping::EnableState;
  const auto& e = engine_status_;
  // A stop button first: pressed this tick, this tick's frame is neutral.
  answer_stops(e.stop_pressed);
  const bool engine_enabled = e.enable == EnableState::kEnabled;
  if (machine_.state() == OpState::kNotEnabled && engine_enabled) apply(OpEvent::kFreshPress);
  if (machine_.state() == OpState::kEnabled && !engine_enabled) {
    apply(e.enable == EnableState::kPanic      ? OpEvent::kPanic
          : e.enable == EnableState::kTimedOut ? OpEvent::kEnableTimeout
                                               : OpEvent::kRelease);
  }
}

void Bridge::answer_stops(mapping::StopPresses pressed) {
  if (pressed.by_operator) apply(OpEvent::kOperatorStop);
  if (pressed.by_supervisor) apply(OpEvent::kSupervisorStop);
}

Effect Bridge::apply(OpEvent event) {
  Effect effect = machine_.on(event);
  if (effect.rebase) {
    // A stop button pressed and not yet answered is answered before the
    // rebase makes its press history (a reset takes the presses made while stopped).
    const bool reset = event == OpEvent::kOperatorReset || event == OpEvent::kSupervisorReset;
    const auto pressed = frames_.take_stop(state_);
    if (!reset && pressed.by_operator) effect.changed = machine_.on(OpEvent::kOperatorStop).changed || effect.changed;
    if (!reset && pressed.by_supervisor) {
      effect.changed = machine_.on(OpEvent::kSupervisorStop).changed || effect.changed;
    }
    frames_.restart(state_);
  }
  // Each of these begins with its own neutral frames.
  const OpState now = machine_.state();
  if (effect.changed && (now == OpState::kStopping || now == OpState::kSuspended || now == OpState::kReloading)) {
    start_sequence();
  }
  return effect;
}

link::SendResult Bridge::send(const protocol::DataBytes& offered, const Observer& observe) {
  // The last gate (docs/safety-states.md): a frame breaking a rule never reaches the link, and the loop stops.
  GateVerdict gate = gate_.pass(offered, machine_.motion_allowed());
  if (gate.tripped()) apply(OpEvent::kGateTrip);
  const link::SendResult result = link_.send(protocol::encode(gate.data), clock_.now().count());
  if (link_up() != machine_.link_up()) apply(link_up() ? OpEvent::kLinkUp : link_lost_event());
  TickReport r = report(gate.data, result, true);
  r.gate_fault = std::move(gate.fault);
  observe(r);
  return result;
}

bool Bridge::link_up() const {
  // A link that stalled (TCP) gets neutral frames only: for the state, it is not up.
  return link_.state() == link::LinkState::kUp && link_.motion_allowed();
}

OpEvent Bridge::link_lost_event() const {
  return link_.fault() == link::FaultLink::Fault::kTaken ? OpEvent::kLinkTaken : OpEvent::kLinkDown;
}

void Bridge::start_sequence() {
  sequence_sent_ = 0;
  sequence_ticks_ = 0;
}

bool Bridge::sequence_done() const {
  // A frame the link could not take this tick (busy, reconnecting) is tried
  // again on the next one, a few ticks at most, so that a stop stays short.
  return sequence_sent_ >= options_.shutdown_frames ||
         sequence_ticks_ >= options_.shutdown_frames + options_.shutdown_extra_ticks;
}

bool Bridge::neutral_frame(const Observer& observe) {
  if (send(frames_.neutral(), observe) == link::SendResult::kSent) ++sequence_sent_;
  ++sequence_ticks_;
  return sequence_done();
}

void Bridge::close() {
  shutdown_report_.neutral_sent = sequence_sent_;
  shutdown_report_.neutral_wanted = options_.shutdown_frames;
  shutdown_report_.drained = link_.drain_and_close(options_.drain_timeout_ms);
  apply(OpEvent::kLinkDown);  // closed (in these states, only the condition changes)
}

void Bridge::pause(const RunControl& control) {
  control.pause();
  // Go on at the first tick still to come: unlike a stall, this gap was asked for.
  const std::int64_t elapsed = (clock_.now() - start_).count();
  tick_ = std::max(tick_ + 1, schedule_.next_tick(-1, elapsed) + 1);
  skipped_ = 0;
  // What happened while the process was stopped is history too.
  state_.begin_tick();
  input_.pump(state_, elapsed / kNsPerMs);
  resume_pending_ = false;
  resumed(control);
}

void Bridge::advance() {
  const std::int64_t next = schedule_.next_tick(tick_, (clock_.now() - start_).count());
  skipped_ = next - tick_ - 1;
  tick_ = next;
}

TickReport Bridge::report(const protocol::DataBytes& data, link::SendResult result, bool sent) const {
  TickReport r;
  r.tick = tick_;
  r.t_ms = schedule_.tick_ms(tick_);
  r.skipped = skipped_;
  r.data = data;
  r.result = result;
  r.sent = sent;
  r.state = machine_.state();
  r.stopped_by = machine_.stopped_by();
  r.reset_by = machine_.reset_by();
  r.connected = state_.connected();
  r.controller = state_.name();
  r.supervised = input_.supervised();
  r.supervisor_connected = state_.supervisor().connected();
  r.supervisor = state_.supervisor().name();
  r.engine = engine_status_;
  r.link = link_.status();
  r.gate_trips = gate_.trips();
  return r;
}

}  // namespace andros::run
