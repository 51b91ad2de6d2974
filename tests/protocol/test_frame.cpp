#include <gtest/gtest.h>

#include <initializer_list>
#include <random>

#include "andros/base/error.hpp"
#include "andros/protocol/decoder.hpp"
#include "andros/protocol/frame.hpp"
#include "andros/protocol/json.hpp"

namespace andros::protocol {
namespace {

const DataBytes kExampleData = {0x00, 0x00, 0x1C, 0x20, 0x00, 0x90, 0x7F, 0x7E,
                                0x3E, 0x00, 0x00, 0xFF, 0xFF, 0x20, 0xCC, 0x02};
const Frame kExampleFrame = {0xF1, 0xF1, 0x30, 0x30, 0x30, 0x30, 0x31, 0x43, 0x32, 0x30, 0x30, 0x30,
                             0x39, 0x30, 0x37, 0x46, 0x37, 0x45, 0x33, 0x45, 0x30, 0x30, 0x30, 0x30,
                             0x46, 0x46, 0x46, 0x46, 0x32, 0x30, 0x43, 0x43, 0x30, 0x32, 0xF2, 0x06};

TEST(Frame, WorkedExampleEncodes) { EXPECT_EQ(encode(kExampleData), kExampleFrame); }

TEST(Frame, WorkedExampleDecodes) {
  Decoder decoder;
  std::vector<DecodedFrame> frames;
  decoder.push(kExampleFrame, [&](const DecodedFrame& f) { frames.push_back(f); });
  ASSERT_EQ(frames.size(), 1U);
  EXPECT_EQ(frames[0].data, kExampleData);
  EXPECT_EQ(frames[0].checksum_sent, 0x06F2);
  EXPECT_TRUE(frames[0].checksum_ok);
  EXPECT_TRUE(frames[0].valid) << ::testing::PrintToString(frames[0].errors);
  const auto s = read_signals(frames[0].data);
  EXPECT_EQ(s[signal_id("pivot")], 0x7F);
  EXPECT_EQ(s[signal_id("drive")], 0x7E);
  EXPECT_EQ(s[signal_id("arm_speed")], 0x3E);
  EXPECT_EQ(s[signal_id("inset_4")], 1);
  EXPECT_EQ(s[signal_id("speed_low")], 1);
  EXPECT_EQ(s[signal_id("battery")], 0xCC);
  EXPECT_EQ(s[signal_id("safety")], 0);
}

TEST(Frame, ChecksumRange) {
  // Every digit is 0x30..0x46, so the checksum's high byte is 06, 07 or 08.
  DataBytes zeros{};
  DataBytes ffs;
  ffs.fill(0xFF);
  const auto low = encode(zeros);
  const auto high = encode(ffs);
  EXPECT_EQ(checksum(std::span(low).subspan(2, 32)), 0x0600);
  EXPECT_EQ(checksum(std::span(high).subspan(2, 32)), 0x08C0);
}

TEST(Frame, HexParsing) {
  EXPECT_EQ(parse_data_hex("00001C2000907F7E3E0000FFFF20CC02"), kExampleData);
  EXPECT_EQ(parse_data_hex("00001c2000907f7e3e0000ffff20cc02"), kExampleData);
  EXPECT_THROW(parse_data_hex("00001C2000907F7E3E0000FFFF20CC0"), InputError);
  EXPECT_THROW(parse_data_hex("00001C2000907F7E3E0000FFFF20CC0G"), InputError);
  EXPECT_THROW(parse_data_hex(""), InputError);
}

TEST(Frame, RoundTripTenThousandRandomBlocks) {
  std::mt19937 rng(42);
  std::uniform_int_distribution<int> byte(0, 255);
  std::vector<std::uint8_t> stream;
  std::vector<DataBytes> sent;
  for (int i = 0; i < 10000; ++i) {
    DataBytes d;
    for (auto& b : d) b = static_cast<std::uint8_t>(byte(rng));
    sent.push_back(d);
    const auto f = encode(d);
    EXPECT_EQ(parse_data_hex(to_hex(d)), d);
    stream.insert(stream.end(), f.begin(), f.end());
  }
  Decoder decoder;
  std::vector<DataBytes> got;
  decoder.push(stream, [&](const DecodedFrame& f) {
    EXPECT_TRUE(f.checksum_ok);
    got.push_back(f.data);
  });
  decoder.finish();
  EXPECT_EQ(got, sent);
  EXPECT_EQ(decoder.stats().bytes_skipped, 0U);
  EXPECT_EQ(decoder.stats().bad_checksum, 0U);
}

TEST(FrameBuilder, ForcesValidationBitsCodeAndTrailer) {
  ControlState all_ones;
  all_ones.values.fill(0xFF);
  for (const std::uint8_t code : std::initializer_list<std::uint8_t>{0x00, 0x01, 0x3C, 0xFF}) {
    for (const auto& state : {ControlState{}, all_ones}) {
      const auto data = FrameBuilder(code).build(state);
      EXPECT_TRUE(validation_errors(data).empty());
      EXPECT_EQ(data[11], code);
      EXPECT_EQ(data[15], 0x02);
    }
  }
}

TEST(FrameBuilder, PlacesEverySignal) {
  const FrameBuilder builder(0x01);
  for (std::size_t i = 0; i < kSignalCount; ++i) {
    const auto& s = kSignals[i];
    if (s.name == "code") continue;  // forced by the builder
    ControlState state;
    state.values[i] = s.is_bit() ? 1 : 0xA5;
    const auto back = read_signals(builder.build(state));
    EXPECT_EQ(back.values[i], state.values[i]) << s.name;
    for (std::size_t j = 0; j < kSignalCount; ++j) {
      if (j == i || kSignals[j].name == "code") continue;
      EXPECT_EQ(back.values[j], 0) << s.name << " leaks into " << kSignals[j].name;
    }
  }
}

TEST(Validation, EachRuleBrokenOnceIsNamed) {
  const auto good = FrameBuilder(0x01).build(ControlState{});
  ASSERT_TRUE(validation_errors(good).empty());
  for (const auto& f : kFixedBits) {
    auto bad = good;
    bad[f.byte] = static_cast<std::uint8_t>(bad[f.byte] ^ (1U << f.bit));
    const auto errors = validation_errors(bad);
    ASSERT_EQ(errors.size(), 1U);
    EXPECT_EQ(errors[0], "byte " + std::to_string(f.byte) + " bit " + std::to_string(f.bit) + " must be " +
                             std::to_string(f.value));
  }
  auto bad = good;
  bad[15] = 0x03;
  EXPECT_EQ(validation_errors(bad), std::vector<std::string>{"byte 15 is 0x03, must be 0x02"});
}

}  // namespace
}  // namespace andros::protocol

namespace andros::protocol {
namespace {

TEST(Json, WriterMatchesFreshDocumentFrameAfterFrame) {
  FrameJsonWriter writer;
  DecodedFrame a;
  a.offset = 7;
  a.data = FrameBuilder(0x3C).build(ControlState{});
  a.checksum_ok = a.valid = true;
  DecodedFrame b = a;
  b.offset = 43;
  b.data[7] = 0xFE;
  b.valid = false;
  b.errors = {"byte 15 is 0x00, must be 0x02"};
  for (const auto* f : {&a, &b, &a}) EXPECT_EQ(writer.line(*f), frame_to_json(*f).dump());
}

}  // namespace
}  // namespace andros::protocol
