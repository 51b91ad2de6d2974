// The flight recorder (run/recorder.hpp) on the run loop itself: a disk that
// stalls or fails never delays a frame, and a recorded session (a stall, a
// Ctrl-Z, a link loss and a reload inside it) replays byte for byte.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "andros/input/script_input.hpp"
#include "andros/link/fault_link.hpp"
#include "andros/mapping/engine.hpp"
#include "andros/mapping/loader.hpp"
#include "andros/protocol/signals.hpp"
#include "andros/record/recorded_loop.hpp"
#include "andros/record/recorder.hpp"
#include "andros/record/session_replay.hpp"
#include "andros/timing/rate.hpp"
#include "support/temp_dir.hpp"

namespace andros::record {
namespace {

const std::string kMappings = ANDROS_MAPPINGS_DIR;

/// A sink that holds every write until released (a disk that does not answer).
class StallingSink final : public RecordSink {
 public:
  struct Gate {
    std::mutex mutex;
    std::condition_variable open;
    bool released = false;
    int writes = 0;
    void release() {
      const std::lock_guard lock(mutex);
      released = true;
      open.notify_all();
    }
    /// Until the writer has stalled in `n` writes (false after 10 s: it never got there).
    bool stalled_in(int n) {
      std::unique_lock lock(mutex);
      return open.wait_for(lock, std::chrono::seconds(10), [&] { return writes >= n; });
    }
  };
  explicit StallingSink(std::shared_ptr<Gate> gate) : gate_(std::move(gate)) {}
  bool write(std::string_view, std::string&) override {
    std::unique_lock lock(gate_->mutex);
    ++gate_->writes;
    gate_->open.notify_all();
    gate_->open.wait(lock, [this] { return gate_->released; });
    return true;
  }
  bool sync(std::string&) override { return true; }

