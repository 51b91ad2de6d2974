#include "andros/json.hpp"

namespace andros {

nlohmann::ordered_json signals_to_json(const ControlState& state) {
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (std::size_t i = 0; i < kSignals.size(); ++i) out[std::string(kSignals[i].name)] = state.values[i];
  return out;
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

}  // namespace andros
