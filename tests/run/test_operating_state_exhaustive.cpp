// Every sequence of the operating-state machine's events up to kDepth, from
// each start (the link down, as `run` starts; up, as a replay does), each
// step judged by the oracle of tests/oracle/state_oracle.hpp, which is
// written from docs/safety-states.md and the contract, not from the table.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <iostream>
#include <string>
#include <vector>

#include "andros/run/operating_state.hpp"
#include "oracle/state_oracle.hpp"
#include "support/sweep.hpp"

namespace andros::run {
namespace {

/// The depth: every sequence of this many events, and so each shorter one
/// as its prefix. Fixed by the build, never chosen by speed: 21 steps (20
/// events and a pad swap) to depth 8 is 37,822,859,361 sequences per start, of which the walk
/// steps 236 million nodes (a no-op is not walked further: walk()): 10.8 s
/// of CPU (-O2) on the 2-core machine; depth 9 is some 20 times that. Under the sanitizers
/// (support/sweep.hpp) depth 6: every sequence two events shorter, at about a
/// hundredth of the steps (the sanitizers look for memory and undefined
/// behaviour along the machine's code; the plain build checks the rules to 8).
constexpr int kDepth = test::kSanitizedSweep ? 6 : 8;

/// One step of a walk: an event of the machine's, or (swap) another
/// physical pad taking the operator's role (pad 1 and pad 2 in turn; the
/// supervisor's is pad 3), which the machine reads as the loop tells it.
struct Step {
  OpEvent event{};
  bool swap = false;
};

/// Every event of the enum, read off it, so that an event added is searched too; and the swap.
std::vector<Step> all_events() {
  std::vector<Step> out;
  for (int i = 0; i <= UINT8_MAX; ++i) {
    const auto event = static_cast<OpEvent>(i);
    if (to_string(event) == "?") break;
    out.push_back({event, false});
  }
  out.push_back({OpEvent{}, true});
  return out;
}

std::string to_string(const Step& step) {
  return step.swap ? "another operator's pad" : std::string(run::to_string(step.event));
}

constexpr input::PadId kSupervisorPad = 3;

struct Node {
  OperatingState machine;
  test::StateOracle oracle;
  input::PadId operator_pad = 1;

