#pragma once
/// The run loop's one seam to the mapping stage: what computes the frames
/// (the mapping engine in `run` and replay, a fixed frame in the benchmarks
/// and tests). It maps; it never decides whether the vehicle may move: the
/// loop's guards (run/drive_guard.hpp) read the inputs its mapping names for
/// them, the operating-state machine decides, and the step is told.

#include <cstdint>

#include "andros/input/input_state.hpp"
#include "andros/mapping/engine_status.hpp"
#include "andros/mapping/model.hpp"
#include "andros/protocol/frame.hpp"

namespace andros::mapping {

/// One step's result, by value: the frame and the engine's state after it.
struct Step {
  protocol::DataBytes data{};
  EngineStatus status;
};

class FrameSource {
 public:
  virtual ~FrameSource() = default;
  /// The mapping: which inputs are the deadman, the stop buttons and the
  /// reset gestures, and which it reads (the guards' inputs).
  [[nodiscard]] virtual const Mapping& mapping() const = 0;
  /// The frame for the tick at now_ms (ms since start) from this input,
  /// the bindings applied only when motion_allowed (the neutral frame otherwise).
  virtual Step step(const input::InputState& input, std::int64_t now_ms, bool motion_allowed) = 0;
  /// The neutral frame (shutdown, suspend, reload, stopped).
  [[nodiscard]] virtual protocol::DataBytes neutral() const = 0;
  /// Starts afresh from the input as it is now: every press it has counted
  /// is history (the loop's rebase).
  virtual void rebase(const input::InputState& now) = 0;

 protected:
  FrameSource() = default;
  FrameSource(const FrameSource&) = default;
  FrameSource(FrameSource&&) = default;
  FrameSource& operator=(const FrameSource&) = default;
  FrameSource& operator=(FrameSource&&) = default;
};

}  // namespace andros::mapping
