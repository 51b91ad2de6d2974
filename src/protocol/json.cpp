#include "andros/protocol/json.hpp"

namespace andros::protocol {

nlohmann::ordered_json signals_to_json(const ControlState& state) {
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (std::size_t i = 0; i < kSignals.size(); ++i) out[std::string(kSignals[i].name)] = state.values[i];
  return out;
}

void update_signals_json(nlohmann::ordered_json& out, const ControlState& state) {
  std::size_t i = 0;
  for (auto& value : out) value = state.values[i++];
}

nlohmann::ordered_json frame_to_json(const DecodedFrame& frame) {
  nlohmann::ordered_json out;
  out["offset"] = frame.offset;
  out["data"] = to_hex(frame.data);
  out["checksum_ok"] = frame.checksum_ok;
  out["valid"] = frame.valid;
  out["errors"] = frame.errors;
  out["signals"] = signals_to_json(read_signals(frame.data));
  return out;
}

std::string FrameJsonWriter::line(const DecodedFrame& frame) {
  // Same keys, same order as frame_to_json; only values are replaced.
  auto it = doc_.begin();
  *it++ = frame.offset;
  *it++ = to_hex(frame.data);
  *it++ = frame.checksum_ok;
  *it++ = frame.valid;
  *it++ = frame.errors;
  update_signals_json(*it, read_signals(frame.data));
  return doc_.dump();
}

}  // namespace andros::protocol
