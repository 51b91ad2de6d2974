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
  TickInput input;
  const InputState& s = input.state();
  const auto a = *parse_button_name("a");
  const auto b = *parse_button_name("b");
  player.advance_to(0, input);
  EXPECT_TRUE(s.connected());
  EXPECT_FALSE(s.button(a).down);
  EXPECT_FALSE(player.finished_at(0));
  player.advance_to(40, input);  // an event at the frame's own time is in that frame
  EXPECT_TRUE(s.button(a).down);
  EXPECT_FALSE(s.button(b).down);
  player.advance_to(80, input);
  EXPECT_TRUE(s.button(b).down);
  EXPECT_FALSE(player.finished_at(80));
  player.advance_to(120, input);
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
  TickInput input;
  std::int64_t t = 0;
  for (player.advance_to(t, input); !player.finished_at(t); player.advance_to(t, input)) t += 40;
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
  TickInput input;
  const InputState& s = input.state();
  supervised.advance_to(100, input);  // the scan rewound: the first line plays
  EXPECT_TRUE(s.connected());
  EXPECT_TRUE(s.button(*parse_button_name("a")).down);
  EXPECT_FALSE(s.supervisor().connected());
  supervised.advance_to(5000, input);
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
  s.apply(parse_event_script("40 supervisor disconnect\n", "d").front());
  EXPECT_TRUE(s.connected());
  EXPECT_FALSE(s.supervisor().connected());
  EXPECT_FALSE(s.supervisor().button(a).down);
  EXPECT_EQ(s.supervisor().connection(), 1U);
  EXPECT_EQ(s.connection(), 1U);
}

// A script's fault events are the run loop's, never the input state's: the
// state after them reads as the state without them, and the loop takes them
// apart, in order, with the recorder's log keeping every event as it came.
TEST(TickInput, KeepsAScriptsFaultEventsApartFromTheInputState) {
  const auto events = parse_event_script(
      "0 connect Pad A\n10 button a 1\n20 link down\n20 button b 1\n30 suspend\n40 reload other.yaml\n"
      "50 link stalled\n60 stop\n",
      "s.events");
  TickInput input;
  InputState controllers_only;
  input.keep_applied(true);
  for (const auto& e : events) {
    input.apply(e);
    if (!e.is_fault()) controllers_only.apply(e);
  }
  EXPECT_EQ(input.state().operator_pad(), controllers_only.operator_pad());
  EXPECT_EQ(input.state().supervisor(), controllers_only.supervisor());
  const auto faults = input.take_faults();
  using Word = InputEvent::Type;
  std::vector<Word> words;
  for (const auto& f : faults) words.push_back(f.type);
  EXPECT_EQ(words, (std::vector{Word::kLinkDown, Word::kSuspend, Word::kReload, Word::kLinkStalled, Word::kShutdown}));
  ASSERT_EQ(faults.size(), 5U);
  EXPECT_EQ(faults[2].name, "other.yaml");
  EXPECT_TRUE(input.take_faults().empty());  // taken once
  const auto applied = input.take_applied();
  ASSERT_EQ(applied.size(), events.size());
  for (std::size_t i = 0; i < applied.size(); ++i) EXPECT_EQ(applied[i].line, events[i].line) << i;
}

// The player hands a script's fault events to the loop at their frame, as it hands the controllers' events.
TEST(ScriptPlayer, HandsFaultEventsApartAtTheirFrame) {
  TextReader in("0 connect\n30 button a 1\n40 link down\n50 resume\n", "s.events", kEventScriptLimits);
  ScriptPlayer player(in);
  TickInput input;
  player.advance_to(40, input);
  EXPECT_TRUE(input.state().button(*parse_button_name("a")).down);
  const auto at_40 = input.take_faults();
  ASSERT_EQ(at_40.size(), 1U);
  EXPECT_EQ(at_40[0].type, InputEvent::Type::kLinkDown);
  EXPECT_EQ(at_40[0].line, 3);
  player.advance_to(80, input);
  const auto at_80 = input.take_faults();
  ASSERT_EQ(at_80.size(), 1U);
  EXPECT_EQ(at_80[0].type, InputEvent::Type::kResume);
}

TEST(ScriptPlayer, ParseErrorsSurfaceAsInputErrors) {
  TextReader in("0 connect\n200 jump\n", "s.events", kEventScriptLimits);
  ScriptPlayer player(in);
  TickInput input;
  try {
    player.advance_to(0, input);  // reads one event ahead: line 2 is parsed here
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.pos().line, 2);
  }
}

}  // namespace
}  // namespace andros::input