  bool operator==(const Node&) const = default;
};

/// Walks every sequence from `start`, depth first; returns the number of
/// sequences of kDepth events checked, and the first failure in `failure`.
/// An event that leaves both the machine and the oracle as they were (a
/// no-op, judged sound) is not walked further: every sequence after it is
/// one after its parent, which the walk checks anyway (the two are values,
/// and each step a function of them and the event). Its sequences are
/// counted as checked; `walked` counts the nodes actually stepped.
std::uint64_t walk(const Node& start, const std::vector<Step>& events, std::string& failure, std::uint64_t& walked) {
  std::vector<Node> path(kDepth + 1, start);
  std::array<std::size_t, kDepth + 1> next{};
  std::array<std::uint64_t, kDepth + 1> below{};  // sequences of kDepth under a node at each depth
  below[kDepth] = 1;
  for (int d = kDepth - 1; d >= 0; --d)
    below[static_cast<std::size_t>(d)] = below[static_cast<std::size_t>(d) + 1] * events.size();
  std::uint64_t full = 0;
  int depth = 0;
  while (depth >= 0) {
    if (depth == kDepth || next[static_cast<std::size_t>(depth)] == events.size()) {
      if (depth == kDepth) ++full;
      --depth;
      continue;
    }
    const auto d = static_cast<std::size_t>(depth);
    const Step step = events[next[d]++];
    Node& node = path[d + 1];
    node = path[d];
    const char* broken = "";
    if (step.swap) {
      node.operator_pad = node.operator_pad == 1 ? 2 : 1;
      node.machine.set_pads(node.operator_pad, kSupervisorPad);
      node.oracle.operator_pad(node.operator_pad);
    } else {
      const OpState before = node.machine.state();
      const Effect effect = node.machine.on(step.event);
      broken = node.oracle.step(step.event, before, node.machine.state(), effect, node.machine.stop_latched());
    }
    ++walked;
    if (*broken == '\0' && node == path[d]) {
      full += below[d + 1];  // a no-op: what follows it follows its parent too
      continue;
    }
    if (*broken != '\0') {
      if (failure.empty()) {
        failure = std::string(broken) + " after:";
        for (std::size_t k = 0; k <= d; ++k) failure += " " + to_string(events[next[k] - 1]);
      }
      continue;  // its longer sequences would only repeat it
    }
    next[d + 1] = 0;
    ++depth;
  }
  return full;
}

TEST(OperatingStateExhaustive, EverySequenceOfEventsKeepsTheRules) {
  const auto events = all_events();
  ASSERT_GE(events.size(), 16U);
  // More would say that to_string(OpEvent) no longer answers "?" past the
  // last event, and the walk would never end (256 to the sixth).
  ASSERT_LE(events.size(), 25U);
  std::uint64_t checked = 0;
  std::uint64_t walked = 0;
  for (const bool link_up : {false, true}) {
    std::string failure;
    Node start{OperatingState(link_up), test::StateOracle(link_up)};
    start.machine.set_pads(start.operator_pad, kSupervisorPad);
    checked += walk(start, events, failure, walked);
    EXPECT_EQ(failure, "") << "from the link " << (link_up ? "up" : "down");
  }
  std::uint64_t per_start = 1;
  for (int k = 0; k < kDepth; ++k) per_start *= events.size();
  EXPECT_EQ(checked, 2 * per_start) << "a sequence was cut short by a failure";
  std::cout << "exhaustive: depth " << kDepth << ", " << events.size() << " events, " << checked
            << " sequences (2 starts), " << walked << " steps walked (no-ops not walked further)\n";
  RecordProperty("sequences", std::to_string(checked));
}

// The oracle's own rules, on steps of a machine that breaks them.
TEST(StateOracle, CatchesEachBrokenRule) {
  using E = OpEvent;
  using S = OpState;
  const Effect none{};
  const Effect changed{true, false};
  const Effect rebased{true, true};
  const auto first_step = [](E event, S before, S after, Effect effect, bool latched) {
    test::StateOracle oracle(true);
    return std::string(oracle.step(event, before, after, effect, latched));
  };
  const auto step = [](test::StateOracle& oracle, E event, S before, S after, Effect effect, bool latched) {
    return std::string(oracle.step(event, before, after, effect, latched));
  };
  // Enabled by anything but a fresh press in not enabled.
  EXPECT_NE(first_step(E::kControllerUp, S::kNoController, S::kEnabled, changed, false), "");
  // Enabled with no controller, or the link down.
  EXPECT_NE(first_step(E::kFreshPress, S::kNotEnabled, S::kEnabled, changed, false), "");
  // The stop button not latched, or left before its reset.
  EXPECT_NE(first_step(E::kOperatorStop, S::kNotEnabled, S::kStopped, changed, false), "");
  EXPECT_NE(first_step(E::kOperatorStop, S::kNotEnabled, S::kNotEnabled, none, true), "");
  // A shutdown that does not end in stopping.
  EXPECT_NE(first_step(E::kShutdown, S::kEnabled, S::kNotEnabled, changed, false), "");
  // The same rules along a run: a link lost and back with no rebase.
  test::StateOracle oracle(true);
  EXPECT_EQ(step(oracle, E::kControllerUp, S::kNoController, S::kNotEnabled, changed, false), "");
  EXPECT_EQ(step(oracle, E::kLinkDown, S::kNotEnabled, S::kNoLink, changed, false), "");
  EXPECT_EQ(step(oracle, E::kLinkUp, S::kNoLink, S::kNotEnabled, changed, false), "");
  EXPECT_NE(step(oracle, E::kFreshPress, S::kNotEnabled, S::kEnabled, changed, false), "");
  // ... and with its rebase, driving again is right; a stop then outlives a resume.
  test::StateOracle good(true);
  EXPECT_EQ(step(good, E::kControllerUp, S::kNoController, S::kNotEnabled, changed, false), "");
  EXPECT_EQ(step(good, E::kLinkDown, S::kNotEnabled, S::kNoLink, changed, false), "");
  EXPECT_EQ(step(good, E::kLinkUp, S::kNoLink, S::kNotEnabled, rebased, false), "");
  EXPECT_EQ(step(good, E::kFreshPress, S::kNotEnabled, S::kEnabled, changed, false), "");
  EXPECT_NE(step(good, E::kRelease, S::kEnabled, S::kEnabled, none, false), "");
  EXPECT_EQ(step(good, E::kOperatorStop, S::kEnabled, S::kStopped, changed, true), "");
  EXPECT_NE(step(good, E::kResume, S::kStopped, S::kNotEnabled, rebased, true), "");
  // A reset from a pad that is not the one that stopped (another took the operator's role): refused.
  test::StateOracle pads(true);
  EXPECT_EQ(step(pads, E::kControllerUp, S::kNoController, S::kNotEnabled, changed, false), "");
  EXPECT_EQ(step(pads, E::kOperatorStop, S::kNotEnabled, S::kStopped, changed, true), "");
  pads.operator_pad(2);
  EXPECT_NE(step(pads, E::kOperatorReset, S::kStopped, S::kNotEnabled, rebased, false), "");
  test::StateOracle back(true);
  EXPECT_EQ(step(back, E::kControllerUp, S::kNoController, S::kNotEnabled, changed, false), "");
  EXPECT_EQ(step(back, E::kOperatorStop, S::kNotEnabled, S::kStopped, changed, true), "");
  back.operator_pad(2);
  back.operator_pad(1);  // the pad that stopped, back
  EXPECT_EQ(step(back, E::kOperatorReset, S::kStopped, S::kNotEnabled, rebased, false), "");
}

}  // namespace
}  // namespace andros::run
