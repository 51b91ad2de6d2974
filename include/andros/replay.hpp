#pragma once
/// Replay (docs/event-scripts.md): an event script through the engine on a
/// virtual clock. Same script, same mapping, same options: same bytes, on any
/// machine, at any speed. The CLI's `replay` is a thin wrapper over this.

#include <cstdint>
#include <functional>
#include <ostream>
#include <string_view>

#include "andros/engine.hpp"
#include "andros/script_player.hpp"

namespace andros {

/// Frame times for a rate given in millihertz, exactly: t_k = floor(k * 1000 / rate)
/// ms, so 25 Hz gives 0, 40, 80, ... and 24 Hz gives 0, 41, 83, 125, ...
class FrameClock {
 public:
  explicit FrameClock(std::int64_t rate_millihertz) : rate_mhz_(rate_millihertz) {}
  [[nodiscard]] std::int64_t time_of(std::int64_t k) const { return k * 1'000'000 / rate_mhz_; }
  [[nodiscard]] std::int64_t rate_millihertz() const { return rate_mhz_; }

 private:
  std::int64_t rate_mhz_;
};

inline constexpr std::int64_t kDefaultRateMillihertz = 25'000;
inline constexpr int kReplayBaud = 9600;
inline constexpr int kBitsPerFrame = 360;  ///< 36 bytes, 10 bits each on the wire (8N1)

/// Parses a frame rate in Hz ("25", "12.5", at most 3 decimals) into
/// millihertz. Refuses a rate below 1 Hz or one whose frames do not fit on a
/// link of `baud` (rate x 360 bits > baud). Throws InputError at pos.
std::int64_t parse_rate(std::string_view text, int baud, const SourcePos& pos);

enum class ReplayFormat : std::uint8_t { kHex, kRaw, kJsonl };

/// "hex" | "raw" | "jsonl"; throws InputError at pos otherwise.
ReplayFormat parse_replay_format(std::string_view text, const SourcePos& pos);

using FrameSink = std::function<void(std::int64_t t_ms, const DataBytes& data)>;

/// Steps the engine at every frame time from t = 0 through the first frame
/// time >= the script's end (its `end`, or its last event), each frame
/// reflecting every event with a time <= its own. Returns the frame count.
std::int64_t replay(ScriptPlayer& player, Engine& engine, const FrameClock& clock, const FrameSink& sink);

/// One frame in a replay format: `T HEX72\n`, the 36 raw bytes, or a JSON
/// line {"t","frame","signals"}.
void write_frame(std::ostream& out, ReplayFormat format, std::int64_t t_ms, const DataBytes& data);

}  // namespace andros
