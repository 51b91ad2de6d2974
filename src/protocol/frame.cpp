#include "andros/protocol/frame.hpp"

#include <cstdio>

#include "andros/base/error.hpp"
#include "andros/base/text.hpp"

namespace andros::protocol {
std::uint16_t checksum(std::span<const std::uint8_t> ascii_digits) {
  std::uint16_t sum = 0;
  for (const auto b : ascii_digits) sum = static_cast<std::uint16_t>(sum + b);
  return sum;
}

Frame encode(const DataBytes& data) {
  Frame frame{};
  frame[0] = kStartByte;
  frame[1] = kStartByte;
  for (std::size_t i = 0; i < data.size(); ++i) {
    frame[2 + 2 * i] = static_cast<std::uint8_t>(hex_digit(data[i] >> 4U));
    frame[3 + 2 * i] = static_cast<std::uint8_t>(hex_digit(data[i]));
  }
  const auto sum = checksum(std::span(frame).subspan(2, 2 * kDataBytes));
  frame[34] = static_cast<std::uint8_t>(sum & 0xFF);
  frame[35] = static_cast<std::uint8_t>(sum >> 8);
  return frame;
}

std::string to_hex(std::span<const std::uint8_t> bytes) {
  std::string out;
  out.reserve(bytes.size() * 2);
  for (const auto b : bytes) out += hex_byte(b);
  return out;
}

DataBytes parse_data_hex(std::string_view text) {
  if (text.size() != 2 * kDataBytes) {
    throw InputError("expected 32 hex digits (16 data bytes), got " + std::to_string(text.size()) + " characters");
  }
  DataBytes data{};
  for (std::size_t i = 0; i < text.size(); ++i) {
    const int v = hex_value(text[i]);
    if (v < 0) {
      throw InputError("character " + std::to_string(i + 1) + " is not a hex digit");
    }
    data[i / 2] = static_cast<std::uint8_t>(data[i / 2] | (v << (i % 2 == 0 ? 4 : 0)));
  }
  return data;
}

ControlState read_signals(const DataBytes& data) {
  ControlState state;
  for (std::size_t i = 0; i < kSignals.size(); ++i) {
    const auto& s = kSignals[i];
    state.values[i] = s.is_bit() ? static_cast<std::uint8_t>((unsigned{data[s.byte]} >> s.bit) & 1U) : data[s.byte];
  }
  return state;
}

std::vector<std::string> validation_errors(const DataBytes& data) {
  std::vector<std::string> errors;
  for (const auto& f : kFixedBits) {
    if (((unsigned{data[f.byte]} >> f.bit) & 1U) != f.value) {
      errors.push_back("byte " + std::to_string(f.byte) + " bit " + std::to_string(f.bit) + " must be " +
                       std::to_string(f.value));
    }
  }
  if (data[kTrailerByte] != kTrailerValue) {
    errors.push_back("byte 15 is 0x" + hex_byte(data[kTrailerByte]) + ", must be 0x02");
  }
  return errors;
}

DataBytes FrameBuilder::build(const ControlState& state) const {
  DataBytes data{};
  for (std::size_t i = 0; i < kSignals.size(); ++i) {
    const auto& s = kSignals[i];
    if (s.is_bit()) {
      if (state.values[i] != 0) data[s.byte] = static_cast<std::uint8_t>(data[s.byte] | (1U << s.bit));
    } else {
      data[s.byte] = state.values[i];
    }
  }
  for (const auto& f : kFixedBits) {
    const auto mask = static_cast<std::uint8_t>(1U << f.bit);
    data[f.byte] = static_cast<std::uint8_t>(f.value ? (data[f.byte] | mask) : (data[f.byte] & ~mask));
  }
  data[kCodeByte] = code_;
  data[kTrailerByte] = kTrailerValue;
  return data;
}

}  // namespace andros::protocol
