// The axis arithmetic of docs/mapping.md, value by value (hand-computed in the comments).
#include <gtest/gtest.h>

#include "andros/mapping/axis.hpp"

namespace andros::mapping {
namespace {

struct AxisCase {
  int raw;
  AxisShape shape;
  bool centred;  // drive/pivot with centre 128, else a trigger on a level byte
  int out;
};

class AxisArithmetic : public ::testing::TestWithParam<AxisCase> {};

TEST_P(AxisArithmetic, MatchesTheDocumentedArithmetic) {
  const auto& c = GetParam();
  const double z = shape_axis(normalise_axis(static_cast<std::int16_t>(c.raw)), c.shape);
  EXPECT_EQ(c.centred ? centred_byte(z, 128) : level_byte(z), c.out) << "raw " << c.raw;
}

INSTANTIATE_TEST_SUITE_P(
    Values, AxisArithmetic,
    ::testing::Values(AxisCase{16384, {false, 0.1, 0.5}, true, 162},               // docs/mapping.md's example
                      AxisCase{0, {}, true, 128}, AxisCase{32767, {}, true, 255},  // 128 + 127
                      AxisCase{-32768, {}, true, 0},                               // -1 exactly: 128 - 128
                      AxisCase{-32768, {true, 0.0, 0.0}, true, 255},               // inverted
                      AxisCase{-16384, {}, true, 64},                              // x = -0.5: 128 - 64
                      AxisCase{16384, {}, true, 192},                 // 0.500015 * 127 = 63.50 -> 64 (half away from 0)
                      AxisCase{16383, {}, true, 191},                 // 0.499985 * 127 = 63.498 -> 63
                      AxisCase{-3276, {false, 0.1, 0.0}, true, 128},  // inside the deadzone
                      AxisCase{-32768, {false, 0.1, 0.5}, true, 0},
                      AxisCase{32767, {false, 0.0, 1.0}, true, 255},  // full expo: y^3
                      AxisCase{16384, {false, 0.0, 1.0}, true, 144},  // 0.125 * 127 = 15.88 -> 16
                      AxisCase{0, {}, false, 0}, AxisCase{32767, {}, false, 255},
                      AxisCase{8192, {}, false, 64},    // 255 * 0.250008 = 63.75
                      AxisCase{16384, {}, false, 128},  // 127.504
                      AxisCase{-20000, {}, false, 0}),  // a stick's negative half on a level byte
    [](const auto& param_info) { return "case" + std::to_string(param_info.index); });

TEST(AxisArithmetic, RoundsHalvesAwayFromZero) {
  EXPECT_EQ(round_half_away(2.5), 3);
  EXPECT_EQ(round_half_away(-2.5), -3);
  EXPECT_EQ(round_half_away(-0.4), 0);
  EXPECT_EQ(centred_byte(-64.5 / 128.0, 128), 63);  // 128 + round(-64.5) = 128 - 65
}

TEST(AxisArithmetic, OtherCentresClamp) {
  EXPECT_EQ(centred_byte(1.0, 100), 255);
  EXPECT_EQ(centred_byte(-1.0, 100), 0);
  EXPECT_EQ(centred_byte(-0.5, 100), 50);
  EXPECT_EQ(centred_byte(0.5, 0), 128);  // 0 + round(0.5 * 255) = 127.5 -> 128
}

}  // namespace
}  // namespace andros::mapping
