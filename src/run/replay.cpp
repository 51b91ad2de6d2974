#include "andros/run/replay.hpp"

#include <cstdio>

#include "andros/protocol/json.hpp"

namespace andros::run {

ReplayFormat parse_replay_format(std::string_view text, const SourcePos& pos) {
  std::string names;
  for (std::size_t i = 0; i < kReplayFormatNames.size(); ++i) {
    if (text == kReplayFormatNames[i]) return static_cast<ReplayFormat>(i);
    names += (i == 0 ? "" : ", ") + std::string(kReplayFormatNames[i]);
  }
  throw InputError(pos, "format " + quote(text) + " is not one of " + names);
}

std::int64_t replay(input::ScriptPlayer& player, mapping::Engine& engine, const timing::FrameClock& clock, const FrameSink& sink) {
  input::InputState input;
  for (std::int64_t k = 0;; ++k) {
    const auto t = clock.time_of(k);
    player.advance_to(t, input);
    sink(t, engine.step(input, t));
    if (player.finished_at(t)) return k + 1;
  }
}

void write_frame(std::ostream& out, ReplayFormat format, std::int64_t t_ms, const protocol::DataBytes& data) {
  const auto frame = protocol::encode(data);
  switch (format) {
    case ReplayFormat::kHex: out << t_ms << ' ' << protocol::to_hex(frame) << '\n'; break;
    case ReplayFormat::kRaw: out.write(reinterpret_cast<const char*>(frame.data()), frame.size()); break;
    case ReplayFormat::kJsonl: {
      nlohmann::ordered_json line;
      line["t"] = t_ms;
      line["frame"] = protocol::to_hex(frame);
      line["signals"] = protocol::signals_to_json(protocol::read_signals(data));
      out << line.dump() << '\n';
      break;
    }
  }
}

}  // namespace andros::run
