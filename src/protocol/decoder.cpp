#include "andros/protocol/decoder.hpp"

#include <cstdio>

#include "andros/base/text.hpp"

namespace andros::protocol {
namespace {

constexpr std::size_t kDigits = 2 * kDataBytes;
constexpr std::size_t kChecksumAt = 2 + kDigits;

/// The switchbox sends upper-case digits only.
bool is_hex_digit(std::uint8_t b) {
  const auto c = static_cast<char>(b);
  return hex_value(c) >= 0 && to_upper(c) == c;
}

std::uint8_t nibble(std::uint8_t b) { return static_cast<std::uint8_t>(hex_value(static_cast<char>(b))); }

std::string hex16(std::uint16_t v) {
  char text[8];
  std::snprintf(text, sizeof text, "0x%04X", v);
  return text;
}

}  // namespace

void Decoder::emit(std::size_t pos, const Sink& sink, bool* lost_checksum) {
  DecodedFrame f;
  f.offset = buf_offset_ + pos;
  for (std::size_t i = 0; i < kDataBytes; ++i) {
    f.data[i] = static_cast<std::uint8_t>(nibble(buf_[pos + 2 + 2 * i]) << 4 | nibble(buf_[pos + 3 + 2 * i]));
  }
  f.checksum_computed = checksum(std::span(buf_).subspan(pos + 2, kDigits));
  f.checksum_sent = static_cast<std::uint16_t>(buf_[pos + kChecksumAt] | buf_[pos + kChecksumAt + 1] << 8);
  f.checksum_ok = f.checksum_sent == f.checksum_computed;
  if (!f.checksum_ok) {
    f.errors.push_back("checksum " + hex16(f.checksum_sent) + ", computed " + hex16(f.checksum_computed));
  }
  auto rules = validation_errors(f.data);
  f.errors.insert(f.errors.end(), rules.begin(), rules.end());
  if (expected_code_ && f.data[kCodeByte] != *expected_code_) {
    char text[48];
    std::snprintf(text, sizeof text, "byte 11 code 0x%02X, expected 0x%02X", f.data[kCodeByte], *expected_code_);
    f.errors.emplace_back(text);
  }
  f.valid = f.errors.empty();

  ++stats_.frames;
  if (f.valid) {
    ++stats_.valid;
  } else if (!f.checksum_ok) {
    ++stats_.bad_checksum;
  } else {
    ++stats_.invalid;
  }
  // A checksum slot holding an F1 may really be the start of the next frame
  // (a frame that lost its checksum): then the slot is scanned again. A good
  // checksum's F1 is never rescanned, since a good frame is consumed whole.
  *lost_checksum =
      !f.checksum_ok && (buf_[pos + kChecksumAt] == kStartByte || buf_[pos + kChecksumAt + 1] == kStartByte);
  sink(f);
}

void Decoder::push(std::span<const std::uint8_t> bytes, const Sink& sink) {
  stats_.bytes_total += bytes.size();
  buf_.insert(buf_.end(), bytes.begin(), bytes.end());
  const std::size_t n = buf_.size();
  std::size_t pos = 0;
  while (pos < n) {
    if (buf_[pos] != kStartByte) {
      ++stats_.bytes_skipped;
      ++pos;
      continue;
    }
    if (pos + 1 >= n) break;  // an F1 at the end: wait for the next byte
    if (buf_[pos + 1] != kStartByte) {
      ++stats_.bytes_skipped;
      ++pos;
      continue;
    }
    // A candidate start: every data byte must be a hex digit.
    std::size_t j = pos + 2;
    while (j < pos + kChecksumAt && j < n && is_hex_digit(buf_[j])) ++j;
    if (j < pos + kChecksumAt && j < n) {
      // False start (F1 F1 then a non-digit): drop one byte and look again, so
      // an F1 F1 inside the run (a real start after a truncated one) is found.
      ++stats_.bytes_skipped;
      ++pos;
      continue;
    }
    if (pos + kFrameSize > n) break;  // incomplete: wait for more
    bool lost_checksum = false;
    emit(pos, sink, &lost_checksum);
    pos += lost_checksum ? kChecksumAt : kFrameSize;
  }
  buf_.erase(buf_.begin(), buf_.begin() + static_cast<std::ptrdiff_t>(pos));
  buf_offset_ += pos;
}

void Decoder::finish() {
  stats_.bytes_skipped += buf_.size();
  buf_offset_ += buf_.size();
  buf_.clear();
}

}  // namespace andros::protocol
