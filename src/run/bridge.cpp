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
      machine_(link_up()) {}

void Bridge::run(const StopCheck& stop, const Observer& observe) {
  RunControl control;
  control.poll = [&stop] { return stop() ? Request::kStop : Request::kNone; };
  run(control, observe);
}

void Bridge::run(const RunControl& control, const Observer& observe) {
  start_ = clock_.now();
  tick_ = 0;
  skipped_ = 0;
  closed_ = false;
  try {
    while (tick(control, observe)) {
    }
  } catch (...) {
    // A script's bad line: the neutral frames still go first.
    if (!closed_) {
      apply(OpEvent::kShutdown);
      neutral_then_close(observe);
    }
    throw;
  }
}

bool Bridge::tick(const RunControl& control, const Observer& observe) {
  clock_.sleep_until(start_ + Nanos(schedule_.tick_ns(tick_)));
  const std::int64_t t_ms = schedule_.tick_ms(tick_);
  if (machine_.state() == OpState::kStopping) {
    neutral_then_close(observe);
    return false;
  }
  // The input is read right after the tick's time: never older than the frame.
  input_.pump(state_, t_ms);
  on_request(control.poll(), control);
  for (const auto& fault : state_.take_faults()) on_fault(fault, control);
  if (state_.connected() != machine_.controller_up()) {
    apply(state_.connected() ? OpEvent::kControllerUp : OpEvent::kControllerDown);
  }

  switch (machine_.state()) {
    case OpState::kStopping:
      neutral_then_close(observe);
      return false;
    case OpState::kSuspended:
      if (suspend_frames_due_) {
        suspend(control, observe);
        return true;
      }
      // A script's suspend: nothing is sent until its resume.
      observe(report(frames_.neutral(), link::SendResult::kDown, false));
      break;
    case OpState::kReloading:
      if (send(frames_.neutral(), observe) == link::SendResult::kSent) ++reload_neutral_;
      ++reload_ticks_;
      if (reload_neutral_ >= options_.shutdown_frames ||
          reload_ticks_ >= options_.shutdown_frames + options_.shutdown_extra_ticks) {
        if (control.finish_reload()) {
          apply(OpEvent::kReloadDone);
          if (std::exchange(suspend_pending_, false)) begin_suspend();
        }
      }
      break;
    default: {
      Step step = frames_.step(state_, t_ms);
      engine_status_ = std::move(step.status);
      // A link known to be down (a fault, a stalled server) is so before the frame is chosen.
      if (machine_.link_up() && !link_up()) apply(link_lost_event());
      const bool engine_enabled = engine_status_.enable == mapping::EnableState::kEnabled;
      if (machine_.state() == OpState::kNotEnabled && engine_enabled) apply(OpEvent::kFreshPress);
      if (machine_.state() == OpState::kEnabled && !engine_enabled) apply(OpEvent::kRelease);
      send(machine_.motion_allowed() ? step.data : frames_.neutral(), observe);
      break;
    }
  }
  advance();
  if (input_.finished(t_ms)) {
    if (!options_.neutral_tail_at_end) return false;
    apply(OpEvent::kShutdown);
  }
  return true;
}

void Bridge::on_request(Request request, const RunControl& control) {
  switch (request) {
    case Request::kNone: break;
    case Request::kStop: apply(OpEvent::kShutdown); break;
    case Request::kSuspend:
      pause_after_suspend_ = true;
      begin_suspend();
      break;
    case Request::kResumed: apply(OpEvent::kResume); break;
    case Request::kReload: begin_reload(control, ""); break;
  }
}

void Bridge::on_fault(const input::InputEvent& fault, const RunControl& control) {
  using T = input::InputEvent::Type;
  switch (fault.type) {
    case T::kLinkDown: link_.set_fault(link::FaultLink::Fault::kDown); break;
    case T::kLinkTaken: link_.set_fault(link::FaultLink::Fault::kTaken); break;
    case T::kLinkUp: link_.set_fault(link::FaultLink::Fault::kNone); break;
    case T::kSuspend:
      pause_after_suspend_ = false;
      begin_suspend();
      break;
    case T::kResume:
      // Answered once the suspend's neutral frames are out.
      if (suspend_frames_due_) {
        resume_pending_ = true;
      } else {
        apply(OpEvent::kResume);
      }
      break;
    case T::kReload: begin_reload(control, fault.name); break;
    case T::kStop: apply(OpEvent::kShutdown); break;
    default: break;
  }
}

