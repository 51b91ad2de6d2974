#pragma once
/// The switchbox frame: 16 data bytes sent as `F1 F1`, 32 ASCII hex digits and
/// a 16-bit checksum of those digits, low byte first.

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "andros/protocol/signals.hpp"

namespace andros::protocol {

using DataBytes = std::array<std::uint8_t, kDataBytes>;

inline constexpr std::size_t kFrameSize = 36;
inline constexpr std::uint8_t kStartByte = 0xF1;
/// The switchbox's own line speed (8N1): the default link, and the one replay
/// assumes.
inline constexpr int kSwitchboxBaud = 9600;
using Frame = std::array<std::uint8_t, kFrameSize>;

/// The 16-bit sum of the ASCII hex digits of the data field.
std::uint16_t checksum(std::span<const std::uint8_t> ascii_digits);

/// The reference encoder: exactly these data bytes, nothing forced.
Frame encode(const DataBytes& data);

/// Upper-case hex text of any byte sequence ("F1F130...").
std::string to_hex(std::span<const std::uint8_t> bytes);

/// Parses exactly 16 bytes from 32 hex digits (either case). Throws
/// InputError naming what is wrong.
DataBytes parse_data_hex(std::string_view text);

/// The value of every catalogue signal: 0/1 for a bit, 0..255 for a byte.
struct ControlState {
  std::array<std::uint8_t, kSignalCount> values{};

  [[nodiscard]] std::uint8_t operator[](SignalId id) const { return values[id]; }
  std::uint8_t& operator[](SignalId id) { return values[id]; }
  bool operator==(const ControlState&) const = default;
};

/// Reads every catalogue signal out of data bytes.
ControlState read_signals(const DataBytes& data);

/// One broken validation rule, as a short human-readable string.
std::vector<std::string> validation_errors(const DataBytes& data);

/// Builds data bytes from a control state with the validation bits, byte 11
/// (the dip-switch code) and byte 15 forced, so that no caller can emit a
/// frame a vehicle would reject.
class FrameBuilder {
 public:
  explicit FrameBuilder(std::uint8_t code) : code_(code) {}

  [[nodiscard]] DataBytes build(const ControlState& state) const;

 private:
  std::uint8_t code_;
};

}  // namespace andros::protocol
