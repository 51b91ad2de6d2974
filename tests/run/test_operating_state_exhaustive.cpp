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
/// as its prefix. Fixed by the build, never chosen by speed: 20 events to
/// depth 8 is 25,600,000,000 sequences per start, of which the walk steps 92
/// million nodes (a no-op is not walked further: walk()): 4.1 s of CPU (-O2)
/// on the 2-core machine; depth 9 is some 20 times that. Under the sanitizers
/// (support/sweep.hpp) depth 7: every sequence one event shorter, at about a
/// tenth of the steps.
constexpr int kDepth = test::kSanitizedSweep ? 7 : 8;

/// Every event of the enum, read off it, so that an event added is searched too.
std::vector<OpEvent> all_events() {
  std::vector<OpEvent> out;
  for (int i = 0; i <= UINT8_MAX; ++i) {
    const auto event = static_cast<OpEvent>(i);
    if (to_string(event) == "?") break;
    out.push_back(event);
  }
  return out;
}

struct Node {
  OperatingState machine;
  test::StateOracle oracle;

  bool operator==(const Node&) const = default;
};

/// Walks every sequence from `start`, depth first; returns the number of
/// sequences of kDepth events checked, and the first failure in `failure`.
/// An event that leaves both the machine and the oracle as they were (a
/// no-op, judged sound) is not walked further: every sequence after it is
/// one after its parent, which the walk checks anyway (the two are values,
/// and each step a function of them and the event). Its sequences are
/// counted as checked; `walked` counts the nodes actually stepped.
std::uint64_t walk(const Node& start, const std::vector<OpEvent>& events, std::string& failure, std::uint64_t& walked) {
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
    const OpEvent event = events[next[d]++];
    Node& node = path[d + 1];
    node = path[d];
    const OpState before = node.machine.state();
    const Effect effect = node.machine.on(event);
    const char* broken = node.oracle.step(event, before, node.machine.state(), effect, node.machine.stop_latched());
    ++walked;
    if (*broken == '\0' && node == path[d]) {
      full += below[d + 1];  // a no-op: what follows it follows its parent too
      continue;
    }
    if (*broken != '\0') {
      if (failure.empty()) {
        failure = std::string(broken) + " after:";
        for (std::size_t k = 0; k <= d; ++k) failure += std::string(" ") + std::string(to_string(events[next[k] - 1]));
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
  ASSERT_LE(events.size(), 24U);
  std::uint64_t checked = 0;
  std::uint64_t walked = 0;
  for (const bool link_up : {false, true}) {
    std::string failure;
    checked += walk(Node{OperatingState(link_up), test::StateOracle(link_up)}, events, failure, walked);
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
}

}  // namespace
}  // namespace andros::run
