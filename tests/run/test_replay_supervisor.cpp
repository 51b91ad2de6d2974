// The supervisor's controller through the run loop on the virtual clock
// (replay): each report names both controllers, the operating state waits for
// both, and the supervisor's stop reaches the loop on the tick that sees it.
#include <gtest/gtest.h>

#include <algorithm>

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
  const auto r = replay_reports(
      "0 connect Pad A\n10 button leftshoulder 1\n90 supervisor connect Pad B\n"
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
  EXPECT_EQ(r[3].engine.deadman, mapping::DeadmanState::kHeldNotFresh);
  EXPECT_EQ(r[4].state, OpState::kNoController);
  EXPECT_FALSE(r[4].supervisor_connected);

  const auto alone = replay_reports("0 connect Pad A\n10 button leftshoulder 1\n80 end\n", kSupervisorMapping);
  EXPECT_FALSE(alone.back().supervised);
  EXPECT_EQ(alone.back().state, OpState::kEnabled);  // a script without a supervisor runs as before
}

// The supervisor's stop latches as the operator's own does, and is the
// supervisor's: a tap is enough, the deadman released and pressed never
// resets it, nor its stop held; the supervisor's reset chord (back and start
// on its pad) held 2 s with the deadman released does; the deadman must
// then be pressed afresh.
TEST(ReplaySupervisor, TheSupervisorsStopLatchesLikeTheOperators) {
  const auto states = [](const std::string& script) {
    std::vector<OpState> out;
    for (const auto& t : replay_reports(script, kSupervisorMapping)) out.push_back(t.state);
    return out;
  };
  using S = OpState;
  // 0..280 every 40 ms: a tap at 90, LB released at 170, pressed again at 210: still stopped.
  EXPECT_EQ(states("0 connect\n0 supervisor connect\n10 button leftshoulder 1\n"
                   "90 supervisor button x 1\n95 supervisor button x 0\n"
                   "170 button leftshoulder 0\n210 button leftshoulder 1\n280 end\n"),
            (std::vector<S>{S::kNotEnabled, S::kEnabled, S::kEnabled, S::kStopped, S::kStopped, S::kStopped,
                            S::kStopped, S::kStopped}));
  // Its stop held 2 s and more: a stop, never a reset (issue 33).
  const auto held = states(
      "0 connect\n0 supervisor connect\n10 button leftshoulder 1\n90 supervisor button x 1\n"
      "95 supervisor button x 0\n130 button leftshoulder 0\n150 supervisor button x 1\n2300 supervisor button x 0\n"
      "2330 button leftshoulder 1\n2400 end\n");
  EXPECT_EQ(std::count(held.begin(), held.end(), S::kStopped), 58);  // 120 .. 2400
  // Reset by the supervisor's chord (from 160, done at 2160); who stopped and who reset in the reports.
  const auto r = replay_reports(
      "0 connect Pad A\n0 supervisor connect Pad B\n10 button leftshoulder 1\n"
      "90 supervisor button x 1\n95 supervisor button x 0\n130 button leftshoulder 0\n"
      "150 supervisor button back 1\n150 supervisor button start 1\n2300 supervisor button back 0\n"
      "2300 supervisor button start 0\n2330 button leftshoulder 1\n2400 end\n",
      kSupervisorMapping);
  ASSERT_EQ(r.size(), 61U);  // 0 .. 2400
  EXPECT_EQ(r[3].state, S::kStopped);
  EXPECT_EQ(r[3].stopped_by, StopBy::kSupervisor);
  EXPECT_EQ(r[53].state, S::kStopped);     // 2120
  EXPECT_EQ(r[54].state, S::kNotEnabled);  // 2160: reset, and not enabled
  EXPECT_FALSE(r[54].stopped_by);
  EXPECT_EQ(r[54].reset_by, StopBy::kSupervisor);
  EXPECT_EQ(r[54].reset_pad.name, "Pad B");
  EXPECT_EQ(r[59].state, S::kEnabled);  // 2360: the fresh press
  EXPECT_FALSE(r[59].reset_by);
}

TEST(ReplaySupervisor, TheSupervisorsHeldStopIsShownWhileStopped) {
  using S = OpState;
  const auto states = [](const std::string& script) {
    std::vector<OpState> out;
    for (const auto& t : replay_reports(script, kSupervisorMapping)) out.push_back(t.state);
    return out;
  };
  // Held by the supervisor through the deadman's release and press: still stopped.
  EXPECT_EQ(states("0 connect\n0 supervisor connect\n10 button leftshoulder 1\n"
                   "90 supervisor button x 1\n170 button leftshoulder 0\n210 button leftshoulder 1\n280 end\n")
                .back(),
            S::kStopped);
  // While stopped the engine is not stepped, but what the screen says is held is now's.
  const auto r = replay_reports(
      "0 connect\n0 supervisor connect\n10 button leftshoulder 1\n"
      "90 supervisor button x 1\n130 supervisor button x 0\n200 end\n",
      kSupervisorMapping);
  ASSERT_GE(r.size(), 5U);
  EXPECT_EQ(r[3].state, S::kStopped);  // 120
  EXPECT_TRUE(r[3].engine.supervisor_stop);
  EXPECT_EQ(r[4].state, S::kStopped);  // 160: the deadman still held
  EXPECT_FALSE(r[4].engine.supervisor_stop);
}

}  // namespace
}  // namespace andros::run
