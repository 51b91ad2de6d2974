// The supervisor's controller through the run loop on the virtual clock
// (replay): each report names both controllers, the operating state waits for
// both, and the supervisor's stop reaches the loop on the tick that sees it.
#include <gtest/gtest.h>

#include <vector>

#include "andros/input/script_player.hpp"
#include "andros/mapping/loader.hpp"
#include "andros/run/replay.hpp"

namespace andros::run {
namespace {

std::vector<TickReport> replay_reports(const std::string& script, const std::string& mapping_file) {
  TextReader in(script, "s.events", kEventScriptLimits);
  input::ScriptPlayer player(in);
  std::vector<TickReport> reports;
  ReplayOptions options;
  options.observe = [&reports](const TickReport& r) { reports.push_back(r); };
  replay(player, mapping::Engine(mapping::load_mapping(mapping_file), options.engine), options,
         [](std::int64_t, const protocol::DataBytes&) {});
  return reports;
}

const std::string kSupervisorMapping = ANDROS_TEST_DATA_DIR "/mappings/supervisor.yaml";

TEST(ReplaySupervisor, EachReportNamesBothControllersAndTheStateWaitsForBoth) {
  const auto r = replay_reports("0 connect Pad A\n10 button leftshoulder 1\n90 supervisor connect Pad B\n"
                                "130 supervisor disconnect\n160 end\n",
                                kSupervisorMapping);
  ASSERT_EQ(r.size(), 5U);  // 0 .. 160
  for (const auto& t : r) EXPECT_TRUE(t.supervised) << t.t_ms;
  EXPECT_EQ(r[1].state, OpState::kNoController);  // the operator's deadman, but no supervisor yet
  EXPECT_TRUE(r[1].connected);
  EXPECT_FALSE(r[1].supervisor_connected);
  EXPECT_EQ(r[3].state, OpState::kNotEnabled);  // 120: both there, the deadman no longer fresh
  EXPECT_TRUE(r[3].supervisor_connected);
  EXPECT_EQ(r[3].supervisor, "Pad B");
  EXPECT_EQ(r[3].engine.enable, mapping::EnableState::kDeadmanNotFresh);
  EXPECT_EQ(r[4].state, OpState::kNoController);
  EXPECT_FALSE(r[4].supervisor_connected);

  const auto alone = replay_reports("0 connect Pad A\n10 button leftshoulder 1\n80 end\n", kSupervisorMapping);
  EXPECT_FALSE(alone.back().supervised);
  EXPECT_EQ(alone.back().state, OpState::kEnabled);  // a script without a supervisor runs as before
}

// Until the loop latches it (the operator's stop, issue 16 item 1), the stop
// is what the engine reports: pressed on the tick that sees the press, held
// while it is held.
TEST(ReplaySupervisor, TheSupervisorsStopReachesTheLoopOnTheTickThatSeesIt) {
  const auto r = replay_reports("0 connect\n0 supervisor connect\n10 button leftshoulder 1\n"
                                "90 supervisor button x 1\n95 supervisor button x 0\n"
                                "170 supervisor button x 1\n250 supervisor button x 0\n280 end\n",
                                kSupervisorMapping);
  std::vector<std::int64_t> pressed;
  std::vector<std::int64_t> held;
  for (const auto& t : r) {
    if (t.engine.stop_pressed) pressed.push_back(t.t_ms);
    if (t.engine.stop_held) held.push_back(t.t_ms);
  }
  EXPECT_EQ(pressed, (std::vector<std::int64_t>{120, 200, 240}));
  EXPECT_EQ(held, (std::vector<std::int64_t>{200, 240}));
}

}  // namespace
}  // namespace andros::run
