#include <gtest/gtest.h>
#include <unistd.h>

#include <ctime>
#include <filesystem>
#include <fstream>

#include "andros/base/error.hpp"
#include "andros/input/script_input.hpp"
#include "andros/link/fault_link.hpp"
#include "andros/link/pty_pair.hpp"
#include "andros/link/serial_link.hpp"
#include "andros/run/bridge.hpp"
#include "andros/run/loop.hpp"
#include "andros/view/status_board.hpp"
#include "support/frame_doubles.hpp"
#include "support/frame_reader.hpp"

namespace andros::run {
namespace {

/// What the frame gate holds the stand-in's frames to: its code, no weapons.
const FrameRules kRules{false, 0x3C};

/// A stand-in for the mapping engine: drive 200 while motion is allowed,
/// its deadman button a (the loop's guard decides when a press is fresh).
class PressToDrive final : public testing::WithoutStops {
 public:
  PressToDrive() : WithoutStops(input::parse_button_name("a")) {}
  Step step(const input::InputState& /*input*/, std::int64_t /*now_ms*/, bool motion_allowed) override {
    protocol::ControlState s;
    s[protocol::signal_id("drive")] = motion_allowed ? 200 : 128;
    s[protocol::signal_id("pivot")] = 128;
    s[protocol::signal_id("safety")] = motion_allowed ? 1 : 0;
    return Step{protocol::FrameBuilder(0x3C).build(s), {}};
  }
  protocol::DataBytes neutral() const override {
    protocol::ControlState s;
    s[protocol::signal_id("drive")] = 128;
    s[protocol::signal_id("pivot")] = 128;
    return protocol::FrameBuilder(0x3C).build(s);
  }
  void rebase(const input::InputState& /*now*/) override { ++restarts; }
  int restarts = 0;
};

/// An input that never ends.
class Idle final : public input::InputSource {
 public:
  void pump(input::TickInput&, std::int64_t) override {}
  bool finished(std::int64_t) const override { return false; }
};

/// A bridge at 25 Hz on a virtual clock from an idle input to a sink that keeps what it took.
struct OnSink {
  VirtualClock clock;
  Idle input;
  PressToDrive frames;
  std::vector<protocol::Frame> got;
  link::SinkLink link{[this](std::int64_t, const protocol::Frame& f) { got.push_back(f); }};
  Bridge bridge{clock, input, frames, link, BridgeOptions{.rate_millihertz = 25'000, .rules = kRules}};
};

std::string write_script(const std::string& text) {
  const auto path =
      std::filesystem::temp_directory_path() / ("andros-bridge-test-" + std::to_string(getpid()) + ".events");
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
  VirtualClock clock;  // the ticks the script names, however busy the machine (a real clock skips one when late)
  Bridge bridge{clock, input, frames, link, BridgeOptions{.rate_millihertz = 25'000, .rules = kRules}};
};

TEST(Bridge, PlaysAScriptThenEndsOnNeutralFrames) {
  ScriptOnPty on("0 connect pad\n40 button a 1\n120 button a 0\n160 end\n");
  auto& [pty, script, input, frames, link, clock, bridge] = on;
  std::vector<std::int64_t> times;
  int shutdown_ticks = 0;
  bridge.run([] { return false; },
             [&](const TickReport& r) {
               if (r.shutting_down()) ++shutdown_ticks;
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

/// A script through the bridge on a virtual clock into a sink: the reports.
std::vector<TickReport> run_script(const std::string& text, PressToDrive& frames, const RunControl& control = {}) {
  const auto path = write_script(text);
  input::ScriptInput input(path);
  std::filesystem::remove(path);
  VirtualClock clock;
  link::SinkLink link([](std::int64_t, const protocol::Frame&) {});
  Bridge bridge(clock, input, frames, link, BridgeOptions{.rate_millihertz = 25'000, .rules = kRules});
  std::vector<TickReport> ticks;
  bridge.run(control, [&](const TickReport& r) { ticks.push_back(r); });
  return ticks;
}

TEST(Bridge, EachReportCarriesTheStepsStatusTheStateAndTheLinksState) {
  PressToDrive frames;
  const auto ticks = run_script("0 connect pad\n40 button a 1\n120 end\n", frames);
  ASSERT_EQ(ticks.size(), 4u + 3u);
  for (std::size_t i = 0; i < ticks.size(); ++i) {
    const auto& r = ticks[i];
    EXPECT_TRUE(r.connected) << "tick " << i;
    EXPECT_EQ(r.controller, "pad");
    // Shutting down, the status is the last step's.
    const auto enable = i == 0 ? mapping::DeadmanState::kReleased : mapping::DeadmanState::kFreshHold;
    EXPECT_EQ(r.engine.deadman, enable) << "tick " << i;
    const auto state = i == 0 ? OpState::kNotEnabled : i < 4 ? OpState::kEnabled : OpState::kShuttingDown;
    EXPECT_EQ(r.state, state) << "tick " << i;
    EXPECT_EQ(r.data[7], i == 0 || r.shutting_down() ? 128 : 200) << "tick " << i;
    EXPECT_EQ(r.link.counters.sent, i + 1) << "tick " << i;
  }
}

TEST(Bridge, AStopRequestEndsOnNeutralFramesAndTheLinkClosed) {
  OnSink on;
  int ticks = 0;
  int neutral = 0;
  on.bridge.run([&] { return ticks >= 4; },
                [&](const TickReport& r) {
                  ++ticks;
                  if (r.shutting_down() && r.result == link::SendResult::kSent) ++neutral;
                });
  EXPECT_EQ(neutral, 3);
  EXPECT_EQ(on.got.size(), 7u);
  EXPECT_EQ(on.link.state(), link::LinkState::kConnecting);  // closed
  EXPECT_TRUE(on.bridge.shutdown_report().ok());
}

TEST(Bridge, TheTickThatSeesAStopCarriesTheFirstNeutralFrame) {
  OnSink on;
  std::int64_t polls = 0;
  std::vector<TickReport> ticks;
  on.bridge.run([&] { return ++polls > 4; }, [&](const TickReport& r) { ticks.push_back(r); });
  // Polled on ticks 0..4; the stop is seen on tick 4, which is neutral, not left out.
  ASSERT_EQ(ticks.size(), 7u);
  for (std::size_t i = 0; i < ticks.size(); ++i) {
    EXPECT_EQ(ticks[i].tick, static_cast<std::int64_t>(i));
    EXPECT_EQ(ticks[i].t_ms, static_cast<std::int64_t>(i) * 40);
    EXPECT_EQ(ticks[i].shutting_down(), i >= 4) << "tick " << i;
  }
}

TEST(Bridge, ASuspendSendsNeutralFramesThenPausesThenStartsAfresh) {
  OnSink on;
  int polls = 0;
  int paused = 0;
  std::vector<TickReport> ticks;
  std::vector<std::size_t> ticks_at_pause;
  RunControl control;
  control.poll = [&] {
    ++polls;
    if (polls == 3) return Request::kSuspend;  // polled on every tick, the neutral ones too
    if (polls == 8) return Request::kResumed;
    return polls >= 10 ? Request::kShutdown : Request::kNone;
  };
  control.pause = [&](const ShutdownReport&) {
    ++paused;
    ticks_at_pause.push_back(ticks.size());
    EXPECT_EQ(on.link.state(), link::LinkState::kConnecting);  // drained and closed
    on.clock.advance(std::chrono::seconds(5));                 // the process stays stopped a while
  };
  const int restarts_before = on.frames.restarts;
  on.bridge.run(control, [&](const TickReport& r) { ticks.push_back(r); });
  EXPECT_EQ(paused, 1);
  // After the pause, when the link comes back, and on the SIGSTOP-behind-the-back resume.
  EXPECT_EQ(on.frames.restarts - restarts_before, 3);
  // Ticks 0, 1; the suspend seen on tick 2 sends neutral frames on 2, 3, 4; the pause.
  ASSERT_EQ(ticks_at_pause, std::vector<std::size_t>{5});
  for (std::size_t i = 0; i < 5; ++i) EXPECT_EQ(ticks[i].state == OpState::kSuspended, i >= 2) << "tick " << i;
  // Then the run goes on at the first tick still to come, without a burst, and ends on 3 neutral frames.
  ASSERT_EQ(ticks.size(), 5u + 4u + 3u);
  EXPECT_EQ(ticks[5].tick, 4 + 125 + 1);  // 5 s after tick 4: tick 129 is due, 130 the first to come
  EXPECT_EQ(ticks[5].skipped, 0);
  EXPECT_EQ(ticks[5].state, OpState::kNoController);  // the link came back: a new link; no pad here
  EXPECT_TRUE(ticks[9].shutting_down());
  EXPECT_EQ(on.got.size(), 12u);
}

/// An input with no controller that ends at a time.
class EndsAt final : public input::InputSource {
 public:
  explicit EndsAt(std::int64_t end_ms) : end_ms_(end_ms) {}
  void pump(input::TickInput&, std::int64_t) override {}
  bool finished(std::int64_t now_ms) const override { return now_ms >= end_ms_; }

 private:
  std::int64_t end_ms_;
};

// The one assembly every command calls: the parts it is given, run as one
// loop; every observer sees every report, in the order given; the pause
// hears how the suspend's neutral frames went, the caller how the last did.
TEST(RunLoop, RunsTheLoopItsPartsDescribeWithEveryObserverInOrder) {
  VirtualClock clock;
  EndsAt input(400);
  PressToDrive frames;
  std::vector<protocol::Frame> got;
  link::SinkLink link{[&got](std::int64_t, const protocol::Frame& f) { got.push_back(f); }};
  std::vector<std::pair<char, std::int64_t>> seen;
  std::vector<ShutdownReport> pauses;
  int polls = 0;
  LoopParts loop{.clock = clock,
                 .input = input,
                 .frames = frames,
                 .link = link,
                 .options = {.rate_millihertz = 25'000, .rules = kRules},
                 .control = {},
                 .observers = {[&seen](const TickReport& r) { seen.emplace_back('a', r.tick); },
                               [&seen](const TickReport& r) { seen.emplace_back('b', r.tick); }}};
  loop.control.poll = [&polls] { return ++polls == 2 ? Request::kSuspend : Request::kNone; };
  loop.control.pause = [&pauses](const ShutdownReport& neutral) { pauses.push_back(neutral); };
  const ShutdownReport end = run_loop(loop);

  ASSERT_EQ(pauses.size(), 1U);  // after the suspend's 3 neutral frames, drained
  EXPECT_EQ(pauses[0].neutral_sent, 3);
  EXPECT_TRUE(pauses[0].ok());
  EXPECT_EQ(end.neutral_sent, 3);  // the end of the input: 3 more, then closed
  EXPECT_TRUE(end.ok());
  ASSERT_FALSE(seen.empty());
  ASSERT_EQ(seen.size() % 2, 0U);
  for (std::size_t i = 0; i < seen.size(); i += 2) {
    EXPECT_EQ(seen[i].first, 'a') << i;
    EXPECT_EQ(seen[i + 1].first, 'b') << i;
    EXPECT_EQ(seen[i].second, seen[i + 1].second) << i;
  }
  EXPECT_EQ(got.size(), seen.size() / 2);  // every tick offered a frame the sink took (the pause's none)
}

TEST(Bridge, AContinueDuringASuspendsNeutralFramesMeansNoPause) {
  // kill -TSTP; sleep 0.08; kill -CONT: the SIGCONT comes before the process stopped itself.
  OnSink on;
  int polls = 0;
  std::vector<TickReport> ticks;
  RunControl control;
  control.poll = [&] {
    ++polls;
    if (polls == 3) return Request::kSuspend;
    if (polls == 4) return Request::kResumed;
    return polls >= 8 ? Request::kShutdown : Request::kNone;
  };
  control.pause = [](const ShutdownReport&) { FAIL() << "stopped although continued before the stop"; };
  on.bridge.run(control, [&](const TickReport& r) { ticks.push_back(r); });
  // Suspend frames on 2, 3, 4, then on without a gap: not enabled, ticks 5, 6, and the stop's 7, 8, 9.
  ASSERT_EQ(ticks.size(), 10u);
  for (std::size_t i = 0; i < ticks.size(); ++i) EXPECT_EQ(ticks[i].tick, static_cast<std::int64_t>(i));
  EXPECT_EQ(ticks[4].state, OpState::kSuspended);
  EXPECT_EQ(ticks[5].state, OpState::kNoController);
}

TEST(Bridge, AReloadSendsNeutralFramesOnTheOpenLinkWhileTheSettingsAreReadThenStartsAfresh) {
  OnSink on;
  int polls = 0;
  int finish_calls = 0;
  std::vector<TickReport> ticks;
  std::vector<std::string> begun;
  RunControl control;
  control.poll = [&] {
    ++polls;
    if (polls == 3) return Request::kReload;
    if (polls == 4) return Request::kReload;  // a second SIGHUP while it runs: read again, frames afresh
    return polls >= 10 ? Request::kShutdown : Request::kNone;
  };
  control.pause = [](const ShutdownReport&) { FAIL() << "a reload is not a pause"; };
  control.begin_reload = [&](const std::string& mapping) { begun.push_back(mapping); };
  control.finish_reload = [&]() -> std::optional<ReloadOutcome> {
    EXPECT_EQ(on.link.state(), link::LinkState::kUp);  // not closed
    // The reading takes two ticks more than the neutral frames.
    if (++finish_calls < 3) return std::nullopt;
    return ReloadOutcome{true, ""};
  };
  const int restarts_before = on.frames.restarts;
  on.bridge.run(control, [&](const TickReport& r) { ticks.push_back(r); });
  EXPECT_EQ(begun, (std::vector<std::string>{"", ""}));
  EXPECT_EQ(on.frames.restarts - restarts_before, 1);
  // Ticks 0, 1; the reload seen on tick 2, again on 3: neutral frames from 2, at least 3
  // from tick 3 (3, 4, 5), then while it reads (6, 7).
  for (std::size_t i = 0; i < 8; ++i) EXPECT_EQ(ticks[i].reloading(), i >= 2) << "tick " << i;
  EXPECT_EQ(finish_calls, 3);
  ASSERT_EQ(ticks.size(), 8u + 1u + 3u);
  EXPECT_EQ(ticks[8].tick, ticks[7].tick + 1);  // without a gap
  EXPECT_EQ(ticks[8].state, OpState::kNoController);
  for (const auto& r : ticks) EXPECT_EQ(r.data[7], 128);
}

TEST(Bridge, ALinkThatComesBackLandsInNotEnabledUntilAFreshPress) {
  PressToDrive frames;
  // a held from 40; the link lost at 120 and back at 200; released at 280, pressed at 320.
  const auto ticks = run_script(
      "0 connect pad\n40 button a 1\n120 link down\n200 link up\n280 button a 0\n320 button a 1\n400 end\n", frames);
  std::vector<std::pair<std::int64_t, int>> delivered;  // t, drive
  for (const auto& r : ticks) {
    if (r.result == link::SendResult::kSent && !r.shutting_down()) delivered.emplace_back(r.t_ms, r.data[7]);
  }
  const std::vector<std::pair<std::int64_t, int>> want = {{0, 128},   {40, 200},  {80, 200},  {200, 128}, {240, 128},
                                                          {280, 128}, {320, 200}, {360, 200}, {400, 200}};
  EXPECT_EQ(delivered, want);
  EXPECT_EQ(ticks[3].state, OpState::kNoLink);
  EXPECT_EQ(ticks[3].link.detail, "held down by the event script");
  EXPECT_EQ(ticks[5].state, OpState::kNotEnabled);
}

// Issue 33, item 7: "link regained" is said of a link that was lost and came
// back, never of the first link at start-up (a port opened at the first
// frame), nor of the link the loop reopens after a suspend closed it: the
// first cause is then the start-up, or the resume.
TEST(Bridge, OnlyALinkLostAndBackIsALinkRegained) {
  ScriptOnPty on("0 connect pad\n80 end\n");
  std::vector<TickReport> started;
  on.bridge.run([] { return false; }, [&](const TickReport& r) { started.push_back(r); });
  ASSERT_FALSE(started.empty());
  EXPECT_EQ(started[0].state, OpState::kNotEnabled);
  EXPECT_EQ(view::state_text(started[0]), "press the deadman to enable");

  // As the status board says it: the first cause followed from the reports' transitions.
  const auto first_not_enabled_from = [](const std::vector<TickReport>& ticks, std::int64_t t_ms) {
    view::FirstCause cause;
    for (const auto& r : ticks) {
      cause.follow(r.transitions);
      if (r.t_ms >= t_ms && r.state == OpState::kNotEnabled) return view::state_text(r, cause.transition());
    }
    return std::string("(never not enabled)");
  };
  PressToDrive frames;
  const auto lost = run_script("0 connect pad\n40 link down\n120 link up\n200 end\n", frames);
  EXPECT_EQ(first_not_enabled_from(lost, 120), "link regained: press the deadman afresh");
  const auto resumed = run_script("0 connect pad\n40 suspend\n200 resume\n320 end\n", frames);
  EXPECT_EQ(first_not_enabled_from(resumed, 200), "resumed: press the deadman afresh");
}

TEST(Bridge, APortTakenAndRegainedIsANewLink) {
  PressToDrive frames;
  const auto ticks = run_script("0 connect pad\n40 button a 1\n80 link taken\n160 link up\n240 end\n", frames);
  for (const auto& r : ticks) {
    if (r.t_ms >= 80 && !r.shutting_down()) {
      EXPECT_EQ(r.data[7], 128) << r.t_ms;
      EXPECT_NE(r.state, OpState::kEnabled) << r.t_ms;
    }
  }
  EXPECT_EQ(ticks[2].link.detail, "taken by another program (event script)");
}

TEST(Bridge, AScriptSuspendSendsNeutralFramesClosesTheLinkAndSendsNothingUntilResumed) {
  PressToDrive frames;
  const auto ticks = run_script("0 connect pad\n40 button a 1\n80 suspend\n400 resume\n600 end\n", frames);
  std::vector<std::int64_t> sent_at;
  for (const auto& r : ticks) {
    if (r.delivered()) sent_at.push_back(r.t_ms);
    if (r.t_ms >= 80 && !r.shutting_down()) {
      EXPECT_EQ(r.data[7], 128) << r.t_ms;
    }
  }
  // 0, 40; neutral 80, 120, 160; nothing until 400; then on to the end and its neutral frames.
  std::vector<std::int64_t> want = {0, 40, 80, 120, 160};
  for (std::int64_t t = 400; t <= 600; t += 40) want.push_back(t);
  for (std::int64_t t = 640; t <= 720; t += 40) want.push_back(t);
  EXPECT_EQ(sent_at, want);
}

TEST(Bridge, KeepsTicksWhileTheLinkIsDownAndSaysNoLink) {
  VirtualClock clock;
  Idle input;
  PressToDrive frames;
  link::SerialLink link("/nonexistent/andros-port", 9600);
  Bridge bridge(clock, input, frames, link, BridgeOptions{.rate_millihertz = 50'000, .rules = kRules});
  int ticks = 0;
  bridge.run([&] { return ticks >= 5; },
             [&](const TickReport& r) {
               ++ticks;
               if (!r.shutting_down()) {
                 EXPECT_EQ(r.state, OpState::kNoLink);
               }
             });
  EXPECT_EQ(ticks, 5 + 3 + 5);  // frames computed; the shutdown's tries bounded
  EXPECT_EQ(link.counters().sent, 0u);
}

/// Stalls once, at tick 2, for 130 ms (more than three periods at 25 Hz).
class StallOnce final : public testing::WithoutStops {
 public:
  explicit StallOnce(VirtualClock& clock) : WithoutStops(input::parse_button_name("a")), clock_(clock) {}
  Step step(const input::InputState& input, std::int64_t now_ms, bool motion_allowed) override {
    if (now_ms == 80) clock_.advance(std::chrono::milliseconds(130));
    return inner_.step(input, now_ms, motion_allowed);
  }
  protocol::DataBytes neutral() const override { return inner_.neutral(); }
  void rebase(const input::InputState& /*now*/) override {}

 private:
  VirtualClock& clock_;
  PressToDrive inner_;
};

TEST(Bridge, AfterAStallSkipsMissedTicksInsteadOfBursting) {
  VirtualClock clock;
  Idle input;
  StallOnce frames(clock);
  link::SinkLink link([](std::int64_t, const protocol::Frame&) {});
  Bridge bridge(clock, input, frames, link, BridgeOptions{.rate_millihertz = 25'000, .rules = kRules});
  std::vector<TickReport> ticks;
  bridge.run([&] { return ticks.size() >= 6; },
             [&](const TickReport& r) {
               if (!r.shutting_down()) ticks.push_back(r);
             });
  ASSERT_EQ(ticks.size(), 6u);
  EXPECT_EQ(ticks[2].tick, 2);
  // 130 ms after tick 2's time (80 ms) ticks 3..5 (120, 160, 200) are past:
  // the next frame is the latest tick due, once, with the others skipped.
  EXPECT_EQ(ticks[3].tick, 5);
  EXPECT_EQ(ticks[3].skipped, 2);
  EXPECT_EQ(ticks[3].t_ms, 200);
  EXPECT_EQ(ticks[4].tick, 6);
  EXPECT_EQ(ticks[4].skipped, 0);
}

TEST(Bridge, ReportsWhetherTheNeutralFramesReachedTheLink) {
  OnSink on;  // the frames go out
  int ticks = 0;
  on.bridge.run([&] { return ticks >= 2; }, [&](const TickReport&) { ++ticks; });
  EXPECT_TRUE(on.bridge.shutdown_report().ok());
  EXPECT_EQ(on.bridge.shutdown_report().neutral_sent, 3);

  // A device gone: nothing could be handed over, and the caller is told.
  link::SerialLink gone("/nonexistent/andros-port", 9600);
  Bridge lost(on.clock, on.input, on.frames, gone, BridgeOptions{.rate_millihertz = 50'000, .rules = kRules});
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
