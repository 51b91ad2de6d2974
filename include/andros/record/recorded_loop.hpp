#pragma once
/// The loop's input and controls with what they hand it recorded (the flight
/// recorder, recorder.hpp): the events it applies, the requests and reload
/// outcomes it answers.

#include <functional>

#include "andros/input/input_source.hpp"
#include "andros/record/recorder.hpp"
#include "andros/run/bridge.hpp"

namespace andros::record {

/// The input as the loop sees it, with every event it applies recorded.
class RecordingInput final : public input::InputSource {
 public:
  RecordingInput(input::InputSource& inner, Recorder& recorder) : inner_(inner), recorder_(recorder) {}
  void pump(input::TickInput& input, std::int64_t now_ms) override;
  [[nodiscard]] bool finished(std::int64_t now_ms) const override;
  void feedback(const input::FeedbackPattern& pattern) override { inner_.feedback(pattern); }
  // Everything else the loop and the screen ask of the input is the inner source's.
  [[nodiscard]] bool supervised() const override { return inner_.supervised(); }
  [[nodiscard]] std::optional<input::DeviceLayout> device() const override { return inner_.device(); }
  [[nodiscard]] std::string refusal() const override { return inner_.refusal(); }

 private:
  input::InputSource& inner_;
  Recorder& recorder_;
};

/// The loop's controls with what they answer recorded: requests, the end of a
/// job-control stop, reload outcomes (with the settings they put in place:
/// settings() is asked after an ok one).
run::RunControl recorded_control(run::RunControl control, Recorder& recorder,
                                 std::function<SessionSettings()> settings);

}  // namespace andros::record
