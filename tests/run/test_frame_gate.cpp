// The frame gate (src/run/frame_gate.cpp): each rule on frames made by hand,
// and its mutation score in the loop: the mapping engine with one fault
// injected at a time (tests/support/faulty_frames.hpp) drives a script
// through the run loop; every frame the link gets from the first fault on is
// neutral, the loop stops, and the same script without the fault trips nothing.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "andros/base/text_file.hpp"
#include "andros/input/script_player.hpp"
#include "andros/mapping/engine.hpp"
#include "andros/mapping/loader.hpp"
#include "andros/record/recorder.hpp"
#include "andros/record/session.hpp"
#include "andros/run/frame_gate.hpp"
#include "support/faulty_frames.hpp"
#include "support/temp_dir.hpp"

namespace andros::run {
namespace {

constexpr std::uint8_t kCode = 0x5A;
using protocol::signal_id;

protocol::DataBytes frame(std::initializer_list<std::pair<protocol::SignalId, int>> set = {}) {
  protocol::ControlState s;
  s[signal_id("drive")] = protocol::kNeutralCentre;
  s[signal_id("pivot")] = protocol::kNeutralCentre;
  for (const auto& [id, v] : set) s[id] = static_cast<std::uint8_t>(v);
  return protocol::FrameBuilder(kCode).build(s);
}

TEST(FrameGate, PassesTheNeutralFrameAndMotionWhileEnabled) {
  const FrameGate gate({false, kCode});
  const auto selectors = frame({{signal_id("speed_low"), 1}, {signal_id("main_video_2"), 1}, {signal_id("light"), 9}});
  EXPECT_EQ(gate.fault(selectors, false), "");
  const auto driving = frame({{signal_id("safety"), 1}, {signal_id("drive"), 255}, {signal_id("pt_left"), 1}});
  EXPECT_EQ(gate.fault(driving, true), "");
  EXPECT_EQ(gate.fault(driving, false), "safety = 1 while not enabled");
}

TEST(FrameGate, NamesEachRuleAFrameBreaks) {
  const FrameGate gate({false, kCode});
  EXPECT_EQ(gate.fault(frame({{signal_id("drive"), 129}}), false), "drive = 129 while not enabled (neutral is 128)");
  EXPECT_EQ(gate.fault(frame({{signal_id("safety"), 1}}), false), "safety = 1 while not enabled");
  EXPECT_EQ(gate.fault(frame({{signal_id("zoom_up"), 1}, {signal_id("zoom_down"), 1}}), true),
            "zoom_down and zoom_up both 1 (an opposing pair)");
  EXPECT_EQ(gate.fault(frame({{signal_id("laser"), 1}}), true), "laser = 1 with weapons not enabled for the run");
  EXPECT_EQ(FrameGate({true, kCode}).fault(frame({{signal_id("laser"), 1}}), false), "laser = 1 while not enabled");
  EXPECT_EQ(FrameGate({true, kCode}).fault(frame({{signal_id("laser"), 1}}), true), "");
  auto code = frame();
  code[protocol::kCodeByte] = 0x5B;
  EXPECT_EQ(gate.fault(code, true), "byte 11 is 0x5B, the configured code is 0x5A");
  auto trailer = frame();
  trailer[protocol::kTrailerByte] = 0;
  EXPECT_EQ(gate.fault(trailer, true), "invalid frame: byte 15 is 0x00, must be 0x02");
}

TEST(FrameGate, ItsNeutralFrameKeepsSelectorsAndLevelsAndNothingElse) {
  FrameGate gate({false, kCode});
  auto bad = frame({{signal_id("drive"), 3},
                    {signal_id("safety"), 1},
                    {signal_id("speed_high"), 1},
                    {signal_id("speed_low"), 1},
                    {signal_id("inset_3"), 1},
                    {signal_id("arm_speed"), 77}});
  bad[protocol::kCodeByte] = 0x11;
  const GateVerdict v = gate.pass(bad, false);
  EXPECT_TRUE(v.tripped());
  EXPECT_EQ(v.data, frame({{signal_id("inset_3"), 1}, {signal_id("arm_speed"), 77}}));
  EXPECT_EQ(gate.trips(), 1);
  EXPECT_FALSE(gate.pass(v.data, false).tripped());
  EXPECT_EQ(gate.trips(), 1);
}

/// The script as the loop's input.
class TextInput final : public input::InputSource {
 public:
  explicit TextInput(const std::string& text) : reader_(text, "gate.events", kEventScriptLimits), player_(reader_) {}
  void pump(input::TickInput& input, std::int64_t now_ms) override { player_.advance_to(now_ms, input); }
  [[nodiscard]] bool finished(std::int64_t now_ms) const override { return player_.finished_at(now_ms); }
  [[nodiscard]] bool supervised() const override { return player_.supervised(); }

