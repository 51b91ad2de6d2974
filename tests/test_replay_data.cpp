// Table-driven replay: every tests/data/replay/NAME.events against its
// hand-derived NAME.expected (see replay_data.hpp for the format).
#include <gtest/gtest.h>

#include <sstream>

#include "andros/mapping_loader.hpp"
#include "andros/replay.hpp"
#include "replay_data.hpp"

namespace andros {
namespace {

struct Case {
  const char* name;
  const char* mapping;  // under tests/data/mappings/
  bool weapons = false;
  std::int64_t rate_mhz = kDefaultRateMillihertz;
};

const std::string kData = ANDROS_TEST_DATA_DIR;

class ReplayData : public ::testing::TestWithParam<Case> {};

TEST_P(ReplayData, FramesMatchTheHandDerivedOnes) {
  const auto& c = GetParam();
  const std::uint8_t code = 0x01;
  Engine engine(load_mapping(kData + "/mappings/" + c.mapping), EngineOptions{c.weapons, code});
  const std::string events = kData + "/replay/" + c.name + ".events";
  std::istringstream in(testing::read_text(events));
  ScriptPlayer player(in, events);
  std::vector<std::pair<std::int64_t, DataBytes>> got;
  replay(player, engine, FrameClock(c.rate_mhz), [&](std::int64_t t, const DataBytes& d) { got.emplace_back(t, d); });

  const auto want = testing::read_expected(kData + "/replay/" + c.name + ".expected", code);
  ASSERT_EQ(got.size(), want.size()) << "frame count";
  for (std::size_t i = 0; i < want.size(); ++i) {
    EXPECT_EQ(got[i].first, want[i].t) << "frame " << i;
    EXPECT_TRUE(validation_errors(got[i].second).empty());
    const auto expected = FrameBuilder(code).build(want[i].state);
    EXPECT_EQ(got[i].second, expected) << c.name << ".expected:" << want[i].line << " t=" << want[i].t << ": "
                                       << testing::describe_difference(read_signals(expected), read_signals(got[i].second));
  }
}

INSTANTIATE_TEST_SUITE_P(
    Catalogue, ReplayData,
    ::testing::Values(
        Case{"momentary", "core.yaml"},
        Case{"toggle", "core.yaml"},
        Case{"opposing_axis_pair", "core.yaml"},
        Case{"drive_deadzone", "core.yaml"},
        Case{"pivot_deadzone_expo", "core.yaml"},
        Case{"trigger_analog", "core.yaml"},
        Case{"knob_ramp", "core.yaml"},
        Case{"deadman_release", "core.yaml"},
        Case{"fresh_press_after_connect", "core.yaml"},
        Case{"stuck_deadman_at_connect", "core.yaml"},
        Case{"controller_loss_mid_drive", "core.yaml"},
        Case{"reconnect", "core.yaml"},
        Case{"toggle_cleared_by_loss", "core.yaml"},
        Case{"short_tap_between_frames", "core.yaml"},
        Case{"opposing_buttons", "core.yaml"},
        Case{"presses_while_disabled_ignored", "core.yaml"},
        Case{"weapons_off", "core.yaml"},
        Case{"weapons_on_without_arming", "core.yaml", true},
        Case{"weapons_on_armed", "core.yaml", true},
        Case{"selector_cycling", "layers.yaml"},
        Case{"layers", "layers.yaml"},
        Case{"rate_24hz", "core.yaml", false, 24'000}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace andros
