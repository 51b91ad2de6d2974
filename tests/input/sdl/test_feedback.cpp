// Rumble and light through the real SDL path: the virtual pad's Rumble and
// SetLED callbacks record what each feedback event plays, and that nothing
// else plays anything.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "andros/input/sdl_input.hpp"
#include "andros/mapping/engine.hpp"
#include "andros/mapping/loader.hpp"
#include "andros/run/feedback.hpp"
#include "support/engine_steps.hpp"
#include "support/temp_dir.hpp"
#include "support/virtual_device.hpp"

namespace andros::input {
namespace {

using test::FeedbackLog;
using test::VirtualDevice;
using E = mapping::FeedbackEvent;
using Rgb = std::array<Uint8, 3>;

constexpr int kDeadman = SDL_CONTROLLER_BUTTON_LEFTSHOULDER;

/// The rumble SDL is asked for, motors at these strengths.
std::array<Uint16, 2> motors(const FeedbackPattern& p) {
  return {static_cast<Uint16>(std::lround(p.low * 0xFFFF)), static_cast<Uint16>(std::lround(p.high * 0xFFFF))};
}

/// The rumbles that started something (SDL's own stops, 0 0, left out).
std::vector<std::array<Uint16, 2>> started(const FeedbackLog& log) {
  std::vector<std::array<Uint16, 2>> out;
  for (const auto& r : log.rumbles) {
    if (r[0] != 0 || r[1] != 0) out.push_back(r);
  }
  return out;
}

/// The log shows this pattern and nothing else.
void expect_played(const FeedbackLog& log, const FeedbackPattern& p, const char* what) {
  const auto rumbles = started(log);
  ASSERT_FALSE(rumbles.empty()) << what;
  for (const auto& r : rumbles) EXPECT_EQ(r, motors(p)) << what;
  ASSERT_TRUE(p.led.has_value());
  EXPECT_EQ(log.leds, std::vector<Rgb>{*p.led}) << what;
}

class SdlFeedbackTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { test::use_dummy_video(); }
  SdlSession session_;
  FeedbackLog log_;
};

TEST_F(SdlFeedbackTest, APatternSetsTheLightAndRunsTheMotors) {
  auto pad = VirtualDevice::pad("Rumble Pad", 1, &log_);
  SdlInput input(SdlInputOptions{});
  input.poll(0);
  const FeedbackPattern p{0.25, 1.0, 50, 1, Rgb{10, 20, 30}};
  input.feedback(p);
  EXPECT_EQ(log_.rumbles, (std::vector<std::array<Uint16, 2>>{{16384, 65535}}));
  EXPECT_EQ(log_.leds, (std::vector<Rgb>{Rgb{10, 20, 30}}));
  // No light asked for, no motors: neither is touched.
  log_ = {};
  input.feedback(FeedbackPattern{0.0, 0.0, 50, 1, std::nullopt});
  EXPECT_TRUE(started(log_).empty());
  EXPECT_TRUE(log_.leds.empty());
}

TEST_F(SdlFeedbackTest, PulsesStartFromThePollsTwoPulseLengthsApart) {
  auto pad = VirtualDevice::pad("Rumble Pad", 1, &log_);
  SdlInput input(SdlInputOptions{});
  input.poll(0);
  input.feedback(FeedbackPattern{1.0, 0.0, 20, 3, std::nullopt});  // pulses at 0, 40, 80 ms
  const auto pulses = [&] { return started(log_).size(); };
  EXPECT_EQ(pulses(), 1U);
  // SDL ends each pulse on its own clock; wait that out so that the next,
  // equal, request is seen as a new one.
  const auto after_pulse = [] { std::this_thread::sleep_for(std::chrono::milliseconds(30)); };
  after_pulse();
  input.poll(39);
  EXPECT_EQ(pulses(), 1U);
  input.poll(40);
  EXPECT_EQ(pulses(), 2U);
  after_pulse();
  input.poll(80);
  EXPECT_EQ(pulses(), 3U);
  after_pulse();
  input.poll(120);
  input.poll(1000);
  EXPECT_EQ(pulses(), 3U);
}

TEST_F(SdlFeedbackTest, WithoutAControllerNothingHappens) {
  SdlInput input(SdlInputOptions{});
  input.poll(0);
  input.feedback(mapping::default_feedback_pattern(E::kEnabled));  // must not fail
  auto pad = VirtualDevice::pad("Rumble Pad", 1, &log_);
  input.poll(40);  // connects: nothing was left pending
  EXPECT_TRUE(started(log_).empty());
  EXPECT_TRUE(log_.leds.empty());
}

/// The run loop's part, on the real SDL path: pump, engine, feedback.
class FeedbackRun {
 public:
  explicit FeedbackRun(const mapping::FeedbackTable& table)
      : engine_(mapping::load_mapping(ANDROS_TEST_DATA_DIR "/mappings/core.yaml"), {}),
        input_(SdlInputOptions{}),
        notifier_(table, input_) {}