Effect Bridge::apply(OpEvent event) {
  const Effect effect = machine_.on(event);
  if (effect.rebase) frames_.restart(state_);
  return effect;
}

void Bridge::begin_suspend() {
  if (machine_.state() == OpState::kReloading) {
    suspend_pending_ = true;  // after the reload's outcome
    return;
  }
  if (apply(OpEvent::kSuspend).changed) suspend_frames_due_ = true;
}

void Bridge::begin_reload(const RunControl& control, const std::string& mapping) {
  // A second one while one runs is the control's to queue (the files read
  // again); while suspended and while stopping it is ignored (no row).
  if (machine_.state() == OpState::kReloading) {
    control.begin_reload(mapping);
    return;
  }
  if (!apply(OpEvent::kReloadBegin).changed) return;
  reload_neutral_ = 0;
  reload_ticks_ = 0;
  control.begin_reload(mapping);
}

link::SendResult Bridge::send(const protocol::DataBytes& data, const Observer& observe) {
  const link::SendResult result = link_.send(protocol::encode(data), clock_.now().count());
  if (link_up() != machine_.link_up()) apply(link_up() ? OpEvent::kLinkUp : link_lost_event());
  observe(report(data, result, true));
  return result;
}

bool Bridge::link_up() const {
  // A link that stalled (TCP) gets neutral frames only: for the state, it is not up.
  return link_.state() == link::LinkState::kUp && link_.motion_allowed();
}

OpEvent Bridge::link_lost_event() const {
  return link_.fault() == link::FaultLink::Fault::kTaken ? OpEvent::kLinkTaken : OpEvent::kLinkDown;
}

void Bridge::neutral_then_close(const Observer& observe) {
  const protocol::DataBytes neutral = frames_.neutral();
  const protocol::Frame frame = protocol::encode(neutral);
  int sent = 0;
  // A frame the link could not take this tick (busy, reconnecting) is tried
  // again on the next one, a few ticks at most, so that a stop stays short.
  for (int i = 0; sent < options_.shutdown_frames &&
                  i < options_.shutdown_frames + options_.shutdown_extra_ticks;
       ++i) {
    if (i > 0) {
      advance();
      clock_.sleep_until(start_ + Nanos(schedule_.tick_ns(tick_)));
    }
    skipped_ = 0;
    const link::SendResult result = link_.send(frame, clock_.now().count());
    if (result == link::SendResult::kSent) ++sent;
    observe(report(neutral, result, true));
  }
  advance();
  shutdown_report_.neutral_sent = sent;
  shutdown_report_.neutral_wanted = options_.shutdown_frames;
  shutdown_report_.drained = link_.drain_and_close(options_.drain_timeout_ms);
  closed_ = machine_.state() == OpState::kStopping;
  apply(OpEvent::kLinkDown);  // closed (in these states, only the condition changes)
}

void Bridge::suspend(const RunControl& control, const Observer& observe) {
  neutral_then_close(observe);
  suspend_frames_due_ = false;
  if (pause_after_suspend_) {
    control.pause();
    // Go on at the first tick still to come: unlike a stall, this gap was asked for.
    const std::int64_t elapsed = (clock_.now() - start_).count();
    tick_ = std::max(tick_, schedule_.next_tick(-1, elapsed) + 1);
    skipped_ = 0;
    // What happened while the process was stopped is history too.
    input_.pump(state_, elapsed / kNsPerMs);
    apply(OpEvent::kResume);
  } else if (std::exchange(resume_pending_, false)) {
    apply(OpEvent::kResume);
  }
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
  r.connected = state_.connected();
  r.controller = state_.name();
  r.engine = engine_status_;
  r.link = link_.status();
  return r;
}

}  // namespace andros::run
