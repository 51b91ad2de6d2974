#pragma once
// The fault simulation's own reading of a frame on the wire
// (simulation.hpp), from docs/protocol.md ("The frame"), not from the
// encoder: `F1 F1`, the 16 data bytes each as two upper-case ASCII hex
// digits, high nibble first, then the 16-bit sum of those 32 digits, low byte
// first. The oracle then checks the data bytes it read, the code byte among them.

#include <cstdint>
#include <string>

#include "andros/protocol/frame.hpp"

namespace andros::test {

/// frame's data bytes into data; empty, or what is wrong with the encoding.
// [rule: wire]
inline std::string read_wire_frame(const protocol::Frame& frame, protocol::DataBytes& data) {
  if (frame[0] != 0xF1 || frame[1] != 0xF1) return "the frame does not start with F1 F1";
  const auto digit = [](std::uint8_t c) -> int {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;  // not an upper-case hex digit
  };
  unsigned sum = 0;
  for (std::size_t i = 0; i < data.size(); ++i) {
    const std::uint8_t high = frame[2 + 2 * i];
    const std::uint8_t low = frame[3 + 2 * i];
    if (digit(high) < 0 || digit(low) < 0) {
      return "data byte " + std::to_string(i) + " is not two upper-case hex digits on the wire";
    }
    data[i] = static_cast<std::uint8_t>(digit(high) * 16 + digit(low));
    sum += high + low;
  }
  if (frame[34] != (sum & 0xFFU) || frame[35] != ((sum >> 8U) & 0xFFU)) {
    return "the checksum on the wire is not the sum of the 32 digits, low byte first";
  }
  return {};
}

}  // namespace andros::test