 private:
  std::shared_ptr<Gate> gate_;
};

/// A full disk.
class FullSink final : public RecordSink {
 public:
  bool write(std::string_view, std::string& error) override {
    error = "No space left on device";
    return false;
  }
  bool sync(std::string&) override { return true; }
};

/// A script that moves the left stick on every tick for `seconds` with the deadman held.
std::string busy_script(int seconds) {
  std::string s = "0 connect pad\n0 button leftshoulder 0\n100 button leftshoulder 1\n";
  for (int t = 200; t < seconds * 1000; t += 40) {
    s += std::to_string(t) + " axis lefty " + std::to_string(-2000 - (t * 7) % 30000) + "\n";
  }
  return s + std::to_string(seconds * 1000) + " end\n";
}

/// The frames the link took in a run of script through hd1, on a virtual
/// clock; with the recorder writing to writer when given.
std::vector<protocol::Frame> run_loop(const std::string& script_path, SessionWriter* writer) {
  input::ScriptInput script(script_path);
  mapping::Engine frames(mapping::load_mapping(kMappings + "/hd1.yaml"), mapping::EngineOptions{});
  std::vector<protocol::Frame> got;
  link::SinkLink link([&got](std::int64_t, const protocol::Frame& f) { got.push_back(f); });
  VirtualClock clock;
  std::optional<Recorder> recorder;
  std::optional<RecordingInput> recorded;
  if (writer != nullptr) recorded.emplace(script, recorder.emplace(*writer));
  input::InputSource& input = recorded ? static_cast<input::InputSource&>(*recorded) : script;
  run::Bridge bridge(clock, input, frames, link, run::BridgeOptions{.rate_millihertz = 25'000, .rules = {false, 0x01}});
  bridge.run([] { return false; },
             [&](const run::TickReport& r) {
               if (recorder) recorder->observe(r);
             });
  if (recorder) recorder->end("end of the input");
  return got;
}

TEST(Recorder, AStalledDiskNeverDelaysAFrame) {
  testing::TempDir dir;
  const auto script = dir.write("busy.events", busy_script(60));
  const auto without = run_loop(script, nullptr);

  auto gate = std::make_shared<StallingSink::Gate>();
  SessionWriter writer(std::make_unique<StallingSink>(gate), 64);
  // The writer thread is stuck in its first write for the whole run: were the
  // loop to wait for it, this run would never end.
  const auto with = run_loop(script, &writer);
  EXPECT_EQ(with, without);  // every frame, on its tick, the same bytes
  EXPECT_EQ(with.size(), 60u * 25 + 1 + 3);
  EXPECT_GT(writer.dropped(), 1000u);  // the queue filled; records, not frames, were dropped
  gate->release();
  EXPECT_FALSE(writer.close(5000));
}

/// A disk that counts what it was asked to do.
class CountingSink final : public RecordSink {
 public:
  struct Counts {
    std::atomic<int> writes{0};
    std::atomic<int> syncs{0};
  };
  explicit CountingSink(std::shared_ptr<Counts> counts) : counts_(std::move(counts)) {}
  bool write(std::string_view, std::string&) override {
    ++counts_->writes;
    return true;
  }
  bool sync(std::string&) override {
    ++counts_->syncs;
    return true;
  }

 private:
  std::shared_ptr<Counts> counts_;
};

/// Waits (bounded, 5 s) until done() holds; whether it did.
template <typename Done>
bool within_5s(Done done) {
  for (int i = 0; i < 5000 && !done(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  return done();
}

// A run at rest records nothing: the writer thread then sleeps (no wake-ups,
// no fdatasync of nothing) until the next record, which it writes and syncs.
TEST(Recorder, AtRestTheWriterSleepsUntilTheNextRecord) {
  const auto counts = std::make_shared<CountingSink::Counts>();
  SessionWriter writer(std::make_unique<CountingSink>(counts));
  writer.push("state 0 NOT_ENABLED");
  ASSERT_TRUE(within_5s([&] { return counts->writes == 1 && counts->syncs == 1; }));
  // Written and synced: nothing more to do. Polling, it would sync again within the second.
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  EXPECT_EQ(counts->writes, 1);
  EXPECT_EQ(counts->syncs, 1);
  writer.push("state 1600 ENABLED");
  EXPECT_TRUE(within_5s([&] { return counts->writes == 2 && counts->syncs == 2; }));
  EXPECT_TRUE(writer.close(5000));
  EXPECT_EQ(writer.written(), 2u);
}

TEST(Recorder, AFullQueueRefusesAtOnceAndCounts) {
  auto gate = std::make_shared<StallingSink::Gate>();
  SessionWriter writer(std::make_unique<StallingSink>(gate), 8);
  // The disk stalls in the first write: the writer took that record and is
  // held there. (Pushed all at once instead, the records the writer takes
  // before its first write depend on how fast each thread runs: 9 on one
  // run, 16 on a slower one.)
  ASSERT_TRUE(writer.push("event first"));
  ASSERT_TRUE(gate->stalled_in(1));
  int taken = 0;
  for (int i = 0; i < 100; ++i) taken += writer.push("event " + std::to_string(i)) ? 1 : 0;
  // The queue's 8, then every push refused at once and counted.
  EXPECT_EQ(taken, 8);
  EXPECT_EQ(writer.dropped(), 92U);
  gate->release();
  writer.close(5000);
}

TEST(Recorder, AFullDiskLosesRecordsWithTheReasonNeverAFrame) {
  testing::TempDir dir;
  const auto script = dir.write("busy.events", busy_script(5));
  const auto without = run_loop(script, nullptr);
  SessionWriter writer(std::make_unique<FullSink>());
  const auto with = run_loop(script, &writer);
  EXPECT_EQ(with, without);
  EXPECT_FALSE(writer.close(5000));
  EXPECT_GT(writer.lost(), 100u);
  EXPECT_EQ(writer.written(), 0u);
  EXPECT_EQ(writer.error(), "No space left on device");
}

/// A "live" run as `run` makes it, on a virtual clock that the test moves as
/// a live one moves: a stall that skips ticks, a Ctrl-Z that stops the
/// process a while, a reload read over a few ticks; recorded into a file.
struct RecordedRun {
  testing::TempDir dir;
  std::filesystem::path session = dir.path() / "live.andros-session";
  std::vector<std::pair<std::int64_t, protocol::DataBytes>> delivered;
  std::vector<run::TickReport> reports;
  std::string reload_file = kMappings + "/f6a.yaml";  ///< what a reload puts in place
  std::string input_name = "script";                  ///< the settings' input, as run names it

  void run(const std::string& script_text) {
    const auto script_path = dir.write("drive.events", script_text);
    input::ScriptInput script(script_path);
    const auto engine_for = [this](const std::string& file, bool weapons) {
      auto m = mapping::load_mapping(file);
      SessionSettings s{.robot = m->robot.value_or("HD1"),
                        .mapping_file = m->file,
                        .rate_millihertz = 25'000,
                        .weapons = weapons,
                        .code = 0x01,
                        .center = m->center,
                        .port = "test",
                        .baud = 9600,
                        .input = input_name,
                        .config = "",
                        .sources = read_mapping_sources(m->chain)};
      return std::make_pair(std::make_shared<mapping::Engine>(std::move(m), mapping::EngineOptions{.weapons = weapons}),
                            s);
    };
    auto [first, settings] = engine_for(kMappings + "/hd1.yaml", false);
    mapping::Engine& frames = *first;
    VirtualClock clock;
    link::SinkLink link([](std::int64_t, const protocol::Frame&) {});
    SessionWriter writer(std::make_unique<FileRecordSink>(session.string()));
    Recorder recorder(writer);
    recorder.header("test", "2024-05-01T12:00:00+0200", 1, "bench", settings, link.status());
    RecordingInput input(script, recorder);
    run::Bridge bridge(clock, input, frames, link,
                       run::BridgeOptions{.rate_millihertz = 25'000, .rules = {false, 0x01}});

    int polls = 0;
    int reload_ticks = 0;
    SessionSettings reloaded;
    run::RunControl control;
    control.poll = [&] { return ++polls == 150 ? run::Request::kSuspend : run::Request::kNone; };  // Ctrl-Z at 6 s
    control.pause = [&](const run::ShutdownReport&) { clock.advance(Nanos(1'234'567'891)); };      // stopped 1.23 s
    control.begin_reload = [&](const std::string&) { reload_ticks = 0; };
    control.finish_reload = [&]() -> std::optional<run::ReloadOutcome> {
      if (++reload_ticks < 4) return std::nullopt;  // the worker still reads
      auto [next, s] = engine_for(reload_file, true);
      reloaded = s;
      return run::ReloadOutcome{true, "reloaded", true, std::move(next)};
    };
    bridge.run(recorded_control(control, recorder, [&] { return reloaded; }), [&](const run::TickReport& r) {
      recorder.observe(r);
      reports.push_back(r);
      if (r.delivered()) delivered.emplace_back(r.tick, r.data);
      if (r.tick == 40 || r.tick == 110) clock.advance(Nanos(130'000'000));  // a stall: ticks 41 and 42 skipped
    });
    recorder.end("end of the input");
    ASSERT_TRUE(writer.close(5000));
  }
};

const char* const kDriveWithFaults =
    "0 connect pad\n"
    "0 button leftshoulder 1\n"
    "1000 button leftshoulder 0\n"
    "1500 button leftshoulder 1\n"
    "2000 axis lefty -16000\n"
    "2500 link down\n"
    "2700 link up\n"
    "2900 axis lefty 0\n"
    "3000 button leftshoulder 0\n"
    "3100 button leftshoulder 1\n"
    "3300 axis lefty -30000\n"
    "3500 axis leftx 12000\n"
    "4000 reload\n"
    "4400 axis lefty 0\n"
    "4420 axis leftx 0\n"
    "4500 button leftshoulder 0\n"
    "4600 button leftshoulder 1\n"
    "4800 axis lefty -25000\n"
    "5500 button dpup 1\n"
    "5800 button dpup 0\n"
    "7000 axis lefty 0\n"
    "7100 button leftshoulder 0\n"
    "7200 button leftshoulder 1\n"
    "7400 axis lefty -20000\n"
    "9000 button leftshoulder 0\n"
    "9500 end\n";

TEST(Recorder, ARecordedSessionReplaysByteForByte) {
  RecordedRun live;
  live.run(kDriveWithFaults);
  ASSERT_TRUE(verify_session(live.session).intact);
  const Session s = read_session(live.session);
  // What happened is in it: the stalls, the pause, the link loss, the reload.
  EXPECT_EQ(std::count_if(s.frames.begin(), s.frames.end(), [](const FrameRecord& f) { return f.gap == 2; }), 2);
  EXPECT_EQ(s.pauses.size(), 1u);
  EXPECT_EQ(s.reloads.size(), 1u);
  EXPECT_TRUE(std::any_of(s.states.begin(), s.states.end(),
                          [](const StateRecord& r) { return r.state == run::OpState::kNoLink; }));
  EXPECT_TRUE(std::any_of(s.states.begin(), s.states.end(),
                          [](const StateRecord& r) { return r.state == run::OpState::kEnabled; }));
  ASSERT_TRUE(s.end);
  EXPECT_EQ(s.end->frames_sent, live.delivered.size());

  // Every frame the live loop sent is one the recording makes again.
  for (const auto& [tick, data] : live.delivered) {
    const auto* f = s.frame_at(tick);
    ASSERT_NE(f, nullptr);
    EXPECT_EQ(f->data, data) << "tick " << tick;
  }

  std::vector<run::TickReport> replayed;
  const auto result =
      replay_session(s, load_recorded_mapping, [&](const run::TickReport& r) { replayed.push_back(r); });
  EXPECT_TRUE(result.identical) << result.difference;
  EXPECT_EQ(result.compared, live.delivered.size());
  // The same ticks and the same states, not only the same bytes.
  ASSERT_EQ(replayed.size(), live.reports.size());
  for (std::size_t i = 0; i < replayed.size(); ++i) {
    EXPECT_EQ(replayed[i].tick, live.reports[i].tick) << i;
    EXPECT_EQ(replayed[i].state, live.reports[i].state) << "tick " << live.reports[i].tick;
  }
}

TEST(Recorder, TextOfAnyBytesIsRecordedWholeAndNeverEndsTheDrive) {
  // A pad that names itself with every byte value (USB descriptors may hold
  // any), an input path and a mapping that are not UTF-8: the drive goes on
  // through the stop, its reset and a reload, and the session gives back the
  // exact bytes (issue 34: the JSON layer refused them and ended the run).
  std::string name;
  for (int b = 0x01; b <= 0xff; ++b) name += static_cast<char>(b);
  RecordedRun live;
  const std::string latin = "robot: HD1\nextends: " + kMappings + "/hd1.yaml\n# caf\xe9, \xff\xc3: Latin-1\n";
  live.reload_file = live.dir.write("latin.yaml", latin).string();
  live.input_name = "drive-caf\xe9-\xff.events";
  input::InputEvent connect{.t_ms = 0, .type = input::InputEvent::Type::kConnect, .name = name};
  live.run(input::format_event(connect) +
           "\n40 button leftshoulder 1\n200 axis lefty -20000\n"
           "1000 button guide 1\n1100 button guide 0\n1120 axis lefty 0\n1140 button leftshoulder 0\n"
           "1200 button back 1\n1200 button start 1\n3400 button back 0\n3400 button start 0\n"
           "3600 reload\n4200 button leftshoulder 1\n4400 axis lefty -20000\n5000 end\n");
  ASSERT_TRUE(verify_session(live.session).intact);
  const Session s = read_session(live.session);
  ASSERT_FALSE(s.events.empty());
  EXPECT_EQ(s.events[0].name, name);
  EXPECT_EQ(s.settings.input, live.input_name);
  ASSERT_EQ(s.stops.size(), 2u);  // the stop and its reset
  EXPECT_EQ(s.stops[0].pad.name, name);
  EXPECT_EQ(s.stops[1].pad.name, name);
  EXPECT_TRUE(s.stops[1].reset);
  ASSERT_EQ(s.reloads.size(), 1u);
  ASSERT_TRUE(s.reloads[0].settings);
  EXPECT_EQ(s.reloads[0].settings->sources.at(0).path, live.reload_file);
  EXPECT_EQ(s.reloads[0].settings->sources.at(0).text, latin);
  EXPECT_EQ(s.dropped, 0u);
  ASSERT_TRUE(s.end);
  // It drove after the reload: a frame with the drive off centre went out after 4.4 s.
  const auto drove = std::any_of(live.reports.begin(), live.reports.end(), [](const run::TickReport& r) {
    return r.t_ms >= 4400 && r.state == run::OpState::kEnabled &&
           protocol::read_signals(r.data)[protocol::signal_id("drive")] != protocol::kNeutralCentre;
  });
  EXPECT_TRUE(drove);
  const auto result = replay_session(s, load_recorded_mapping, [](const run::TickReport&) {});
  EXPECT_TRUE(result.identical) << result.difference;
}

TEST(Recorder, WhoStoppedAndWhoResetAreRecordedAndReplayed) {
  RecordedRun live;
  // The stop, pressed again while stopped, and the reset chord (the shipped mapping's back and start) held 2 s.
  live.run(
      "0 connect {path=/dev/input/event5 guid=030000005e040000} Pad A\n40 button leftshoulder 1\n"
      "200 button guide 1\n300 button guide 0\n320 button leftshoulder 0\n400 button guide 1\n420 button guide 0\n"
      "500 button back 1\n500 button start 1\n2700 button back 0\n2700 button start 0\n2800 button leftshoulder 1\n"
      "3000 end\n");
  const Session s = read_session(live.session);
  ASSERT_EQ(s.stops.size(), 3u);
  const input::PadIdentity pad{"Pad A", "/dev/input/event5", "", "030000005e040000"};
  EXPECT_FALSE(s.stops[0].reset);
  EXPECT_EQ(s.stops[0].by, run::StopBy::kOperator);
  EXPECT_EQ(s.stops[0].t_ms, 200);
  EXPECT_EQ(s.stops[0].pad, pad);
  EXPECT_FALSE(s.stops[1].reset);  // pressed again while stopped: recorded, the latch kept
  EXPECT_TRUE(s.stops[1].again);
  EXPECT_FALSE(s.stops[0].again);
  EXPECT_EQ(s.stops[1].t_ms, 400);
  EXPECT_TRUE(s.stops[2].reset);
  EXPECT_EQ(s.stops[2].by, run::StopBy::kOperator);
  EXPECT_EQ(s.stops[2].t_ms, 2520);  // the chord from 520
  EXPECT_EQ(s.stops[2].pad, pad);
  const auto result = replay_session(s, load_recorded_mapping, [](const run::TickReport&) {});
  EXPECT_TRUE(result.identical) << result.difference;
}

TEST(Recorder, AReplayNamesTheFirstFrameThatDiffers) {
  RecordedRun live;
  live.run(kDriveWithFaults);
  Session s = read_session(live.session);
  // The frame record in effect while driving says something else.
  const auto it = std::find_if(s.frames.begin(), s.frames.end(), [](const FrameRecord& f) { return f.data[7] != 128; });
  ASSERT_NE(it, s.frames.end());
  it->data[7] ^= 0x01;
  const auto result = replay_session(s);
  EXPECT_FALSE(result.identical);
  EXPECT_EQ(result.difference.rfind("tick " + std::to_string(it->tick) + " (", 0), 0u) << result.difference;
}

TEST(Recorder, ASessionWithDroppedRecordsIsNotReplayed) {
  RecordedRun live;
  live.run(kDriveWithFaults);
  Session s = read_session(live.session);
  s.dropped = 3;
  EXPECT_THROW(replay_session(s), InputError);
}

TEST(Recorder, EveryRecordTheLoopWritesIsComparedWithItsLine) {
  RecordedRun live;
  live.run(
      "0 connect {path=/dev/input/event5 guid=030000005e040000} Pad A\n40 button leftshoulder 1\n"
      "200 button guide 1\n300 button guide 0\n320 button leftshoulder 0\n"
      "500 button back 1\n500 button start 1\n2700 button back 0\n2700 button start 0\n3000 end\n");
  const Session s = read_session(live.session);
  ASSERT_TRUE(replay_session(s).identical) << replay_session(s).difference;
  ASSERT_EQ(s.stops.size(), 2u);
  ASSERT_GE(s.states.size(), 3u);
  const auto differs = [](const Session& altered, const std::string& start) {
    const auto result = replay_session(altered);
    EXPECT_FALSE(result.identical);
    EXPECT_EQ(result.difference.rfind(start, 0), 0u) << result.difference;
  };
  // Frames unchanged, each record altered in turn: the replay names its line and both texts.
  Session state = s;
  state.states[1].state = run::OpState::kNotEnabled;
  differs(state, "line " + std::to_string(s.states[1].line) + ": recorded 'state " + std::to_string(s.states[1].t_ms) +
                     " not enabled', the replay makes 'state ");
  Session stop = s;
  stop.stops[0].by = run::StopBy::kSupervisor;
  differs(stop, "line " + std::to_string(s.stops[0].line) + ": recorded 'stop 200 supervisor {");
  Session reset = s;
  reset.stops.pop_back();
  differs(reset, "the replay makes 'reset 2520 operator {");
  Session layer = s;
  layer.layers[0].text = "weapons";
  differs(layer, "line " + std::to_string(s.layers[0].line) + ": recorded 'layer 0 \"weapons\"'");
  Session gate = s;
  gate.gate_trips.push_back({s.states[1].t_ms, "forged", s.states[1].line});
  differs(gate, "line " + std::to_string(s.states[1].line) + ": recorded 'gate ");
  // A frame record repeating the one before it a tick later: the same frames, a record the loop never writes.
  Session frame = s;
  const auto spaced =
      std::adjacent_find(frame.frames.begin(), frame.frames.end(),
                         [](const FrameRecord& a, const FrameRecord& b) { return b.tick > a.tick + 1; });
  ASSERT_NE(spaced, frame.frames.end());
  FrameRecord again = *spaced;
  ++again.tick;
  again.t_ms = timing::FrameClock(25'000).time_of(again.tick);
  frame.frames.insert(spaced + 1, again);
  differs(frame, "line " + std::to_string(again.line) + ": recorded 'frame " + std::to_string(again.tick) + " ");
  // In the file's order: a record matched out of its place is named.
  Session moved = s;
  std::swap(moved.states[1].line, moved.frames[1].line);
  differs(moved, "line ");
}

TEST(Recorder, AFrameRecordIsWrittenAgainEveryMinuteAndReadersHoldItsWriterToIt) {
  RecordedRun live;
  live.run("0 connect pad\n130000 end\n");  // 130 s at rest: one frame throughout
  const Session s = read_session(live.session);
  // After the last change (the link and controller settling), the same frame a minute apart.
  std::vector<std::int64_t> at;
  for (const auto& f : s.frames) {
    if (f.t_ms < 130'000) at.push_back(f.t_ms);
  }
  ASSERT_GE(at.size(), 3u);
  EXPECT_LT(at[at.size() - 3], 60'000);
  EXPECT_EQ(at[at.size() - 2], at[at.size() - 3] + 60'000);
  EXPECT_EQ(at.back(), at[at.size() - 3] + 120'000);
  EXPECT_EQ(s.format, kSessionFormat);
  EXPECT_TRUE(replay_session(s).proven()) << replay_session(s).difference;
  // Without the record at 60 s, ticks stand 60 s and more after a record: refused.
  Session gap = s;
  std::erase_if(gap.frames, [&at](const FrameRecord& f) { return f.t_ms == at[at.size() - 2]; });
  EXPECT_THROW(check_record_spacing(gap), InputError);
  // An earlier format (whose writer did not repeat its record) is read as before.
  gap.format = 2;
  EXPECT_NO_THROW(check_record_spacing(gap));
}

}  // namespace
}  // namespace andros::record
