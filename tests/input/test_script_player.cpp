// ScriptPlayer: the timing of docs/event-scripts.md, on a clock it is told.
#include <gtest/gtest.h>

#include "andros/base/error.hpp"
#include "andros/input/events.hpp"
#include "andros/input/script_player.hpp"

namespace andros::input {
namespace {

TEST(ScriptPlayer, AppliesEventsUpToEachFrameTime) {
  TextReader in("0 connect\n40 button a 1\n41 button b 1\n100 end\n", "s.events", kEventScriptLimits);
  ScriptPlayer player(in);
  InputState s;
  const auto a = *parse_button_name("a");
  const auto b = *parse_button_name("b");
  player.advance_to(0, s);
  EXPECT_TRUE(s.connected());
  EXPECT_FALSE(s.button(a).down);
  EXPECT_FALSE(player.finished_at(0));
  player.advance_to(40, s);  // an event at the frame's own time is in that frame
  EXPECT_TRUE(s.button(a).down);
  EXPECT_FALSE(s.button(b).down);
  player.advance_to(80, s);
  EXPECT_TRUE(s.button(b).down);
  EXPECT_FALSE(player.finished_at(80));
  player.advance_to(120, s);
  EXPECT_TRUE(player.finished_at(120));  // the first frame time >= end
}

struct Ending {
  const char* script;
  std::int64_t last_frame;  // at 25 Hz
};

class ScriptEnding : public ::testing::TestWithParam<Ending> {};

TEST_P(ScriptEnding, LastFrameIsTheFirstAtOrAfterTheEnd) {
  TextReader in(GetParam().script, "s.events", kEventScriptLimits);
  ScriptPlayer player(in);
  InputState s;
  std::int64_t t = 0;
  for (player.advance_to(t, s); !player.finished_at(t); player.advance_to(t, s)) t += 40;
  EXPECT_EQ(t, GetParam().last_frame);
}

INSTANTIATE_TEST_SUITE_P(Cases, ScriptEnding,
                         ::testing::Values(Ending{"0 connect\n90 button a 1\n", 120},  // no end: the last event
                                           Ending{"# nothing\n", 0}, Ending{"0 connect\n80 end\n", 80},
                                           Ending{"0 connect\n81 end\n", 120}, Ending{"0 end\n", 0}));

// A supervisor's line anywhere configures one for the whole run, from its start.
TEST(ScriptPlayer, ASupervisorLineAnywhereMakesTheScriptSupervised) {
  TextReader with("0 connect\n100 button a 1\n5000 supervisor connect Pad B\n", "s.events", kEventScriptLimits);
  ScriptPlayer supervised(with);
  EXPECT_TRUE(supervised.supervised());
  InputState s;
  supervised.advance_to(100, s);  // the scan rewound: the first line plays
  EXPECT_TRUE(s.connected());
  EXPECT_TRUE(s.button(*parse_button_name("a")).down);
  EXPECT_FALSE(s.supervisor().connected());
  supervised.advance_to(5000, s);
  EXPECT_TRUE(s.supervisor().connected());
  EXPECT_EQ(s.supervisor().name(), "Pad B");

  TextReader without("0 connect\n100 button a 1\n", "n.events", kEventScriptLimits);
  EXPECT_FALSE(ScriptPlayer(without).supervised());
}

// The supervisor's events reach its own pad's state; the operator's stays as it was.
TEST(InputState, EachControllersEventsReachItsOwnPadState) {
  InputState s;
  for (const auto& e : parse_event_script("0 connect Pad A\n0 supervisor connect Pad B\n0 supervisor button b 1\n"
                                          "10 supervisor button a 1\n20 button x 1\n30 link down\n",
                                          "s.events")) {
    s.apply(e);
  }
  const auto a = *parse_button_name("a");
  const auto b = *parse_button_name("b");
  const auto x = *parse_button_name("x");
  EXPECT_EQ(s.name(), "Pad A");
  EXPECT_EQ(s.supervisor().name(), "Pad B");
  EXPECT_FALSE(s.button(a).down);
  EXPECT_TRUE(s.button(x).down);
  EXPECT_TRUE(s.supervisor().button(a).down);
  EXPECT_EQ(s.supervisor().button(a).presses, 1U);
  EXPECT_TRUE(s.supervisor().button(b).down);
  EXPECT_EQ(s.supervisor().button(b).presses, 0U);  // held at its connect: not a press
  EXPECT_FALSE(s.supervisor().button(x).down);
  EXPECT_EQ(s.take_faults().size(), 1U);  // faults stay on the top state
  s.apply(parse_event_script("40 supervisor disconnect\n", "d").front());
  EXPECT_TRUE(s.connected());
  EXPECT_FALSE(s.supervisor().connected());
  EXPECT_FALSE(s.supervisor().button(a).down);
  EXPECT_EQ(s.supervisor().connection(), 1U);
  EXPECT_EQ(s.connection(), 1U);
}

TEST(ScriptPlayer, ParseErrorsSurfaceAsInputErrors) {
  TextReader in("0 connect\n200 jump\n", "s.events", kEventScriptLimits);
  ScriptPlayer player(in);
  InputState s;
  try {
    player.advance_to(0, s);  // reads one event ahead: line 2 is parsed here
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.pos().line, 2);
  }
}

}  // namespace
}  // namespace andros::input
