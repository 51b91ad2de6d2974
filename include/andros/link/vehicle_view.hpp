#pragma once
/// The vehicle's side of the link: what it decodes from the bytes that
/// arrive, and how regularly. The simulated vehicle and `monitor` both feed one.

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "andros/link/vehicle_status.hpp"
#include "andros/protocol/decoder.hpp"
#include "andros/timing/frame_timing.hpp"

namespace andros::link {

class VehicleView {
 public:
  /// Each frame decoded, valid or not, with the time its bytes arrived.
  using FrameObserver = std::function<void(const protocol::DecodedFrame& frame, std::int64_t now_ns)>;

  explicit VehicleView(std::optional<std::uint8_t> expected_code = std::nullopt) : decoder_(expected_code) {}

  /// Bytes that arrived at now_ns.
  void push(std::span<const std::uint8_t> bytes, std::int64_t now_ns);
  void finish() { decoder_.finish(); }
  /// Hands every frame decoded from now on to observer too (the trainer's vehicle model).
  void observe_frames(FrameObserver observer) { observer_ = std::move(observer); }
  [[nodiscard]] VehicleStatus status(std::int64_t now_ns) const;
  [[nodiscard]] const protocol::DecoderStats& stats() const { return decoder_.stats(); }

 private:
  protocol::Decoder decoder_;
  timing::FrameTiming timing_;
  std::optional<protocol::DataBytes> last_;
  bool last_valid_ = false;
  std::vector<std::string> last_errors_;
  FrameObserver observer_;
};

}  // namespace andros::link
