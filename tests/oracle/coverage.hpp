#pragma once
// What the fault simulation's oracle (safety_oracle.hpp) counts: the events
// that end "enabled", and what the frames reached, summed over scripts, so
// that a test can ask that each rule was really exercised.

#include <array>
#include <cstddef>
#include <cstdint>

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
  kLinkStalled,
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
      "start",        "connect",     "disconnect", "deadman release", "link down",          "link up",
      "link stalled", "suspend",     "resume",     "reload (same)",   "reload (good file)", "reload (bad file)",
      "stop",         "stop button", "stop reset", "panic squeeze",   "enable timeout"};
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
  std::int64_t refused_resets = 0;  ///< resets made and refused: the operator's of the supervisor's stop, another pad's
  std::int64_t supervised_frames = 0;  ///< frames of scripts with a supervisor's controller
  std::int64_t gated = 0;              ///< frames offered to the link, each checked by the frame gate
  std::int64_t gate_refused = 0;       ///< runs with an engine at fault whose frame the gate refused
  std::int64_t rest_held = 0;          ///< enabled frames where the rest rule held drive or pivot at the trim
  std::int64_t trimmed = 0;            ///< frames of a mapping whose centre is not 128

  OracleCoverage& operator+=(const OracleCoverage& o) {
    using C = OracleCoverage;
    for (const auto count :
         {&C::frames, &C::motion, &C::weapons, &C::stops_with_frames, &C::suspend_frames, &C::reload_frames,
          &C::stop_latches, &C::panics, &C::timeouts, &C::supervisor_stops, &C::operator_resets, &C::supervisor_resets,
          &C::refused_resets, &C::supervised_frames, &C::gated, &C::gate_refused, &C::rest_held, &C::trimmed}) {
      this->*count += o.*count;
    }
    for (std::size_t i = 0; i < motion_after.size(); ++i) motion_after[i] += o.motion_after[i];
    return *this;
  }
};

}  // namespace andros::test
