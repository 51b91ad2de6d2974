#pragma once
/// Replay (docs/event-scripts.md): an event script through the engine on a
/// virtual clock. Same script, same mapping, same options: same bytes, on any
/// machine, at any speed. The CLI's `replay` is a thin wrapper over this.

#include <array>
#include <cstdint>
#include <functional>

#include "andros/input/script_player.hpp"
#include "andros/mapping/engine.hpp"
#include "andros/timing/rate.hpp"

namespace andros::run {

using FrameSink = std::function<void(std::int64_t t_ms, const protocol::DataBytes& data)>;

/// Steps the engine at every frame time from t = 0 through the first frame
/// time >= the script's end (its `end`, or its last event), each frame
/// reflecting every event with a time <= its own. Returns the frame count.
std::int64_t replay(input::ScriptPlayer& player, mapping::Engine& engine, const timing::FrameClock& clock,
                    const FrameSink& sink);

}  // namespace andros::run