 private:
  TextReader reader_;
  input::ScriptPlayer player_;
};

// Driving; Ctrl-Z and fg while driving (a suspend's neutral frames); a stop
// button, released; the deadman released and pressed again; driving again.
constexpr const char* kScript =
    "0 connect pad\n40 button leftshoulder 1\n60 axis lefty -32768\n200 suspend\n240 resume\n"
    "300 button guide 1\n340 button guide 0\n400 button leftshoulder 0\n500 axis lefty 0\n"
    "520 button leftshoulder 1\n560 axis lefty -20000\n800 end\n";

struct GateRun {
  std::vector<TickReport> reports;                                 ///< every tick
  std::vector<std::pair<std::int64_t, protocol::DataBytes>> wire;  ///< what the link took, by tick
};

GateRun run_gated(const std::string& script, bool weapons, std::optional<test::EngineFault> fault,
                  const RunControl& control = {}) {
  TextInput input(script);
  std::unique_ptr<FrameSource> engine =
      std::make_unique<mapping::Engine>(mapping::load_mapping(ANDROS_MAPPINGS_DIR "/hd1.yaml"),
                                        mapping::EngineOptions{.weapons = weapons, .code = kCode});
  if (fault) engine = std::make_unique<test::FaultyFrames>(std::move(engine), *fault);
  VirtualClock clock;
  GateRun out;
  // The virtual clock stands at the tick's time while the frame is sent (25 Hz: 40 ms a tick).
  link::SinkLink link([&](std::int64_t t_ns, const protocol::Frame& f) {
    out.wire.emplace_back(t_ns / 40'000'000, protocol::parse_data_hex(std::string(f.begin() + 2, f.begin() + 34)));
  });
  Bridge bridge(clock, input, *engine, link,
                BridgeOptions{.rate_millihertz = 25'000, .neutral_tail_at_end = false, .rules = {weapons, kCode}});
  bridge.run(control, [&](const TickReport& r) { out.reports.push_back(r); });
  return out;
}

/// Neutral as the contract has it, checked here on its own: every bit but
/// the selector-like ones 0 (and never both of a pair), drive and pivot 128,
/// the code, a valid frame.
bool is_neutral(const protocol::DataBytes& d) {
  if (!protocol::validation_errors(d).empty() || d[protocol::kCodeByte] != kCode) return false;
  const auto s = protocol::read_signals(d);
  for (std::size_t i = 0; i < protocol::kSignalCount; ++i) {
    const auto& sig = protocol::kSignals[i];
    const auto p = protocol::partner_of(static_cast<protocol::SignalId>(i));
    if (sig.kind == protocol::SignalKind::kCentred && s.values[i] != 128) return false;
    if (sig.is_bit() && sig.kind != protocol::SignalKind::kSelector && s.values[i] != 0) return false;
    if (p && s.values[i] != 0 && s.values[*p] != 0) return false;
  }
  return true;
}

TEST(FrameGate, CatchesEveryInjectedEngineFaultOnTheWire) {
  int caught = 0;
  for (const auto& kind : test::kFaultKinds) {
    SCOPED_TRACE(kind.name);
    const GateRun clean = run_gated(kScript, kind.weapons, std::nullopt);
    ASSERT_EQ(clean.reports.back().gate_trips, 0) << "a false alarm without a fault";
    const GateRun faulty = run_gated(kScript, kind.weapons, kind.fault);
    std::optional<std::int64_t> first;
    for (const auto& r : faulty.reports) {
      if (r.gate_fault.empty()) continue;
      if (!first) first = r.tick;
      // Stopped; or the stop latched for when a suspend or reload ends.
      EXPECT_NE(r.state, OpState::kEnabled) << "tick " << r.tick << ": " << r.gate_fault;
      EXPECT_TRUE(is_neutral(r.data)) << "tick " << r.tick;
    }
    ASSERT_TRUE(first) << "never tripped";
    // What the link got: before the first fault, the clean run's frames; then
    // the clean run's or neutral ones, never a frame with the fault.
    std::map<std::int64_t, protocol::DataBytes> reference(clean.wire.begin(), clean.wire.end());
    for (const auto& [tick, data] : faulty.wire) {
      const auto it = reference.find(tick);
      const bool as_clean = it != reference.end() && it->second == data;
      if (tick < *first) EXPECT_TRUE(as_clean) << "tick " << tick;
      else EXPECT_TRUE(as_clean || is_neutral(data)) << "tick " << tick << ": " << protocol::to_hex(data);
    }
    EXPECT_GT(faulty.reports.back().gate_trips, 0);
    const bool motion_before = std::any_of(faulty.wire.begin(), faulty.wire.end(),
                                           [&](const auto& w) { return w.first < *first && !is_neutral(w.second); });
    std::printf("frame gate: %-50s caught at tick %lld (%lld frames replaced; motion before it: %s)\n", kind.name,
                static_cast<long long>(*first), static_cast<long long>(faulty.reports.back().gate_trips),
                motion_before ? "yes" : "no");
    ++caught;
  }
  std::printf("frame gate: %d of %zu kinds of engine fault caught\n", caught, test::kFaultKinds.size());
  EXPECT_EQ(caught, static_cast<int>(test::kFaultKinds.size()));
}

TEST(FrameGate, AReloadSetsWhetherWeaponsMayBeSent) {
  // A weapon bit while driving; weapons off at the start, then a reload at
  // tick 0 whose settings enable them, or not.
  for (const bool enabled_by_reload : {true, false}) {
    RunControl control;
    bool asked = false;
    control.poll = [&] { return std::exchange(asked, true) ? Request::kNone : Request::kReload; };
    control.finish_reload = [&] { return std::optional(ReloadOutcome{true, "", enabled_by_reload}); };
    const std::string script = "0 connect pad\n300 button leftshoulder 1\n320 axis lefty -32768\n600 end\n";
    const GateRun r = run_gated(script, false, test::EngineFault::kWeaponWithoutWeapons, control);
    EXPECT_EQ(r.reports.back().gate_trips == 0, enabled_by_reload) << enabled_by_reload;
  }
}

TEST(FrameGate, ATripIsRecordedInTheSession) {
  testing::TempDir dir;
  const auto path = dir.path() / "gate.andros-session";
  {
    record::SessionWriter writer(std::make_unique<record::FileRecordSink>(path.string()));
    record::Recorder recorder(writer);
    record::SessionSettings settings;
    settings.robot = "HD1";
    settings.rate_millihertz = 25'000;
    settings.sources = {{"/m/hd1.yaml", "robot: HD1\n"}};
    recorder.header("test", "2024-05-01T12:00:00+0200", 1, "bench", settings, link::LinkStatus{});
    TickReport r;
    r.tick = 3;
    r.t_ms = 120;
    r.state = OpState::kStopped;
    r.gate_fault = "pt_left = 1 while not enabled";
    r.gate_trips = 1;
    recorder.observe(r);
    recorder.end("end of the input");
    ASSERT_TRUE(writer.close(5000));
  }
  const auto s = record::read_session(path);
  ASSERT_EQ(s.gate_trips.size(), 1u);
  EXPECT_EQ(s.gate_trips[0].t_ms, 120);
  EXPECT_EQ(s.gate_trips[0].text, "pt_left = 1 while not enabled");
}

}  // namespace
}  // namespace andros::run
