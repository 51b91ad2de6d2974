// `record`'s engine, in process: a virtual pad in, an event script out.
#include <gtest/gtest.h>

#include <regex>

#include <sstream>
#include <thread>

#include "andros/base/clock.hpp"
#include "andros/base/shutdown_request.hpp"
#include "andros/input/events.hpp"
#include "andros/input/script_recorder.hpp"
#include "support/virtual_device.hpp"

namespace andros::input {
namespace {

using test::VirtualDevice;
using T = InputEvent::Type;

TEST(ScriptRecorder, WritesAScriptThatParsesBackWithConnectPressesDisconnectAndEnd) {
  test::use_dummy_video();
  const SdlSession session;
  auto pad = std::make_unique<VirtualDevice>(VirtualDevice::pad("Test Pad"));
  pad->button(SDL_CONTROLLER_BUTTON_LEFTSHOULDER, true);  // held at connect
  SdlInput input(SdlInputOptions{});
  std::ostringstream out;
  RecordOptions options;
  options.period_ms = 2;
  options.header = "test recording\ncontroller: Test Pad";
  // Between ticks, the "operator": the callback runs on the recorder's thread.
  // Counted per call: on a busy machine the recorder skips tick numbers.
  int step = 0;
  const auto script = [&](const RecordStatus&) {
    switch (++step) {
      case 2: pad->button(SDL_CONTROLLER_BUTTON_A, true); break;
      case 3: pad->axis(SDL_CONTROLLER_AXIS_LEFTY, -32768); break;
      case 4: pad->button(SDL_CONTROLLER_BUTTON_A, false); break;
      case 5: pad->unplug(); break;
      default: break;
    }
    return step < 7;
  };
  ShutdownRequest stop;
  const auto written = record_script(input, out, options, stop, script).events;

  const std::string text = out.str();
  EXPECT_EQ(text.rfind("# test recording\n# controller: Test Pad\n", 0), 0U) << text;
  const auto events = parse_event_script(text, "recorded");
  ASSERT_EQ(events.size(), static_cast<std::size_t>(written) + 1) << text;
  // The connect names its physical pad (docs/event-scripts.md): SDL's virtual device has a GUID, no path or serial.
  EXPECT_TRUE(std::regex_match(events[0].device, std::regex("guid=[0-9a-f]{32}"))) << events[0].device;
  EXPECT_EQ(format_event(events[0]), "0       connect     {" + events[0].device + "} Test Pad");
  std::vector<std::string> lines;
  for (auto e : events) {
    e.device.clear();
    auto line = format_event(e);
    lines.push_back(line.substr(line.find_first_not_of("0123456789 ")));
  }
  const std::vector<std::string> expected = {"connect     Test Pad",
                                             "button      leftshoulder 1",
                                             "button      a 1",
                                             "axis        lefty -32768",
                                             "button      a 0",
                                             "disconnect",
                                             "end"};
  EXPECT_EQ(lines, expected) << text;
  EXPECT_EQ(events[0].t_ms, 0);
  EXPECT_EQ(events[1].t_ms, 0);  // held at connect: the connect's time
  EXPECT_GT(events[2].t_ms, 0);
  for (std::size_t i = 1; i < events.size(); ++i) EXPECT_GE(events[i].t_ms, events[i - 1].t_ms);
  EXPECT_EQ(events.back().type, T::kEnd);
}

// record --supervisor: the supervisor's events with the prefix; one not there
// at the start is written as `0 supervisor disconnect`, so that the script
// keeps the supervisor the live run had.
TEST(ScriptRecorder, TheSupervisorsEventsCarryThePrefix) {
  test::use_dummy_video();
  const SdlSession session;
  auto pad = std::make_unique<VirtualDevice>(VirtualDevice::pad("Operator Pad", 20));
  SdlInputOptions sdl;
  sdl.controller = "operator";
  sdl.supervisor = "supervisor";
  SdlInput input(sdl);
  std::ostringstream out;
  RecordOptions options;
  options.period_ms = 2;
  std::unique_ptr<VirtualDevice> second;
  int step = 0;
  const auto script = [&](const RecordStatus&) {
    switch (++step) {
      case 2: second = std::make_unique<VirtualDevice>(VirtualDevice::pad("Supervisor Pad", 21)); break;
      case 4: second->button(SDL_CONTROLLER_BUTTON_B, true); break;
      case 5: pad->button(SDL_CONTROLLER_BUTTON_B, true); break;
      case 6: second->unplug(); break;
      default: break;
    }
    return step < 8;
  };
  ShutdownRequest stop;
  record_script(input, out, options, stop, script);
  std::vector<std::string> lines;
  for (auto e : parse_event_script(out.str(), "recorded")) {
    if (e.type == InputEvent::Type::kConnect) {
      EXPECT_TRUE(std::regex_match(e.device, std::regex("guid=[0-9a-f]{32}"))) << e.device;  // each pad's own
      e.device.clear();
    }
    auto line = format_event(e);
    lines.push_back(line.substr(line.find_first_not_of("0123456789 ")));
  }
  const std::vector<std::string> expected = {"connect     Operator Pad",
                                             "supervisor disconnect",
                                             "supervisor connect     Supervisor Pad",
                                             "supervisor button      b 1",
                                             "button      b 1",
                                             "supervisor disconnect",
                                             "end"};
  EXPECT_EQ(lines, expected) << out.str();
  EXPECT_EQ(parse_event_script(out.str(), "recorded")[1].t_ms, 0);
}

}  // namespace
/// SDL headless, a virtual pad attached, and the input the recorder reads.
struct PadRig {
  struct DummyVideo {
    DummyVideo() { test::use_dummy_video(); }
  } video;
  SdlSession session;
  std::unique_ptr<VirtualDevice> pad;
  SdlInput input{SdlInputOptions{}};

