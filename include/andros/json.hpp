#pragma once
/// JSON views of frames and signals, in catalogue order (nlohmann::ordered_json).

#include <nlohmann/json.hpp>

#include "andros/decoder.hpp"
#include "andros/frame.hpp"

namespace andros {

/// Every canonical signal name to its value.
nlohmann::ordered_json signals_to_json(const ControlState& state);

/// A decoded frame: offset, data, checksum_ok, valid, errors, signals.
nlohmann::ordered_json frame_to_json(const DecodedFrame& frame);

}  // namespace andros
