#include "andros/run/bridge.hpp"

#include <algorithm>
#include <utility>

namespace andros::run {

Bridge::Bridge(Clock& clock, input::InputSource& input, FrameSource& frames, link::Link& link, BridgeOptions options)
    : clock_(clock),
      source_(input),
      frames_(&frames),
      link_(link),
      options_(options),
      schedule_(options.rate_millihertz),
      machine_(link_up()),
      guard_(frames.mapping()),
      gate_(options.rules) {}

void Bridge::run(const ShutdownCheck& shutdown, const Observer& observe) {
  RunControl control;
  control.poll = [&shutdown] { return shutdown() ? Request::kShutdown : Request::kNone; };
  run(control, observe);
}

void Bridge::run(const RunControl& control, const Observer& observe) {
  control_ = &control;
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
    apply(OpEvent::kShutdown, Who::kScript);
    while (tick(control, observe)) {
    }
    control_ = nullptr;
    throw;
  }
  control_ = nullptr;
}

bool Bridge::tick(const RunControl& control, const Observer& observe) {
  clock_.sleep_until(start_ + Nanos(schedule_.tick_ns(tick_)));
  const std::int64_t t_ms = schedule_.tick_ms(tick_);
  if (!input_failed_) {
    // The input is read right after the tick's time: never older than the
    // frame; every change since the last tick counts, not only where it ended.
    input_.begin_tick();
    source_.pump(pumped_, t_ms);
    // The pads in each role, as numbers: the machine decides on them; the registry keeps what is said of them.
    operator_pad_ = pads_.id_of(input_.operator_pad().identity());
    supervisor_pad_ = pads_.id_of(input_.supervisor().identity());
    machine_.set_pads(operator_pad_, supervisor_pad_);
    pads_.keep({operator_pad_, supervisor_pad_, machine_.stopper_pad(), machine_.reset_pad()});
    on_request(control.poll());
    for (const auto& fault : pumped_.take_faults()) on_fault(fault);
    // Every configured controller: losing the supervisor's stops motion as losing the operator's does.
    const bool controllers_up = input_.connected() && (!source_.supervised() || input_.supervisor().connected());
    if (controllers_up) {
      if (!machine_.controller_up()) apply(OpEvent::kControllerUp);  // the machine knows whose it was
    } else if (machine_.controller_up()) {
      // Both needed and only the supervisor's missing: it is the one lost.
      apply(OpEvent::kControllerDown, input_.connected() ? Who::kSupervisor : Who::kOperator);
    }
  }

  // A suspend's and a reload's ticks do not step the engine: a stop button
  // pressed in them latches for when they end (the latch only: no row there).
  if (machine_.state() == OpState::kSuspended || machine_.state() == OpState::kReloading) {
    answer_stops(guard_.take_stop(input_));
  }
  switch (machine_.state()) {
    case OpState::kShuttingDown:
      if (neutral_frame(observe)) {
        close();
        return false;
      }
      break;
    case OpState::kSuspended:
      if (!machine_.neutral_due()) {
        // Its frames are out: nothing is sent until the resume (a script's suspend; job control pauses below).
        observe(report(frames_->neutral(), link::SendResult::kDown, false));
      } else if (neutral_frame(observe)) {
        close();
        apply(OpEvent::kNeutralSent);  // a resume that waited for the frames is answered now: no pause
        if (machine_.state() == OpState::kSuspended && suspend_pauses_) {
          pause(control);
          return true;
        }
      }
      break;
    case OpState::kStopped: {
      // The engine is not stepped: nothing the hands do while stopped acts
      // (a selector, a knob), and nothing held enables. A stop pressed again
      // is recorded and keeps the latch (the supervisor's makes it the
      // supervisor's); reset by a reset gesture on the pad that stopped (or
      // the supervisor's), never while a stop button is held.
      const auto stops = guard_.stopped(input_, t_ms);
      answer_stops(stops.pressed);
      if (stops.reset) {
        apply(*stops.reset == input::Pad::kSupervisor ? OpEvent::kSupervisorReset : OpEvent::kOperatorReset);
      }
      guard_.report_held(input_, engine_status_);  // what the screen says is held, now
      if (machine_.state() == OpState::kStopped) engine_status_.reset_hold = stops.hold;
      send(frames_->neutral(), observe);
      break;
    }
    case OpState::kReloading:
      if (neutral_frame(observe)) {
        if (machine_.neutral_due()) apply(OpEvent::kNeutralSent);
        if (const auto outcome = control.finish_reload()) {
          if (outcome->ok) gate_.set_weapons(outcome->weapons);
          if (outcome->ok && outcome->frames) {
            reloaded_ = outcome->frames;
            frames_ = reloaded_.get();
            guard_ = DriveGuard(frames_->mapping());  // the new mapping's inputs, read afresh
          }
          // A suspend that waited for the outcome begins now.
          apply(OpEvent::kReloadDone, Who::kLoop, !outcome->ok);
        }
      }
      break;
    default: drive(t_ms, observe); break;
  }
  advance();
  if (!input_failed_ && machine_.state() != OpState::kShuttingDown && source_.finished(t_ms)) {
    if (!options_.neutral_tail_at_end) return false;
    apply(OpEvent::kShutdown, Who::kScript);
  }
  return true;
}

