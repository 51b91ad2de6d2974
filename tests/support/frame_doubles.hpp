#pragma once
// Test doubles of the run loop's frame source. FrameSource's stop methods
// have no default (a source that forgot them would clear a stop at once, or
// never latch one): a double that has no stop buttons says so here, once.

#include "andros/run/bridge.hpp"

namespace andros::testing {

/// A frame source with no stop buttons: nothing it reads ever stops, and so
/// nothing ever resets (for the tests of everything but the stop).
class WithoutStops : public run::FrameSource {
 public:
  mapping::StopPresses take_stop(const input::InputState& /*input*/) override { return {}; }
  mapping::StoppedTick stopped(const input::InputState& /*input*/, std::int64_t /*now_ms*/) override { return {}; }
  void held_stops(const input::InputState& /*input*/, mapping::EngineStatus& /*status*/) const override {}
};

}  // namespace andros::testing
