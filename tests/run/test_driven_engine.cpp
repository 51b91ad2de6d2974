// The engine tests' double (support/driven_engine.hpp) held to the run loop
// it stands for: the bridge with the real operating-state machine and guards
// over the same engine, fed the same random controller input. Up to the
// first stop the loop latches (the double has no latch), each tick the
// double allows motion exactly when the loop is enabled, and sends the same
// frame; at that stop, neither moves.
#include <gtest/gtest.h>

#include <cstddef>
#include <random>
#include <string>
#include <vector>

#include "andros/base/clock.hpp"
#include "andros/link/fault_link.hpp"
#include "andros/run/bridge.hpp"
#include "support/engine_steps.hpp"

namespace andros::run {
namespace {

using testing::DrivenEngine;

constexpr std::uint8_t kDrivenCode = 0x3C;

/// The controller's events, played into an input state at the tick's time as a pad's are.
class EventList final : public input::InputSource {
 public:
  explicit EventList(const std::vector<input::InputEvent>& events) : events_(events) {}
  void pump(input::TickInput& input, std::int64_t now_ms) override {
    for (; next_ < events_.size() && events_[next_].t_ms <= now_ms; ++next_) input.apply(events_[next_]);
  }
  [[nodiscard]] bool finished(std::int64_t /*now_ms*/) const override { return false; }

 private:
  const std::vector<input::InputEvent>& events_;
  std::size_t next_ = 0;
};

input::InputEvent button_event(std::int64_t t, const char* name, bool down) {
  input::InputEvent e;
  e.t_ms = t;
  e.type = input::InputEvent::Type::kButton;
  e.key = *input::parse_button_name(name);
  e.value = down ? 1 : 0;
  return e;
}

input::InputEvent axis_event(std::int64_t t, const char* name, int value) {
  input::InputEvent e;
  e.t_ms = t;
  e.type = input::InputEvent::Type::kAxis;
  e.key = *input::parse_axis_name(name);
  e.value = value;
  return e;
}

/// Random controller input for a mapping whose deadman is leftshoulder (or,
/// trigger_deadman, lefttrigger) and whose stop is guide: the deadman most
/// often, the drive stick, the stop now and then, the pad lost and back, and
/// pauses long enough for the enable timeout.
std::vector<input::InputEvent> random_input(std::mt19937& rng, bool trigger_deadman) {
  std::vector<input::InputEvent> out;
  std::int64_t t = 0;
  input::InputEvent connect;
  connect.type = input::InputEvent::Type::kConnect;
  out.push_back(connect);
  const auto pick = [&](int n) { return static_cast<int>(rng() % static_cast<unsigned>(n)); };
  for (int i = 0; i < 150; ++i) {
    t += pick(10) == 0 ? 400 + pick(1200) : pick(60);
    const int what = pick(40);
    if (what < 14) {
      if (trigger_deadman) out.push_back(axis_event(t, "lefttrigger", input::kAxisMin + pick(65536)));
      else out.push_back(button_event(t, "leftshoulder", pick(2) == 0));
    } else if (what < 30) {
      out.push_back(axis_event(t, "lefty", input::kAxisMin + pick(65536)));
    } else if (what < 36) {
      out.push_back(button_event(t, "a", pick(2) == 0));
    } else if (what < 38) {
      input::InputEvent e;
      e.t_ms = t;
      e.type = pick(2) == 0 ? input::InputEvent::Type::kConnect : input::InputEvent::Type::kDisconnect;
      out.push_back(e);
    } else if (what < 39 || pick(4) == 0) {
      out.push_back(button_event(t, "guide", true));
    } else {
      out.push_back(button_event(t, "guide", false));
    }
  }
  return out;
}

/// The loop's reports, one a tick, up to end_ms (its shutdown's left out).
std::vector<TickReport> through_the_loop(const mapping::ValidMapping& mapping,
                                         const std::vector<input::InputEvent>& events, std::int64_t end_ms) {
  mapping::Engine engine(mapping, mapping::EngineOptions{false, kDrivenCode});
  EventList input(events);
  VirtualClock clock;
  link::SinkLink link([](std::int64_t, const protocol::Frame&) {});
  Bridge bridge(clock, input, engine, link, BridgeOptions{.rate_millihertz = 25'000, .rules = {false, kDrivenCode}});
  std::vector<TickReport> out;
  bridge.run([&] { return !out.empty() && out.back().t_ms >= end_ms; },
             [&](const TickReport& r) {
               if (!r.shutting_down()) out.push_back(r);
             });
  return out;
}

/// The double against the loop over one mapping, on `seeds` random inputs: the ticks compared.
int double_against_loop(const std::string& yaml, bool trigger_deadman, int seeds) {
  const auto mapping = testing::mapping_from_yaml(yaml);
  int compared = 0;
  for (int seed = 0; seed < seeds; ++seed) {
    std::mt19937 rng(static_cast<unsigned>(seed));
    const auto events = random_input(rng, trigger_deadman);
    const auto loop = through_the_loop(mapping, events, events.back().t_ms + 200);
    DrivenEngine driven(mapping, mapping::EngineOptions{false, kDrivenCode});
    input::InputState state;
    std::size_t next = 0;
    for (const TickReport& r : loop) {
      state.begin_tick();
      for (; next < events.size() && events[next].t_ms <= r.t_ms; ++next) state.apply(events[next]);
      const auto data = driven.step(state, r.t_ms);
      ++compared;
      if (r.stopped_by) {
        // The loop latched a stop at this tick: neither moves.
        EXPECT_FALSE(driven.enabled()) << "seed " << seed << " at " << r.t_ms;
        EXPECT_EQ(data, r.data) << "seed " << seed << " at " << r.t_ms;
        break;
      }
      EXPECT_EQ(driven.enabled(), r.state == OpState::kEnabled) << "seed " << seed << " at " << r.t_ms;
      EXPECT_EQ(data, r.data) << "seed " << seed << " at " << r.t_ms;
      if (::testing::Test::HasFailure()) return compared;
    }
  }
  return compared;
}

const std::string kDriveBinding = "bindings:\n  - analog: drive\n    axis: lefty\n    invert: true\n";

TEST(DrivenEngine, DecidesAsTheRunLoopOnRandomInputWithAButtonDeadman) {
  const int ticks = double_against_loop(
      "robot: HD1\ndeadman: leftshoulder\nestop: guide\nstop_reset: [back, start]\nenable_timeout: 1\n" + kDriveBinding,
      false, 300);
  EXPECT_GT(ticks, 10'000);  // not cut short by early stops
}

TEST(DrivenEngine, DecidesAsTheRunLoopOnRandomInputWithATriggerDeadmanAndItsPanic) {
  const int ticks = double_against_loop(
      "robot: HD1\ndeadman: lefttrigger\ndeadman_panic: 0.9\nestop: guide\nstop_reset: [back, start]\n"
      "enable_timeout: 1\n" +
          kDriveBinding,
      true, 300);
  EXPECT_GT(ticks, 10'000);
}

}  // namespace
}  // namespace andros::run
