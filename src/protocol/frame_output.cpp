#include "andros/protocol/frame_output.hpp"

#include "andros/protocol/json.hpp"

namespace andros::protocol {

ReplayFormat parse_replay_format(std::string_view text, const SourcePos& pos) {
  std::string names;
  for (std::size_t i = 0; i < kReplayFormatNames.size(); ++i) {
    if (text == kReplayFormatNames[i]) return static_cast<ReplayFormat>(i);
    names += (i == 0 ? "" : ", ") + std::string(kReplayFormatNames[i]);
  }
  throw InputError(pos, "format " + quote(text) + " is not one of " + names);
}

void write_frame(std::ostream& out, ReplayFormat format, std::int64_t t_ms, const DataBytes& data) {
  const auto frame = encode(data);
  switch (format) {
    case ReplayFormat::kHex: out << t_ms << ' ' << to_hex(frame) << '\n'; break;
    case ReplayFormat::kRaw: out.write(reinterpret_cast<const char*>(frame.data()), frame.size()); break;
    case ReplayFormat::kJsonl: {
      nlohmann::ordered_json line;
      line["t"] = t_ms;
      line["frame"] = to_hex(frame);
      line["signals"] = signals_to_json(read_signals(data));
      out << line.dump() << '\n';
      break;
    }
  }
}

}  // namespace andros::protocol
