#include <gtest/gtest.h>
#include <unistd.h>

#include <ctime>
#include <filesystem>
#include <fstream>

#include "andros/base/error.hpp"
#include "andros/input/script_input.hpp"
#include "andros/link/pty_pair.hpp"
#include "andros/link/serial_link.hpp"
#include "andros/run/bridge.hpp"
#include "support/frame_reader.hpp"

namespace andros::run {
namespace {

/// A stand-in for the mapping engine: drive 200 while button a is held.
class PressToDrive final : public FrameSource {
 public:
  Step step(const input::InputState& input, std::int64_t) override {
    const bool enabled = input.connected() && input.button(*input::parse_button_name("a")).down;
    protocol::ControlState s;
    s[protocol::signal_id("drive")] = enabled ? 200 : 128;
    s[protocol::signal_id("pivot")] = 128;
    s[protocol::signal_id("safety")] = enabled ? 1 : 0;
    mapping::EngineStatus status;
    status.enable = enabled ? mapping::EnableState::kEnabled : mapping::EnableState::kDeadmanReleased;
    return Step{protocol::FrameBuilder(0x3C).build(s), status};
  }
  protocol::DataBytes neutral() const override {
    protocol::ControlState s;
    s[protocol::signal_id("drive")] = 128;
    s[protocol::signal_id("pivot")] = 128;
    return protocol::FrameBuilder(0x3C).build(s);
  }
  void restart() override { ++restarts; }
  int restarts = 0;
};

/// An input that never ends.
class Idle final : public input::InputSource {
 public:
  void pump(input::InputState&, std::int64_t) override {}
  bool finished(std::int64_t) const override { return false; }
};

/// A bridge at 25 Hz from an idle input to a pty, the far end read by the test.
struct OnPty {
  link::PtyPair pty = link::open_pty_pair();
  Idle input;
  PressToDrive frames;
  link::SerialLink link{pty.path, 9600};
  Bridge bridge{input, frames, link, BridgeOptions{.rate_millihertz = 25'000}};
};

std::string write_script(const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("andros-bridge-test-" + std::to_string(getpid()) + ".events");
  std::ofstream(path) << text;
  return path;
}

/// A bridge at 25 Hz playing an event script to a pty.
struct ScriptOnPty {
  explicit ScriptOnPty(const std::string& text) : script(write_script(text)), input(script) {}
  ~ScriptOnPty() { std::filesystem::remove(script); }
  ScriptOnPty(const ScriptOnPty&) = delete;
  ScriptOnPty& operator=(const ScriptOnPty&) = delete;

  link::PtyPair pty = link::open_pty_pair();
  std::string script;
  input::ScriptInput input;
  PressToDrive frames;
  link::SerialLink link{pty.path, 9600};
  Bridge bridge{input, frames, link, BridgeOptions{.rate_millihertz = 25'000}};
};

TEST(Bridge, PlaysAScriptThenEndsOnNeutralFrames) {
  ScriptOnPty on("0 connect pad\n40 button a 1\n120 button a 0\n160 end\n");
  auto& [pty, script, input, frames, link, bridge] = on;
  std::vector<std::int64_t> times;
  int shutdown_ticks = 0;
  bridge.run([] { return false; },
             [&](const TickReport& r) {
               if (r.shutting_down) ++shutdown_ticks;
               else times.push_back(r.t_ms);
             });
  EXPECT_EQ(times, (std::vector<std::int64_t>{0, 40, 80, 120, 160}));
  EXPECT_EQ(shutdown_ticks, 3);

  test::FrameReader reader(pty.master.get());
  const auto got = reader.next(8, 2000);
  ASSERT_EQ(got.size(), 8u);
  const std::vector<int> drive = {128, 200, 200, 128, 128, 128, 128, 128};
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_TRUE(got[i].valid);
    EXPECT_EQ(got[i].data[7], drive[i]) << "frame " << i;
    EXPECT_EQ(got[i].data[11], 0x3C);
  }
  EXPECT_EQ(link.state(), link::LinkState::kConnecting);  // closed
}

TEST(Bridge, EachReportCarriesTheStepsStatusAndTheLinksState) {
  ScriptOnPty on("0 connect pad\n40 button a 1\n120 end\n");
  std::vector<TickReport> ticks;
  on.bridge.run([] { return false; }, [&](const TickReport& r) { ticks.push_back(r); });
  ASSERT_EQ(ticks.size(), 4u + 3u);
  for (std::size_t i = 0; i < ticks.size(); ++i) {
    const auto& r = ticks[i];
    EXPECT_TRUE(r.connected) << "tick " << i;
    EXPECT_EQ(r.controller, "pad");
    // Shutting down, the status is the last step's.
    const auto enable = i == 0 ? mapping::EnableState::kDeadmanReleased : mapping::EnableState::kEnabled;
    EXPECT_EQ(r.engine.enable, enable) << "tick " << i;
    EXPECT_EQ(r.data[7], i == 0 || r.shutting_down ? 128 : 200) << "tick " << i;
    // Taken after this tick's send.
    const auto& c = r.link.counters;
    EXPECT_EQ(c.sent + c.busy + c.down, i + 1) << "tick " << i;
    if (r.result == link::SendResult::kSent) {
      EXPECT_EQ(r.link.state, link::LinkState::kUp);
    }
  }
}

TEST(Bridge, AStopRequestEndsOnNeutralFrames) {
  OnPty on;
  auto& [pty, input, frames, link, bridge] = on;
  int ticks = 0;
  int neutral = 0;
  bridge.run([&] { return ticks >= 4; },
             [&](const TickReport& r) {
               ++ticks;
               if (r.shutting_down && r.result == link::SendResult::kSent) ++neutral;
             });
  EXPECT_EQ(neutral, 3);
  test::FrameReader reader(pty.master.get());
  EXPECT_EQ(reader.next(7, 2000).size(), 7u);
}

TEST(Bridge, TheTickThatSeesAStopCarriesTheFirstNeutralFrame) {
  OnPty on;
  auto& [pty, input, frames, link, bridge] = on;
  std::int64_t polls = 0;
  std::vector<TickReport> ticks;
  bridge.run([&] { return ++polls > 4; }, [&](const TickReport& r) { ticks.push_back(r); });
  // Polled before ticks 0..4; the stop is seen on tick 4, which is neutral, not left out.
  ASSERT_EQ(ticks.size(), 7u);
  for (std::size_t i = 0; i < ticks.size(); ++i) {
    EXPECT_EQ(ticks[i].tick, static_cast<std::int64_t>(i));
    EXPECT_EQ(ticks[i].shutting_down, i >= 4) << "tick " << i;
  }
}

TEST(Bridge, ASuspendSendsNeutralFramesThenPausesThenStartsAfresh) {
  OnPty on;
  auto& [pty, input, frames, link, bridge] = on;
  int polls = 0;
  int paused = 0;
  std::vector<TickReport> ticks;
  std::vector<std::size_t> ticks_at_pause;
  const RunControl control{
      [&] {
        ++polls;
        if (polls == 3) return Request::kSuspend;
        if (polls == 6) return Request::kResumed;
        return polls >= 8 ? Request::kStop : Request::kNone;
      },
      [&] {
        ++paused;
        ticks_at_pause.push_back(ticks.size());
        EXPECT_EQ(link.state(), link::LinkState::kConnecting);  // drained and closed
      }};
  bridge.run(control, [&](const TickReport& r) { ticks.push_back(r); });
  EXPECT_EQ(paused, 1);
  EXPECT_EQ(frames.restarts, 2);  // after the pause, and on the resume
  // Ticks 0, 1; the suspend seen on tick 2 sends neutral frames on 2, 3, 4; the pause.
  ASSERT_EQ(ticks_at_pause, std::vector<std::size_t>{5});
  for (std::size_t i = 0; i < 5; ++i) EXPECT_EQ(ticks[i].shutting_down, i >= 2) << "tick " << i;
  // Then the run goes on after the neutral ticks, without a burst, and ends on 3 neutral frames.
  ASSERT_EQ(ticks.size(), 5u + 4u + 3u);
  EXPECT_GT(ticks[5].tick, ticks[4].tick);
  EXPECT_EQ(ticks[5].skipped, 0);
  EXPECT_FALSE(ticks[5].shutting_down);
  EXPECT_TRUE(ticks[9].shutting_down);
  test::FrameReader reader(pty.master.get());
  EXPECT_EQ(reader.next(12, 2000).size(), 12u);
}

TEST(Bridge, AReloadSendsNeutralFramesOnTheOpenLinkThenStartsAfresh) {
  OnPty on;
  auto& [pty, input, frames, link, bridge] = on;
  int polls = 0;
  std::vector<TickReport> ticks;
  std::vector<std::size_t> ticks_at_reload;
  const RunControl control{[&] {
                                 ++polls;
                                 if (polls == 3) return Request::kReload;
                                 return polls >= 6 ? Request::kStop : Request::kNone;
                               },
                               [] { FAIL() << "a reload is not a pause"; },
                               [&] {
                                 ticks_at_reload.push_back(ticks.size());
                                 EXPECT_EQ(link.state(), link::LinkState::kUp);  // not closed
                                 EXPECT_EQ(frames.restarts, 0);                // restarted after the swap
                               }};
  bridge.run(control, [&](const TickReport& r) { ticks.push_back(r); });
  EXPECT_EQ(frames.restarts, 1);
  // Ticks 0, 1; the reload seen on tick 2 sends neutral frames on 2, 3, 4; the swap.
  ASSERT_EQ(ticks_at_reload, std::vector<std::size_t>{5});
  for (std::size_t i = 0; i < 5; ++i) EXPECT_EQ(ticks[i].reloading, i >= 2) << "tick " << i;
  for (std::size_t i = 0; i < 5; ++i) EXPECT_FALSE(ticks[i].shutting_down) << "tick " << i;
  // Then on, without a gap or a burst: 2 ticks, and the stop's 3 neutral frames.
  ASSERT_EQ(ticks.size(), 5u + 2u + 3u);
  EXPECT_EQ(ticks[5].tick, ticks[4].tick + 1);
  EXPECT_EQ(link.counters().losses, 0u);
  test::FrameReader reader(pty.master.get());
  EXPECT_EQ(reader.next(10, 2000).size(), 10u);
}

TEST(Bridge, KeepsTicksWhileTheLinkIsDown) {
  Idle input;
  PressToDrive frames;
  link::SerialLink link("/nonexistent/andros-port", 9600);
  Bridge bridge(input, frames, link, BridgeOptions{.rate_millihertz = 50'000});
  int ticks = 0;
  bridge.run([&] { return ticks >= 5; }, [&](const TickReport&) { ++ticks; });
  EXPECT_EQ(ticks, 5 + 3 + 5);  // frames computed; the shutdown's tries bounded
  EXPECT_EQ(link.counters().sent, 0u);
}

/// Stalls once, at tick 2, for 130 ms (more than three periods at 25 Hz).
class StallOnce final : public FrameSource {
 public:
  Step step(const input::InputState& input, std::int64_t now_ms) override {
    if (now_ms == 80) {
      const timespec stall{0, 130'000'000};
      nanosleep(&stall, nullptr);
    }
    return inner_.step(input, now_ms);
  }
  protocol::DataBytes neutral() const override { return inner_.neutral(); }
  void restart() override {}

 private:
  PressToDrive inner_;
};

TEST(Bridge, AfterAStallSkipsMissedTicksInsteadOfBursting) {
  auto pty = link::open_pty_pair();
  Idle input;
  StallOnce frames;
  link::SerialLink link(pty.path, 9600);
  Bridge bridge(input, frames, link, BridgeOptions{.rate_millihertz = 25'000});
  std::vector<TickReport> ticks;
  bridge.run([&] { return ticks.size() >= 6; }, [&](const TickReport& r) {
    if (!r.shutting_down) ticks.push_back(r);
  });
  ASSERT_GE(ticks.size(), 4u);
  EXPECT_EQ(ticks[2].tick, 2);
  // 130 ms after tick 2's time (80 ms) ticks 3 and 4 (120, 160) are past:
  // the next frame is the latest tick due, once, with the others skipped.
  EXPECT_GE(ticks[3].tick, 5);
  EXPECT_EQ(ticks[3].skipped, ticks[3].tick - 3);
  EXPECT_EQ(ticks[3].t_ms, ticks[3].tick * 40);
  for (std::size_t i = 4; i < ticks.size(); ++i) EXPECT_EQ(ticks[i].skipped, ticks[i].tick - ticks[i - 1].tick - 1);
}

TEST(Bridge, ReportsWhetherTheNeutralFramesReachedTheLink) {
  OnPty on;  // a pty: the frames go out
  auto& [pty, input, frames, link, delivered] = on;
  int ticks = 0;
  delivered.run([&] { return ticks >= 2; }, [&](const TickReport&) { ++ticks; });
  EXPECT_TRUE(delivered.shutdown_report().ok());
  EXPECT_EQ(delivered.shutdown_report().neutral_sent, 3);

  // A device gone: nothing could be handed over, and the caller is told.
  link::SerialLink gone("/nonexistent/andros-port", 9600);
  Bridge lost(input, frames, gone, BridgeOptions{.rate_millihertz = 50'000});
  ticks = 0;
  lost.run([&] { return ticks >= 2; }, [&](const TickReport&) { ++ticks; });
  EXPECT_FALSE(lost.shutdown_report().ok());
  EXPECT_EQ(lost.shutdown_report().neutral_sent, 0);
  EXPECT_EQ(lost.shutdown_report().neutral_wanted, 3);
}

TEST(ScriptInput, ABadLineStopsBeforeTheFirstFrame) {
  const auto script = write_script("0 connect\n10 button nosuchbutton 1\n");
  try {
    input::ScriptInput input(script);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.pos().line, 2);
  }
  std::filesystem::remove(script);
}

}  // namespace
}  // namespace andros::run
