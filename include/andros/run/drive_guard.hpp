#pragma once
/// The guards with memory and time that feed the operating-state machine
/// (operating_state.hpp), beside it in the run loop: the deadman's freshness
/// and its panic latch (deadman.hpp), the enable timeout, and the stop
/// buttons with their reset holds (stop_buttons.hpp). The mapping names the
/// inputs they read (which is the deadman, which a stop button, which a
/// reset gesture, and every input whose change keeps the enable timeout from
/// running out); the mapping engine maps, and decides nothing of this. Each
/// guard counts presses per controller session and starts afresh at a rebase.

#include <cstdint>
#include <map>
#include <optional>
#include <vector>

#include "andros/input/input_state.hpp"
#include "andros/mapping/engine_status.hpp"
#include "andros/mapping/model.hpp"
#include "andros/run/deadman.hpp"
#include "andros/run/stop_buttons.hpp"

namespace andros::run {

class DriveGuard {
 public:
  explicit DriveGuard(const mapping::Mapping& mapping);

  /// A driving tick's facts at now_ms, before the machine decides: what the
  /// deadman did (a fresh press, released, not fresh, the panic, the enable
  /// timeout) and the stop buttons pressed or held (taking the presses).
  /// enabled: the machine is enabled now (the enable timeout runs only
  /// then). The first call is start-up: deadman presses counted before it are not fresh.
  mapping::InputFacts facts(const input::InputState& input, std::int64_t now_ms, bool enabled);
  /// The machine's decision for the tick's step: enabling is the first
  /// change the enable timeout counts from.
  void decided(bool motion_allowed, std::int64_t now_ms);
  /// The stop buttons pressed since the last read or held, taking the
  /// presses (for the ticks that are not driven: a reload's, a suspend's
  /// neutral frames; and before a rebase, which makes every press history).
  /// Ends any reset hold.
  mapping::StopPresses take_stop(const input::InputState& input);
  /// Stopped, once per tick: the stop buttons pressed since the last call,
  /// and a reset hold completed (StopButtons::stopped).
  StoppedTick stopped(const input::InputState& input, std::int64_t now_ms);
  /// Starts afresh from the input as it is now (the loop's rebase): every
  /// press so far is history, the deadman needs a fresh press.
  void rebase(const input::InputState& now);

  /// The guards' part of the status after a driving tick, into status: the
  /// deadman's state and the stop buttons pressed, from its facts(); those held now, the reset gestures.
  void report(const input::InputState& input, mapping::EngineStatus& status) const;
  /// Stopped: which stop buttons are held now, and the reset gestures, into status.
  void report_held(const input::InputState& input, mapping::EngineStatus& status) const { stops_.held(input, status); }

 private:
  /// Start-up, or a controller's new session (the operator's, the supervisor's): afresh.
  void follow_sessions(const input::InputState& input);
  void start_session(const input::InputState& input, bool at_start_up);
  /// Notes whether any input the mapping reads changed since the last change (the enable timeout).
  void note_activity(const input::InputState& input, std::int64_t now_ms);
  /// Enabled, and no input changed for the mapping's enable_timeout by now_ms.
  [[nodiscard]] bool timed_out(std::int64_t now_ms) const;

  mapping::ReadInputs inputs_;                  ///< every input the mapping reads (the enable timeout's)
  std::optional<std::int64_t> enable_timeout_;  ///< the mapping's `enable_timeout:`
  Deadman deadman_;
  StopButtons stops_;
  bool started_ = false;
  std::uint32_t connection_ = 0;                                    ///< the operator's controller session
  std::uint32_t supervisor_connection_ = 0;                         ///< the supervisor's
  bool was_enabled_ = false;                                        ///< motion allowed at the last driving tick
  std::int64_t last_activity_ms_ = 0;                               ///< the last tick that saw an input change
  std::map<input::InputKey, input::ButtonState> activity_buttons_;  ///< as at that tick
  std::map<input::InputKey, std::int16_t> activity_axes_;
  mapping::DeadmanState enable_ = mapping::DeadmanState::kNoPad;  ///< the last driving tick's
  mapping::StopPresses stop_pressed_;                             ///< and its stop buttons
};

}  // namespace andros::run