void Bridge::drive(std::int64_t t_ms, const Observer& observe) {
  // The facts first: a stop button, the deadman, the panic, the timeout.
  const mapping::InputFacts facts = guard_.facts(input_, t_ms, machine_.motion_allowed());
  // A link known to be down (a fault, a stalled server) is so before the frame is chosen.
  if (machine_.link_up() && !link_up()) link_changed(false);
  act(machine_.on(facts), false);
  // The machine decided; the engine maps what it allows.
  guard_.decided(machine_.motion_allowed(), t_ms);
  Step step = frames_->step(input_, t_ms, machine_.motion_allowed());
  engine_status_ = std::move(step.status);
  guard_.report(input_, engine_status_);
  send(step.data, observe);
}

void Bridge::answer_stops(mapping::StopPresses pressed) {
  if (pressed.by_operator) apply(OpEvent::kOperatorStop);
  if (pressed.by_supervisor) apply(OpEvent::kSupervisorStop);
}

Effect Bridge::apply(OpEvent event, Who who, bool refused) {
  return act(machine_.on(event, who, refused), event == OpEvent::kOperatorReset || event == OpEvent::kSupervisorReset);
}

Effect Bridge::act(Effect effect, bool reset) {
  if (effect.rebase) {
    // A stop button pressed and not yet answered is answered before the
    // rebase makes its press history (a reset takes the presses made while stopped).
    // Stopped already, a button held through it changes nothing but whose the stop is.
    const auto pressed = guard_.take_stop(input_);
    const bool stopped = machine_.state() == OpState::kStopped;
    if (!reset && !stopped && pressed.by_operator) {
      effect.changed = machine_.on(OpEvent::kOperatorStop).changed || effect.changed;
    }
    if (!reset && pressed.by_supervisor && (!stopped || machine_.stopped_by() != StopBy::kSupervisor)) {
      effect.changed = machine_.on(OpEvent::kSupervisorStop).changed || effect.changed;
    }
    guard_.rebase(input_);
    frames_->rebase(input_);
  }
  if (effect.neutral_frames) start_sequence();
  if (effect.begin_reload && control_ != nullptr) control_->begin_reload(reload_mapping_);
  for (const auto& t : machine_.take_transitions()) transitions_.push_back({t, pads_.identity(t.pad)});
  return effect;
}

void Bridge::link_changed(bool up, Who who) { apply(up ? OpEvent::kLinkUp : link_lost_event(), who); }

link::SendResult Bridge::send(const protocol::DataBytes& offered, const Observer& observe) {
  // The last gate (docs/safety-states.md): a frame breaking a rule never reaches the link, and the loop stops.
  GateVerdict gate = gate_.pass(offered, machine_.motion_allowed());
  if (gate.tripped()) apply(OpEvent::kGateTrip);
  const link::SendResult result = link_.send(protocol::encode(gate.data), clock_.now().count());
  if (link_up() != machine_.link_up()) link_changed(link_up());
  TickReport r = report(gate.data, result, true);
  r.gate_fault = std::move(gate.fault);
  observe(r);
  return result;
}

bool Bridge::link_up() const { return link::carries_motion(link_.state(), link_.far_end_reading()); }

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
  if (send(frames_->neutral(), observe) == link::SendResult::kSent) ++sequence_sent_;
  ++sequence_ticks_;
  return sequence_done();
}

void Bridge::close() {
  shutdown_report_.neutral_sent = sequence_sent_;
  shutdown_report_.neutral_wanted = options_.shutdown_frames;
  shutdown_report_.drained = link_.drain_and_close(options_.drain_timeout_ms);
  apply(OpEvent::kLinkDown, Who::kLoop);  // closed (in these states, only the condition changes)
}

void Bridge::pause(const RunControl& control) {
  control.pause(shutdown_report_);
  // Go on at the first tick still to come: unlike a stall, this gap was asked for.
  const std::int64_t elapsed = (clock_.now() - start_).count();
  tick_ = std::max(tick_ + 1, schedule_.next_tick(-1, elapsed) + 1);
  skipped_ = 0;
  // What happened while the process was stopped is history too.
  input_.begin_tick();
  source_.pump(pumped_, elapsed / kNsPerMs);
  apply(OpEvent::kResume, Who::kRequest);
}

void Bridge::advance() {
  const std::int64_t next = schedule_.next_tick(tick_, (clock_.now() - start_).count());
  skipped_ = next - tick_ - 1;
  tick_ = next;
}

TickReport Bridge::report(const protocol::DataBytes& data, link::SendResult result, bool sent) {
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
  r.stopper_pad = pads_.identity(machine_.stopper_pad());
  r.reset_pad = pads_.identity(machine_.reset_pad());
  r.operator_may_reset = machine_.may_reset(StopBy::kOperator, operator_pad_);
  r.supervisor_may_reset = source_.supervised() && machine_.may_reset(StopBy::kSupervisor, supervisor_pad_);
  r.transitions = std::exchange(transitions_, {});
  r.connected = input_.connected();
  r.controller = input_.name();
  r.supervised = source_.supervised();
  r.supervisor_connected = input_.supervisor().connected();
  r.supervisor = input_.supervisor().name();
  r.refusal = source_.refusal();
  r.engine = engine_status_;
  r.link = link_.status();
  r.gate_trips = gate_.trips();
  return r;
}

}  // namespace andros::run
