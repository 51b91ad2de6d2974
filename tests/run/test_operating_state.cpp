// The operating-state machine: every row of its table taken from a state
// reached by real events, and the rules the table must keep whatever its rows.
#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "andros/run/operating_state.hpp"

namespace andros::run {
namespace {

using S = OpState;
using E = OpEvent;

constexpr std::array kStates = {S::kNoLink,  S::kNoController, S::kNotEnabled, S::kEnabled,
                                S::kStopped, S::kSuspended,    S::kReloading,  S::kShuttingDown};
constexpr std::array kEvents = {E::kLinkUp,         E::kLinkDown,        E::kLinkTaken,      E::kControllerUp,
                                E::kControllerDown, E::kFreshPress,      E::kRelease,        E::kPanic,
                                E::kEnableTimeout,  E::kOperatorStop,    E::kSupervisorStop, E::kGateTrip,
                                E::kOperatorReset,  E::kSupervisorReset, E::kReloadBegin,    E::kReloadDone,
                                E::kSuspend,        E::kResume,          E::kShutdown,       E::kNeutralSent};

bool is_reset(E e) { return e == E::kOperatorReset || e == E::kSupervisorReset; }
bool is_stop(E e) { return e == E::kOperatorStop || e == E::kSupervisorStop || e == E::kGateTrip; }

/// The conditions a machine can be in while in `state`: link up or not,
/// controller up or not, and its neutral frames (a suspend's, reload's or
/// shutdown's) still going out or out.
struct Start {
  S state;
  bool link;
  bool controller;
  bool sent = false;
};

/// A machine brought to `start` by events, as the loop would.
OperatingState reach(const Start& start) {
  OperatingState m(false);
  if (start.controller) m.on(E::kControllerUp);
  if (start.link) m.on(E::kLinkUp);
  switch (start.state) {
    case S::kNoLink:
    case S::kNoController:
    case S::kNotEnabled: break;
    case S::kEnabled: m.on(E::kFreshPress); break;
    case S::kStopped: m.on(E::kOperatorStop); break;
    case S::kSuspended: m.on(E::kSuspend); break;
    case S::kReloading: m.on(E::kReloadBegin); break;
    case S::kShuttingDown: m.on(E::kShutdown); break;
  }
  if (start.sent) m.on(E::kNeutralSent);
  return m;
}

/// Every way to be in each state (the driving ones have one each; the others any).
std::vector<Start> starts() {
  std::vector<Start> out = {{S::kNoLink, false, false},
                            {S::kNoLink, false, true},
                            {S::kNoController, true, false},
                            {S::kNotEnabled, true, true},
                            {S::kEnabled, true, true}};
  for (const auto s : {S::kStopped, S::kSuspended, S::kReloading, S::kShuttingDown}) {
    for (const bool link : {false, true}) {
      for (const bool pad : {false, true}) {
        // Enabled first where it can be, so that the stop, suspend or reload interrupts driving.
        out.push_back({s, link, pad});
        if (s != S::kStopped) out.push_back({s, link, pad, true});
      }
    }
  }
  return out;
}

S settled(bool link, bool controller) {
  if (!link) return S::kNoLink;
  return controller ? S::kNotEnabled : S::kNoController;
}

TEST(OperatingState, ReachesEveryStartItClaims) {
  for (const auto& start : starts()) {
    const auto m = reach(start);
    EXPECT_EQ(m.state(), start.state) << to_string(start.state) << " link " << start.link << " pad "
                                      << start.controller;
    EXPECT_EQ(m.link_up(), start.link);
    EXPECT_EQ(m.controller_up(), start.controller);
  }
}

/// The row a machine at `start` takes for `event`: the first that holds (a
/// row for while the neutral frames go out holds only then).
const Row* row_taken(const Start& start, E event) {
  for (const auto& row : OperatingState::table()) {
    if (row.from == start.state && row.event == event && (!row.sending || !start.sent)) return &row;
  }
  return nullptr;
}

TEST(OperatingState, EveryRowOfTheTableIsTakenAsWritten) {
  std::set<std::tuple<S, E, bool>> exercised;
  for (const auto& row : OperatingState::table()) {
    int taken = 0;
    for (const auto& start : starts()) {
      if (row_taken(start, row.event) != &row) continue;
      auto m = reach(start);
      if (row.act == Act::kWait || row.act == Act::kWithdraw || row.act == Act::kAgain) {
        const Effect effect = m.on(row.event);
        EXPECT_EQ(m.state(), row.from) << to_string(row.from) << " + " << to_string(row.event);
        EXPECT_FALSE(effect.changed);
        EXPECT_FALSE(effect.rebase);
        EXPECT_EQ(m.waiting(row.event), row.act == Act::kWait);
        EXPECT_EQ(effect.neutral_frames, row.act == Act::kAgain);
        EXPECT_EQ(effect.begin_reload, row.act == Act::kAgain);
        ++taken;
        continue;
      }
      const Effect effect = m.on(row.event);
      const bool link = row.event == E::kLinkUp                                   ? true
                        : row.event == E::kLinkDown || row.event == E::kLinkTaken ? false
                                                                                  : start.link;
      const bool pad = row.event == E::kControllerUp     ? true
                       : row.event == E::kControllerDown ? false
                                                         : start.controller;
      // A stop latched before the row (or by it) still holds after it, unless the row clears it.
      const bool latched = (start.state == S::kStopped || is_stop(row.event)) && !is_reset(row.event);
      const S want = row.act == Act::kSettle ? (latched ? S::kStopped : settled(link, pad)) : row.to;
      EXPECT_EQ(m.state(), want) << to_string(row.from) << " + " << to_string(row.event);
      EXPECT_EQ(effect.rebase, row.rebase) << to_string(row.from) << " + " << to_string(row.event);
      EXPECT_EQ(effect.changed, want != row.from);
      ++taken;
    }
    EXPECT_GT(taken, 0) << "no test reaches " << to_string(row.from) << " + " << to_string(row.event);
    EXPECT_TRUE(exercised.insert({row.from, row.event, row.sending}).second)
        << "two rows for " << to_string(row.from) << " + " << to_string(row.event);
  }
}

TEST(OperatingState, AnEventWithoutARowChangesNothingButItsCondition) {
  for (const auto& start : starts()) {
    for (const auto event : kEvents) {
      bool has_row = false;
      for (const auto& row : OperatingState::table()) has_row |= row.from == start.state && row.event == event;
      if (has_row) continue;
      auto m = reach(start);
      const Effect effect = m.on(event);
      EXPECT_EQ(m.state(), start.state) << to_string(start.state) << " + " << to_string(event);
      EXPECT_FALSE(effect.changed);
      EXPECT_FALSE(effect.rebase);
    }
  }
}

TEST(OperatingState, TheOnlyWayIntoEnabledIsAFreshPressInNotEnabled) {
  for (const auto& row : OperatingState::table()) {
    if (row.to == S::kEnabled && row.act == Act::kGo) {
      EXPECT_EQ(row.from, S::kNotEnabled);
      EXPECT_EQ(row.event, E::kFreshPress);
    }
  }
  // Whatever sequence of events: enabled only right after a fresh press seen in not enabled.
  for (const auto& start : starts()) {
    for (const auto first : kEvents) {
      for (const auto second : kEvents) {
        auto m = reach(start);
        m.on(first);
        const S before = m.state();
        m.on(second);
        if (m.state() == S::kEnabled && before != S::kEnabled) {
          EXPECT_EQ(before, S::kNotEnabled);
          EXPECT_EQ(second, E::kFreshPress);
        }
      }
    }
  }
}

TEST(OperatingState, WhateverInterruptsDrivingEndsEnabledAndComesBackThroughARebase) {
  // Each of these, from enabled, leaves a state that is not enabled.
  for (const auto event : {E::kLinkDown, E::kLinkTaken, E::kControllerDown, E::kRelease, E::kPanic, E::kEnableTimeout,
                           E::kOperatorStop, E::kReloadBegin, E::kSuspend, E::kResume, E::kShutdown}) {
    auto m = reach({S::kEnabled, true, true});
    m.on(event);
    EXPECT_FALSE(m.motion_allowed()) << to_string(event);
  }
  // Every way back to the driving states from an interruption rebases the
  // engine (a press before it is history), but a controller coming back:
  // the engine counts presses per connection itself.
  for (const auto& row : OperatingState::table()) {
    if (row.act != Act::kSettle) continue;
    EXPECT_EQ(row.rebase, row.event != E::kControllerUp) << to_string(row.from) << " + " << to_string(row.event);
  }
}

TEST(OperatingState, TheOperatorsStopLatchesThroughEverythingButItsClearing) {
  // From every driving state, a stop button lands in stopped, and no sequence
  // of two further events but the clearing and a shutdown leaves it for a
  // state that may send anything: a suspend or a reload comes back to it.
  for (const auto& start : starts()) {
    if (start.state == S::kShuttingDown) continue;
    for (const auto first : kEvents) {
      for (const auto second : kEvents) {
        if (is_reset(first) || is_reset(second)) continue;
        if (first == E::kShutdown || second == E::kShutdown) continue;
        auto m = reach(start);
        m.on(E::kOperatorStop);
        EXPECT_TRUE(m.stop_latched());
        m.on(first);
        m.on(second);
        EXPECT_FALSE(m.motion_allowed()) << to_string(start.state) << ": " << to_string(first) << ", "
                                         << to_string(second);
        EXPECT_TRUE(m.stop_latched());
        const S s = m.state();
        EXPECT_TRUE(s == S::kStopped || s == S::kSuspended || s == S::kReloading) << to_string(s);
      }
    }
  }
  // Suspended or reloading when the stop came: it is there when they end.
  for (const auto& [begin, end] : {std::pair{E::kSuspend, E::kResume}, std::pair{E::kReloadBegin, E::kReloadDone}}) {
    auto m = reach({S::kEnabled, true, true});
    m.on(begin);
    m.on(E::kNeutralSent);  // the loop's frames are out
    m.on(E::kOperatorStop);
    m.on(end);
    EXPECT_EQ(m.state(), S::kStopped) << to_string(begin);
  }
  // Reset: not enabled, rebased; a fresh press is still needed.
  auto m = reach({S::kEnabled, true, true});
  m.on(E::kOperatorStop);
  const Effect cleared = m.on(E::kOperatorReset);
  EXPECT_EQ(m.state(), S::kNotEnabled);
  EXPECT_TRUE(cleared.rebase);
  EXPECT_FALSE(m.stop_latched());
  EXPECT_EQ(m.reset_by(), StopBy::kOperator);
  m.on(E::kFreshPress);
  EXPECT_EQ(m.state(), S::kEnabled);
  EXPECT_FALSE(m.reset_by());  // said until enabled again
}

TEST(OperatingState, TheSupervisorResetsAnyStopTheOperatorOnlyTheOperators) {
  // The supervisor's stop: the operator's reset changes nothing, whatever comes before it.
  for (const auto first : {E::kSupervisorStop, E::kOperatorStop}) {
    auto m = reach({S::kEnabled, true, true});
    m.on(first);
    m.on(E::kSupervisorStop);  // the supervisor's, though the operator's came first
    EXPECT_EQ(m.stopped_by(), StopBy::kSupervisor);
    const Effect refused = m.on(E::kOperatorReset);
    EXPECT_FALSE(refused.changed);
    EXPECT_FALSE(refused.rebase);
    EXPECT_EQ(m.state(), S::kStopped);
    EXPECT_EQ(m.stopped_by(), StopBy::kSupervisor);
    m.on(E::kSupervisorReset);
    EXPECT_EQ(m.state(), S::kNotEnabled);
    EXPECT_EQ(m.reset_by(), StopBy::kSupervisor);
  }
  // The operator's stop stays the operator's when the operator presses again; the supervisor resets it too.
  auto m = reach({S::kEnabled, true, true});
  m.on(E::kOperatorStop);
  m.on(E::kOperatorStop);
  EXPECT_EQ(m.stopped_by(), StopBy::kOperator);
  m.on(E::kSupervisorReset);
  EXPECT_EQ(m.state(), S::kNotEnabled);
  // A reset outside "stopped" (a suspend or a reload under way) resets nothing.
  for (const auto& [begin, end] : {std::pair{E::kSuspend, E::kResume}, std::pair{E::kReloadBegin, E::kReloadDone}}) {
    auto n = reach({S::kEnabled, true, true});
    n.on(E::kOperatorStop);
    n.on(begin);
    n.on(E::kNeutralSent);
    n.on(E::kSupervisorReset);
    n.on(end);
    EXPECT_EQ(n.state(), S::kStopped) << to_string(begin);
  }
}

// The orderings (docs/safety-states.md, "Orderings"): the machine's, as waiting events.
TEST(OperatingState, ASuspendDuringAReloadWaitsForItsOutcome) {
  auto m = reach({S::kEnabled, true, true});
  m.on(E::kReloadBegin);
  EXPECT_EQ(m.on(E::kSuspend), Effect{});
  EXPECT_EQ(m.state(), S::kReloading);
  EXPECT_TRUE(m.waiting(E::kSuspend));
  const Effect done = m.on(E::kReloadDone);
  EXPECT_EQ(m.state(), S::kSuspended);
  EXPECT_TRUE(done.rebase);          // the reload's
  EXPECT_TRUE(done.neutral_frames);  // the suspend's own frames
  EXPECT_FALSE(m.waiting(E::kSuspend));
  EXPECT_TRUE(m.neutral_due());
}

TEST(OperatingState, AResumeBeforeTheReloadsOutcomeAnswersTheSuspendWaitingBehindIt) {
  auto m = reach({S::kEnabled, true, true});
  m.on(E::kReloadBegin);
  m.on(E::kSuspend);
  m.on(E::kResume);
  EXPECT_FALSE(m.waiting(E::kSuspend));
  m.on(E::kReloadDone);
  EXPECT_EQ(m.state(), S::kNotEnabled);
}

TEST(OperatingState, AReloadWhileSuspendedIsAnsweredAfterTheResume) {
  auto m = reach({S::kSuspended, true, true, true});
  EXPECT_EQ(m.on(E::kReloadBegin), Effect{});
  EXPECT_EQ(m.state(), S::kSuspended);
  const Effect resumed = m.on(E::kResume);
  EXPECT_EQ(m.state(), S::kReloading);
  EXPECT_TRUE(resumed.rebase);
  EXPECT_TRUE(resumed.begin_reload);
  EXPECT_TRUE(resumed.neutral_frames);
}

TEST(OperatingState, AResumeWhileTheSuspendsFramesGoOutWaitsForThem) {
  auto m = reach({S::kSuspended, true, true});
  m.on(E::kResume);
  EXPECT_EQ(m.state(), S::kSuspended);
  EXPECT_TRUE(m.waiting(E::kResume));
  const Effect sent = m.on(E::kNeutralSent);
  EXPECT_EQ(m.state(), S::kNotEnabled);
  EXPECT_TRUE(sent.rebase);
  // Suspend, resume, suspend: the last word counts.
  auto n = reach({S::kSuspended, true, true});
  n.on(E::kResume);
  n.on(E::kSuspend);
  n.on(E::kNeutralSent);
  EXPECT_EQ(n.state(), S::kSuspended);
}

TEST(OperatingState, ASecondReloadBeginsItAgainAndAShutdownEndsWhatWaits) {
  auto m = reach({S::kReloading, true, true, true});
  const Effect again = m.on(E::kReloadBegin);
  EXPECT_EQ(m.state(), S::kReloading);
  EXPECT_TRUE(again.neutral_frames && again.begin_reload && !again.changed);
  EXPECT_TRUE(m.neutral_due());
  m.on(E::kSuspend);
  m.on(E::kShutdown);
  EXPECT_EQ(m.state(), S::kShuttingDown);
  EXPECT_FALSE(m.waiting(E::kSuspend));
  m.on(E::kReloadDone);
  EXPECT_EQ(m.state(), S::kShuttingDown);
}

// Issue 36, item 4: each step of the machine is published as {from, event,
// to, who}: a state changed, a condition changed (a stop made another's, a
// stop pressed again, the neutral frames out), an event that waits; a step
// that changes nothing (a reset that may not reset) is not.
TEST(OperatingState, EachStepIsPublishedWithWhoMadeIt) {
  OperatingState m(true);
  m.set_pads(1, 2);
  m.on(E::kControllerUp);
  m.on(E::kFreshPress);
  m.on(E::kOperatorStop);
  m.on(E::kSupervisorStop);
  m.on(E::kOperatorStop);
  m.on(E::kOperatorReset);  // the supervisor's stop: the operator may not reset it
  m.on(E::kSupervisorReset);
  m.on(E::kControllerDown, Who::kSupervisor);
  m.on(E::kControllerUp);  // the one that comes back is the one that was lost
  m.on(E::kReloadBegin, Who::kScript);
  m.on(E::kSuspend, Who::kRequest);  // waits for the reload's outcome
  m.on(E::kNeutralSent);
  m.on(E::kReloadDone, Who::kLoop, true);  // and the suspend that waited, as the request's
  using W = Who;
  const std::vector<Transition> want{
      {S::kNoController, E::kControllerUp, S::kNotEnabled, W::kOperator},
      {S::kNotEnabled, E::kFreshPress, S::kEnabled, W::kOperator},
      {S::kEnabled, E::kOperatorStop, S::kStopped, W::kOperator, 1},
      {S::kStopped, E::kSupervisorStop, S::kStopped, W::kSupervisor, 2},
      {S::kStopped, E::kOperatorStop, S::kStopped, W::kOperator, 1, true},
      {S::kStopped, E::kSupervisorReset, S::kNotEnabled, W::kSupervisor, 2},
      {S::kNotEnabled, E::kControllerDown, S::kNoController, W::kSupervisor},
      {S::kNoController, E::kControllerUp, S::kNotEnabled, W::kSupervisor},
      {S::kNotEnabled, E::kReloadBegin, S::kReloading, W::kScript},
      {S::kReloading, E::kSuspend, S::kReloading, W::kRequest},
      {S::kReloading, E::kNeutralSent, S::kReloading, W::kLoop},
      {S::kReloading, E::kReloadDone, S::kNotEnabled, W::kLoop, input::kNoPad, false, true},
      {S::kNotEnabled, E::kSuspend, S::kSuspended, W::kRequest},
  };
  const auto got = m.take_transitions();
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i) {
    EXPECT_EQ(got[i], want[i]) << i << ": " << to_string(got[i].from) << " + " << to_string(got[i].event) << " -> "
                               << to_string(got[i].to);
  }
  EXPECT_TRUE(m.take_transitions().empty());  // taken
}

TEST(OperatingState, StoppingIsTheEnd) {
  for (const auto event : kEvents) {
    auto m = reach({S::kShuttingDown, true, true});
    m.on(event);
    EXPECT_EQ(m.state(), S::kShuttingDown) << to_string(event);
  }
}

TEST(OperatingState, TheDocsTableIsTheCodes) {
  std::ifstream in(ANDROS_DOCS_DIR "/safety-states.md");
  ASSERT_TRUE(in) << "docs/safety-states.md";
  std::vector<std::string> documented;
  bool inside = false;
  for (std::string line; std::getline(in, line);) {
    if (line.starts_with("<!-- transition table")) inside = true;
    if (line.starts_with("<!-- end of transition table")) inside = false;
    if (inside && line.starts_with("| ") && !line.starts_with("| from")) documented.push_back(line);
  }
  std::vector<std::string> code;
  for (const auto& row : OperatingState::table()) {
    std::ostringstream out;
    out << "| " << to_string(row.from) << " | " << to_string(row.event) << " | " << to_string(row) << " | "
        << (row.rebase ? "yes" : "no") << " |";
    code.push_back(out.str());
  }
  EXPECT_EQ(documented, code);
}

TEST(OperatingState, EveryStateAndEventHasAName) {
  std::set<std::string_view> names;
  for (const auto s : kStates) EXPECT_TRUE(names.insert(to_string(s)).second);
  for (const auto e : kEvents) EXPECT_TRUE(names.insert(to_string(e)).second);
  EXPECT_EQ(names.count("?"), 0U);
}

}  // namespace
}  // namespace andros::run
