#include "andros/run/bridge.hpp"

#include <time.h>

#include <cerrno>
#include <exception>
#include <utility>

#include "andros/base/clock.hpp"

namespace andros::run {

void Bridge::run(const StopCheck& stop, const Observer& observe) {
  run(RunControl{[&stop] { return stop() ? Request::kStop : Request::kNone; }, [] {}}, observe);
}

void Bridge::run(const RunControl& control, const Observer& observe) {
  const std::int64_t start_ns = monotonic_ns();
  std::int64_t tick = 0;  // the tick to send next
  std::int64_t skipped = 0;
  try {
    while (true) {
      sleep_until_ns_uninterrupted(start_ns + schedule_.tick_ns(tick));
      const Request request = control.poll();
      if (request == Request::kStop) break;
      if (request == Request::kSuspend) {
        shutdown(start_ns, tick, observe);
        control.pause();
        frames_.restart();
        // Go on at the first tick still to come (the latest one due was the
        // pause's, or is past); unlike a stall, this gap was asked for.
        tick = schedule_.next_tick(tick, monotonic_ns() - start_ns) + 1;
        skipped = 0;
        continue;
      }
      if (request == Request::kReload) {
        send_neutral(start_ns, tick, observe, true);
        control.reload();
        frames_.restart();
        skipped = 0;
        continue;
      }
      if (request == Request::kResumed) frames_.restart();
      const std::int64_t t_ms = schedule_.tick_ms(tick);
      // The input is read right after the tick's time: never older than the frame.
      input_.pump(state_, t_ms);
      Step step = frames_.step(state_, t_ms);
      engine_status_ = std::move(step.status);
      if (!link_.motion_allowed()) step.data = frames_.neutral();
      const link::SendResult result = link_.send(protocol::encode(step.data), monotonic_ns());
      observe(report(tick, t_ms, skipped, step.data, result, false));
      const std::int64_t next = schedule_.next_tick(tick, monotonic_ns() - start_ns);
      skipped = next - tick - 1;
      tick = next;
      if (input_.finished(t_ms)) break;
    }
  } catch (...) {
    shutdown(start_ns, tick, observe);
    throw;
  }
  shutdown(start_ns, tick, observe);
}

/// Neutral frames from tick `tick` (not sent yet) on.
void Bridge::shutdown(std::int64_t start_ns, std::int64_t tick, const Observer& observe) {
  shutdown_report_.neutral_sent = send_neutral(start_ns, tick, observe, false);
  shutdown_report_.neutral_wanted = options_.shutdown_frames;
  shutdown_report_.drained = link_.drain_and_close(options_.drain_timeout_ms);
}

int Bridge::send_neutral(std::int64_t start_ns, std::int64_t& tick, const Observer& observe, bool reloading) {
  const protocol::DataBytes neutral = frames_.neutral();
  const protocol::Frame frame = protocol::encode(neutral);
  int sent = 0;
  // A frame the link could not take this tick (busy, reconnecting) is tried
  // again on the next one, a few ticks at most, so that shutdown stays short.
  for (int i = 0; sent < options_.shutdown_frames &&
                  i < options_.shutdown_frames + options_.shutdown_extra_ticks;
       ++i) {
    if (i > 0) tick = schedule_.next_tick(tick, monotonic_ns() - start_ns);
    sleep_until_ns_uninterrupted(start_ns + schedule_.tick_ns(tick));
    const link::SendResult result = link_.send(frame, monotonic_ns());
    if (result == link::SendResult::kSent) ++sent;
    TickReport r = report(tick, schedule_.tick_ms(tick), 0, neutral, result, !reloading);
    r.reloading = reloading;
    observe(r);
  }
  tick = schedule_.next_tick(tick, monotonic_ns() - start_ns);
  return sent;
}

TickReport Bridge::report(std::int64_t tick, std::int64_t t_ms, std::int64_t skipped,
                          const protocol::DataBytes& data, link::SendResult result, bool shutting_down) const {
  return TickReport{tick, t_ms, skipped, data, result, shutting_down,
                    state_.connected(), state_.name(), engine_status_, link_.status()};
}

}  // namespace andros::run
