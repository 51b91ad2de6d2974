#pragma once
/// What a vehicle decoded, at one moment, as a plain value: the simulated
/// vehicle and `monitor` hand one to the operator's view (VehicleView makes it).

#include <optional>
#include <string>
#include <vector>

#include "andros/protocol/decoder.hpp"
#include "andros/timing/frame_timing.hpp"

namespace andros::link {

struct VehicleStatus {
  std::optional<protocol::DataBytes> last;  ///< the last frame decoded, valid or not
  bool last_valid = false;
  std::vector<std::string> last_errors;
  protocol::DecoderStats stats;
  timing::TimingSummary timing;
};

}  // namespace andros::link
