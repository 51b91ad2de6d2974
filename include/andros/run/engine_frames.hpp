#pragma once
// The mapping engine as the run loop's frame source.

#include <memory>

#include "andros/mapping/engine.hpp"
#include "andros/run/bridge.hpp"

namespace andros::run {

/// The engine as a frame source for the run loop.
std::unique_ptr<FrameSource> make_engine_frames(mapping::Engine engine);

}  // namespace andros::run
