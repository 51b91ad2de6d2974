// ScriptPlayer: the timing of docs/event-scripts.md, on a clock it is told.
#include <gtest/gtest.h>

#include "andros/base/error.hpp"
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
                                           Ending{"# nothing\n", 0},
                                           Ending{"0 connect\n80 end\n", 80},
                                           Ending{"0 connect\n81 end\n", 120},
                                           Ending{"0 end\n", 0}));

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
