#pragma once
/// Replay (docs/event-scripts.md): an event script through the engine on a
/// virtual clock. Same script, same mapping, same options: same bytes, on any
/// machine, at any speed. The CLI's `replay` is a thin wrapper over this.

#include <array>
#include <cstdint>
#include <functional>
#include <ostream>
#include <string_view>

#include "andros/input/script_player.hpp"
#include "andros/mapping/engine.hpp"
#include "andros/timing/rate.hpp"

namespace andros::run {

enum class ReplayFormat : std::uint8_t { kHex, kRaw, kJsonl };
/// The formats' names, in the enum's order.
inline constexpr std::array<std::string_view, 3> kReplayFormatNames = {"hex", "raw", "jsonl"};

/// One of kReplayFormatNames; throws InputError at pos otherwise.
ReplayFormat parse_replay_format(std::string_view text, const SourcePos& pos);

using FrameSink = std::function<void(std::int64_t t_ms, const protocol::DataBytes& data)>;

/// Steps the engine at every frame time from t = 0 through the first frame
/// time >= the script's end (its `end`, or its last event), each frame
/// reflecting every event with a time <= its own. Returns the frame count.
std::int64_t replay(input::ScriptPlayer& player, mapping::Engine& engine, const timing::FrameClock& clock, const FrameSink& sink);

/// One frame in a replay format: `T HEX72\n`, the 36 raw bytes, or a JSON
/// line {"t","frame","signals"}.
void write_frame(std::ostream& out, ReplayFormat format, std::int64_t t_ms, const protocol::DataBytes& data);

}  // namespace andros::run