  std::optional<E> tick(bool link_up = true) {
    t_ += 40;
    input_.pump(tick_, t_);
    engine_.step(state_, t_);
    // The loop's state is enabled when the engine is and the link is up (no
    // interruption here), and its machine publishes the steps between.
    const bool enabled = engine_.status().deadman == mapping::DeadmanState::kFreshHold && link_up;
    const auto state = [](bool on) { return on ? run::OpState::kEnabled : run::OpState::kNotEnabled; };
    std::vector<run::ReportedTransition> steps;
    if (link_up_ && !link_up) {
      steps.push_back({{.from = state(enabled_),
                        .event = run::OpEvent::kLinkDown,
                        .to = run::OpState::kNoLink,
                        .who = run::Who::kLink},
                       {}});
    } else if (enabled != enabled_) {
      steps.push_back({{.from = state(enabled_),
                        .event = enabled ? run::OpEvent::kFreshPress : run::OpEvent::kRelease,
                        .to = state(enabled),
                        .who = run::Who::kOperator},
                       {}});
    }
    link_up_ = link_up;
    enabled_ = enabled;
    return notifier_.observe(run::FeedbackStatus{state_.connected(), engine_.status().deadman, enabled}, steps);
  }

 private:
  testing::DrivenEngine engine_;
  SdlInput input_;
  run::FeedbackNotifier notifier_;
  TickInput tick_;
  InputState& state_ = tick_.state();
  std::int64_t t_ = 0;
  bool link_up_ = true;
  bool enabled_ = false;
};

TEST_F(SdlFeedbackTest, EachEventPlaysItsPatternAndNothingElsePlaysAnything) {
  const auto table = mapping::default_feedback();
  auto pad = std::make_optional(VirtualDevice::pad("Rumble Pad", 1, &log_));
  pad->button(kDeadman, true);
  FeedbackRun run(table);
  // Held at connect: refused (the connect itself ranks below).
  EXPECT_EQ(run.tick(), E::kDeadmanRefused);
  for (int i = 0; i < 10; ++i) EXPECT_EQ(run.tick(), std::nullopt);
  expect_played(log_, *table[E::kDeadmanRefused], "deadman refused");

  const auto step = [&](const char* what, E event, auto&& act, bool link_up = true) {
    log_ = {};
    act();
    EXPECT_EQ(run.tick(link_up), event) << what;
    for (int i = 0; i < 25; ++i) EXPECT_EQ(run.tick(link_up), std::nullopt) << what;  // a second: nothing more
    expect_played(log_, *table[event], what);
  };
  log_ = {};
  pad->button(kDeadman, false);
  EXPECT_EQ(run.tick(), std::nullopt);
  step("enabled", E::kEnabled, [&] { pad->button(kDeadman, true); });

  log_ = {};
  for (int v = -32768; v < 32767; v += 1000) {  // a steady drive, stick swept through
    pad->axis(SDL_CONTROLLER_AXIS_LEFTY, v);
    EXPECT_EQ(run.tick(), std::nullopt);
  }
  EXPECT_TRUE(started(log_).empty());
  EXPECT_TRUE(log_.leds.empty());

  step("disabled", E::kDisabled, [&] { pad->button(kDeadman, false); });
  step(
      "link lost", E::kLinkLost, [] {}, false);
  EXPECT_EQ(run.tick(true), std::nullopt);  // the link back: nothing
  log_ = {};
  pad.reset();  // unplugged: the lost pad cannot be told
  EXPECT_EQ(run.tick(), std::nullopt);
  step("controller back", E::kControllerBack, [&] { pad.emplace(VirtualDevice::pad("Rumble Pad", 1, &log_)); });
}

TEST_F(SdlFeedbackTest, FeedbackOffPlaysNothing) {
  testing::TempDir dir;
  const auto off = mapping::load_mapping(
      dir.write("off.yaml", "robot: HD1\nextends: " ANDROS_TEST_DATA_DIR "/mappings/core.yaml\nfeedback: off\n"));
  auto pad = std::make_optional(VirtualDevice::pad("Rumble Pad", 1, &log_));
  pad->button(kDeadman, true);
  FeedbackRun run(off->feedback);
  for (int i = 0; i < 5; ++i) run.tick();
  pad->button(kDeadman, false);
  run.tick();
  pad->button(kDeadman, true);
  run.tick();
  pad->axis(SDL_CONTROLLER_AXIS_LEFTY, -20000);
  run.tick(false);
  pad->button(kDeadman, false);
  run.tick();
  pad.reset();
  run.tick();
  pad.emplace(VirtualDevice::pad("Rumble Pad", 1, &log_));
  EXPECT_EQ(run.tick(), std::nullopt);
  EXPECT_TRUE(log_.rumbles.empty());
  EXPECT_TRUE(log_.leds.empty());
}

}  // namespace
}  // namespace andros::input
