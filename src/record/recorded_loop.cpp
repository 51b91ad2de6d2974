#include "andros/record/recorded_loop.hpp"

#include <optional>
#include <utility>

namespace andros::record {

void RecordingInput::pump(input::TickInput& input, std::int64_t now_ms) {
  input.keep_applied(true);
  inner_.pump(input, now_ms);
  recorder_.pumped(now_ms, input.take_applied());
}

bool RecordingInput::finished(std::int64_t now_ms) const {
  const bool done = inner_.finished(now_ms);
  if (done) recorder_.input_end(now_ms);
  return done;
}

run::RunControl recorded_control(run::RunControl control, Recorder& recorder,
                                 std::function<SessionSettings()> settings) {
  control.poll = [poll = std::move(control.poll), &recorder] {
    const run::Request r = poll();
    recorder.request(r);
    return r;
  };
  control.pause = [pause = std::move(control.pause), &recorder](const run::ShutdownReport& neutral) {
    pause(neutral);
    recorder.paused();
  };
  control.finish_reload = [finish = std::move(control.finish_reload), &recorder, settings = std::move(settings)] {
    auto outcome = finish();
    if (outcome) {
      if (outcome->ok) {
        // The settings put in place, read back for the record: should that
        // fail, the reload's records are dropped (counted), never the reload.
        std::optional<SessionSettings> now;
        try {
          now = settings();
        } catch (...) {
          recorder.drop();
          recorder.drop();
          return outcome;
        }
        recorder.reloaded(*outcome, &*now);
      } else {
        recorder.reloaded(*outcome, nullptr);
      }
    }
    return outcome;
  };
  return control;
}

}  // namespace andros::record
