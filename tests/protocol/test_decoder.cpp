#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <random>
#include <sstream>

#include "andros/protocol/decoder.hpp"

namespace andros::protocol {
namespace {

using Bytes = std::vector<std::uint8_t>;

struct Seen {
  std::uint64_t offset;
  DataBytes data;
  bool checksum_ok;
  bool valid;
  bool operator==(const Seen&) const = default;
};

std::vector<Seen> decode_in_chunks(const Bytes& stream, const std::vector<std::size_t>& chunks,
                                   DecoderStats* stats = nullptr) {
  Decoder decoder;
  std::vector<Seen> seen;
  const auto sink = [&](const DecodedFrame& f) { seen.push_back({f.offset, f.data, f.checksum_ok, f.valid}); };
  std::size_t pos = 0, i = 0;
  while (pos < stream.size()) {
    const std::size_t n = std::min(chunks[i++ % chunks.size()], stream.size() - pos);
    decoder.push(std::span(stream).subspan(pos, n), sink);
    pos += n;
  }
  decoder.finish();
  if (stats) *stats = decoder.stats();
  return seen;
}

std::vector<Seen> decode_all(const Bytes& stream, DecoderStats* stats = nullptr) {
  return decode_in_chunks(stream, {std::max<std::size_t>(stream.size(), 1)}, stats);
}

DataBytes valid_data(std::mt19937& rng) {
  ControlState state;
  std::uniform_int_distribution<int> byte(0, 255);
  for (auto& v : state.values) v = static_cast<std::uint8_t>(byte(rng) & 1);
  state[signal_id("drive")] = static_cast<std::uint8_t>(byte(rng));
  state[signal_id("battery")] = static_cast<std::uint8_t>(byte(rng));
  return FrameBuilder(static_cast<std::uint8_t>(byte(rng))).build(state);
}

Bytes frame_bytes(const DataBytes& d) {
  const auto f = encode(d);
  return {f.begin(), f.end()};
}

void append(Bytes& out, const Bytes& more) { out.insert(out.end(), more.begin(), more.end()); }

// Data whose checksum's low byte is F1: a start-of-frame byte inside a frame.
DataBytes data_with_f1_checksum(std::mt19937& rng) {
  while (true) {
    const auto d = valid_data(rng);
    if (encode(d)[34] == 0xF1) return d;
  }
}

TEST(Decoder, FindsFrameAfterGarbage) {
  std::mt19937 rng(1);
  const auto d = valid_data(rng);
  Bytes s = {0x00, 0x41, 0xF1, 0x30, 0xF1};
  append(s, frame_bytes(d));
  DecoderStats stats;
  const auto seen = decode_all(s, &stats);
  ASSERT_EQ(seen.size(), 1U);
  EXPECT_EQ(seen[0], (Seen{5, d, true, true}));
  EXPECT_EQ(stats.bytes_skipped, 5U);
}

TEST(Decoder, FalseStartThenRealFrame) {
  std::mt19937 rng(2);
  const auto d = valid_data(rng);
  Bytes s = {0xF1, 0xF1, 'Z', '1', '2'};
  append(s, frame_bytes(d));
  const auto seen = decode_all(s);
  ASSERT_EQ(seen.size(), 1U);
  EXPECT_EQ(seen[0].offset, 5U);
  EXPECT_TRUE(seen[0].valid);
}

TEST(Decoder, TripleStartByteUsesTheLastPair) {
  std::mt19937 rng(3);
  const auto d = valid_data(rng);
  Bytes s = {0xF1};
  append(s, frame_bytes(d));
  const auto seen = decode_all(s);
  ASSERT_EQ(seen.size(), 1U);
  EXPECT_EQ(seen[0].offset, 1U);
}

TEST(Decoder, TruncatedFrameThenFullFrame) {
  std::mt19937 rng(4);
  const auto d = valid_data(rng);
  auto cut = frame_bytes(valid_data(rng));
  cut.resize(20);
  Bytes s = cut;
  append(s, frame_bytes(d));
  const auto seen = decode_all(s);
  ASSERT_EQ(seen.size(), 1U);
  EXPECT_EQ(seen[0], (Seen{20, d, true, true}));
}

TEST(Decoder, FrameThatLostItsChecksumDoesNotHideTheNext) {
  std::mt19937 rng(5);
  const auto lost = valid_data(rng);
  const auto next = valid_data(rng);
  auto s = frame_bytes(lost);
  s.resize(34);
  append(s, frame_bytes(next));
  const auto seen = decode_all(s);
  ASSERT_EQ(seen.size(), 2U);
  EXPECT_FALSE(seen[0].checksum_ok);
  EXPECT_FALSE(seen[0].valid);
  EXPECT_EQ(seen[1], (Seen{34, next, true, true}));
}

TEST(Decoder, ChecksumF1IsNotAStart) {
  std::mt19937 rng(6);
  Bytes s;
  std::vector<DataBytes> sent;
  for (int i = 0; i < 5; ++i) {
    sent.push_back(data_with_f1_checksum(rng));
    append(s, frame_bytes(sent.back()));
  }
  DecoderStats stats;
  const auto seen = decode_all(s, &stats);
  ASSERT_EQ(seen.size(), sent.size());
  for (std::size_t i = 0; i < sent.size(); ++i) EXPECT_EQ(seen[i], (Seen{36 * i, sent[i], true, true}));
  EXPECT_EQ(stats.bytes_skipped, 0U);
}

TEST(Decoder, BadChecksumAndInvalidAreCountedApart) {
  std::mt19937 rng(7);
  auto bad_sum = frame_bytes(valid_data(rng));
  bad_sum[34] ^= 0x10;
  auto bad15 = valid_data(rng);
  bad15[15] = 0x07;
  Bytes s = bad_sum;
  append(s, frame_bytes(bad15));
  DecoderStats stats;
  const auto seen = decode_all(s, &stats);
  ASSERT_EQ(seen.size(), 2U);
  EXPECT_FALSE(seen[0].checksum_ok);
  EXPECT_TRUE(seen[1].checksum_ok);
  EXPECT_FALSE(seen[1].valid);
  EXPECT_EQ(stats.frames, 2U);
  EXPECT_EQ(stats.bad_checksum, 1U);
  EXPECT_EQ(stats.invalid, 1U);
  EXPECT_EQ(stats.valid, 0U);
}

TEST(Decoder, ExpectedCodeFlagsOtherCodes) {
  auto d = FrameBuilder(0x3C).build(ControlState{});
  Decoder decoder(0x01);
  std::vector<DecodedFrame> seen;
  decoder.push(frame_bytes(d), [&](const DecodedFrame& f) { seen.push_back(f); });
  ASSERT_EQ(seen.size(), 1U);
  EXPECT_FALSE(seen[0].valid);
  EXPECT_EQ(seen[0].errors, std::vector<std::string>{"byte 11 code 0x3C, expected 0x01"});
}

// A long stream of good frames and every kind of damage, decoded whole, a
// byte at a time and in random chunks, finds the same frames at the same offsets.
TEST(Decoder, ChunkingInvariance) {
  std::mt19937 rng(8);
  std::uniform_int_distribution<int> pick(0, 7), byte(0, 255);
  Bytes s;
  std::vector<std::pair<std::uint64_t, DataBytes>> good;
  for (int i = 0; i < 3000; ++i) {
    switch (pick(rng)) {
      case 0:
        for (int k = byte(rng) % 10; k >= 0; --k) s.push_back(static_cast<std::uint8_t>(byte(rng)));
        break;
      case 1: {
        auto f = frame_bytes(valid_data(rng));
        f.resize(static_cast<std::size_t>(2 + byte(rng) % 33));
        append(s, f);
        break;
      }
      case 2: append(s, {0xF1, 0xF1, 0x00}); break;
      case 3: {
        const auto d = data_with_f1_checksum(rng);
        good.emplace_back(s.size(), d);
        append(s, frame_bytes(d));
        break;
      }
      default: {
        const auto d = valid_data(rng);
        good.emplace_back(s.size(), d);
        append(s, frame_bytes(d));
      }
    }
  }
  const auto whole = decode_all(s);
  std::vector<std::pair<std::uint64_t, DataBytes>> found;
  for (const auto& f : whole) {
    if (f.valid) found.emplace_back(f.offset, f.data);
  }
  EXPECT_EQ(found, good);  // every good frame found at its offset, nothing bogus valid

  EXPECT_EQ(decode_in_chunks(s, {1}), whole);
  std::vector<std::size_t> random_chunks;
  for (int i = 0; i < 100; ++i) random_chunks.push_back(static_cast<std::size_t>(1 + byte(rng) % 80));
  EXPECT_EQ(decode_in_chunks(s, random_chunks), whole);
  EXPECT_EQ(decode_in_chunks(s, {35, 36, 37}), whole);
}

TEST(Decoder, RandomBytesNeverYieldAValidFrame) {
  std::mt19937 rng(9);
  std::uniform_int_distribution<int> byte(0, 255);
  Bytes s(1 << 20);
  for (auto& b : s) b = static_cast<std::uint8_t>(byte(rng));
  DecoderStats stats;
  decode_all(s, &stats);
  EXPECT_EQ(stats.valid, 0U);
  EXPECT_EQ(stats.bytes_total, s.size());
}

TEST(Decoder, MixedCaptureFile) {
  std::ifstream in(ANDROS_TEST_DATA_DIR "/mixed_capture.bin", std::ios::binary);
  ASSERT_TRUE(in);
  const Bytes s((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::ifstream expected(ANDROS_TEST_DATA_DIR "/mixed_capture.expected");
  std::vector<std::string> want, got;
  for (std::string line; std::getline(expected, line);) {
    if (!line.empty() && line[0] != '#') want.push_back(line);
  }
  for (const auto& f : decode_all(s)) {
    got.push_back(std::to_string(f.offset) + " " + to_hex(f.data) + " " +
                  (f.valid         ? "valid"
                   : f.checksum_ok ? "invalid"
                                   : "bad_checksum"));
  }
  EXPECT_EQ(got, want);
}

}  // namespace
}  // namespace andros::protocol
