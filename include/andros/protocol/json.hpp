#pragma once
/// JSON views of frames and signals, in catalogue order (nlohmann::ordered_json).

#include <nlohmann/json.hpp>

#include "andros/protocol/decoder.hpp"
#include "andros/protocol/frame.hpp"

namespace andros::protocol {

/// Every canonical signal name to its value.
nlohmann::ordered_json signals_to_json(const ControlState& state);

/// Writes every signal's value into `out`, which must be an object made by
/// signals_to_json: the keys stay, only the values change. A decoder that
/// prints millions of frames reuses one object instead of building each anew.
void update_signals_json(nlohmann::ordered_json& out, const ControlState& state);

/// A decoded frame: offset, data, checksum_ok, valid, errors, signals.
nlohmann::ordered_json frame_to_json(const DecodedFrame& frame);

/// frame_to_json for a stream of frames, reusing one document.
class FrameJsonWriter {
 public:
  /// The frame as one line of JSON (no newline).
  std::string line(const DecodedFrame& frame);

 private:
  nlohmann::ordered_json doc_ = frame_to_json(DecodedFrame{});
};

}  // namespace andros::protocol
