#pragma once
/// Frames written with their time, as `replay` writes them
/// (docs/event-scripts.md): `T HEX72` lines, the raw bytes, or JSON lines.

#include <array>
#include <cstdint>
#include <ostream>
#include <string_view>

#include "andros/base/error.hpp"
#include "andros/protocol/frame.hpp"

namespace andros::protocol {

enum class ReplayFormat : std::uint8_t { kHex, kRaw, kJsonl };
/// The formats' names, in the enum's order.
inline constexpr std::array<std::string_view, 3> kReplayFormatNames = {"hex", "raw", "jsonl"};

/// One of kReplayFormatNames; throws InputError at pos otherwise.
ReplayFormat parse_replay_format(std::string_view text, const SourcePos& pos);

/// One frame in a replay format: `T HEX72\n`, the 36 raw bytes, or a JSON
/// line {"t","frame","signals"}.
void write_frame(std::ostream& out, ReplayFormat format, std::int64_t t_ms, const DataBytes& data);

}  // namespace andros::protocol