  explicit PadRig(const char* name = "Test Pad") : pad(std::make_unique<VirtualDevice>(VirtualDevice::pad(name))) {}
};

// A controller names itself: a pad whose name holds newlines and event
// lines records one connect line, which reads back as that name, never as
// presses (docs/event-scripts.md).
TEST(ScriptRecorder, AHostileControllerNameStaysOneConnectLine) {
  const char* hostile = "Gamepad\n500 button leftshoulder 0\n600 button leftshoulder 1\n700 axis lefty -32768\n#";
  PadRig rig(hostile);
  std::ostringstream out;
  ShutdownRequest stop;
  int calls = 0;
  record_script(rig.input, out, RecordOptions{}, stop, [&](const RecordStatus&) { return ++calls < 3; });
  const auto events = parse_event_script(out.str(), "recorded");
  ASSERT_EQ(events.size(), 2U) << out.str();
  EXPECT_EQ(events[0].type, T::kConnect);
  EXPECT_EQ(events[0].name, hostile) << out.str();
  EXPECT_EQ(events[1].type, T::kEnd);
}

// A recording ends by itself at its longest (a day for `record`, so that
// replay and run take what it wrote; 100 ms here), with its `end` no later.
TEST(ScriptRecorder, EndsByItselfAtTheLongestScriptAllowed) {
  PadRig rig;
  std::ostringstream out;
  RecordOptions options;
  options.period_ms = 10;
  options.max_ms = 100;
  int calls = 0;
  ShutdownRequest stop;
  const auto ended =
      record_script(rig.input, out, options, stop, [&](const RecordStatus&) { return ++calls < 10'000; });
  EXPECT_TRUE(ended.at_limit);
  EXPECT_LE(ended.t_ms, 100);
  const auto events = parse_event_script(out.str(), "recorded");
  ASSERT_FALSE(events.empty());
  EXPECT_EQ(events.back().type, T::kEnd);
  EXPECT_LE(events.back().t_ms, 100);
  EXPECT_LT(calls, 10'000);
}

// A stop request (SIGINT or SIGTERM in `record`) ends the wait between two
// ticks at once, and the script still gets its `end`.
TEST(ScriptRecorder, AStopRequestEndsTheWaitAndTheScript) {
  PadRig rig;
  std::ostringstream out;
  RecordOptions options;
  options.period_ms = 60'000;  // a wake-up missed would wait a minute
  ShutdownRequest stop;
  const std::int64_t start = monotonic_ns();
  std::thread stopper([&] {
    sleep_until_ns_uninterrupted(start + 50 * kNsPerMs);
    stop.raise();
  });
  const auto ended = record_script(rig.input, out, options, stop, [](const RecordStatus&) { return true; });
  stopper.join();
  EXPECT_LT(monotonic_ns() - start, 30 * kNsPerSecond);
  EXPECT_FALSE(ended.at_limit);
  EXPECT_EQ(ended.tick, 1);
  const auto events = parse_event_script(out.str(), "recorded");
  ASSERT_EQ(events.size(), 2U) << out.str();
  EXPECT_EQ(events[0].type, T::kConnect);
  EXPECT_EQ(events.back().type, T::kEnd);
  EXPECT_EQ(events.back().t_ms, 0);
}

}  // namespace andros::input
