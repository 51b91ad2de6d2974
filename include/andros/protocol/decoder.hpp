#pragma once
/// Incremental frame decoder: the vehicle's side of the link. Bytes may arrive
/// in any chunking; the frames found are the same.

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "andros/protocol/frame.hpp"

namespace andros::protocol {

struct DecodedFrame {
  std::uint64_t offset = 0;  ///< stream offset of the frame's first F1
  DataBytes data{};
  std::uint16_t checksum_sent = 0;
  std::uint16_t checksum_computed = 0;
  bool checksum_ok = false;
  bool valid = false;               ///< checksum and every validation rule hold
  std::vector<std::string> errors;  ///< one short string per broken rule
};

struct DecoderStats {
  std::uint64_t frames = 0;
  std::uint64_t valid = 0;
  std::uint64_t bad_checksum = 0;
  std::uint64_t invalid = 0;  ///< checksum right, a validation rule broken
  std::uint64_t bytes_skipped = 0;
  std::uint64_t bytes_total = 0;
};

class Decoder {
 public:
  using Sink = std::function<void(const DecodedFrame&)>;

  /// With an expected code, frames whose byte 11 differs are invalid too (the
  /// vehicle software can be built to drop them).
  explicit Decoder(std::optional<std::uint8_t> expected_code = std::nullopt) : expected_code_(expected_code) {}

  /// Feeds bytes; calls sink for every frame completed by them.
  void push(std::span<const std::uint8_t> bytes, const Sink& sink);
  /// End of stream: whatever is left over counts as skipped.
  void finish();

  [[nodiscard]] const DecoderStats& stats() const { return stats_; }

 private:
  void emit(std::size_t pos, const Sink& sink, bool* lost_checksum);

  std::optional<std::uint8_t> expected_code_;
  std::vector<std::uint8_t> buf_;
  std::uint64_t buf_offset_ = 0;  ///< stream offset of buf_[0]
  DecoderStats stats_;
};

}  // namespace andros::protocol
