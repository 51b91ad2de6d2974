// The session file's chain (run/session.hpp): intact, and each kind of
// tampering found at the first record it touches.
#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "andros/record/session.hpp"
#include "support/temp_dir.hpp"

namespace andros::record {
namespace {

/// A small session, whole: its lines.
std::vector<std::string> session_lines() {
  RecordChain chain;
  std::vector<std::string> lines;
  const auto add = [&](const std::string& payload) {
    auto line = chain.line(payload);
    line.pop_back();  // newline
    lines.push_back(line);
  };
  add(payload::header());
  add(payload::program("9.9.9"));
  add("event 0       connect     pad");
  add("event 40      button      a 1");
  add("state 40 enabled");
  add("event 80      button      a 0");
  add("state 80 not enabled");
  add(payload::end(120, 3, 4, "SIGINT"));
  return lines;
}

std::filesystem::path write_lines(const testing::TempDir& dir, const std::vector<std::string>& lines) {
  std::string text;
  for (const auto& l : lines) text += l + "\n";
  return dir.write("s.andros-session", text);
}

TEST(Session, AWholeSessionIsIntactAndClosed) {
  testing::TempDir dir;
  const auto result = verify_session(write_lines(dir, session_lines()));
  EXPECT_TRUE(result.intact) << result.problem;
  EXPECT_EQ(result.records, 8u);
  EXPECT_TRUE(result.closed);
  EXPECT_EQ(result.last_hash.size(), 64u);
}

TEST(Session, EachLineIsChainedToTheOneBefore) {
  // The same payload after a different history hashes differently.
  RecordChain a;
  RecordChain b;
  a.line("x");
  b.line("y");
  const auto la = a.line("same");
  const auto lb = b.line("same");
  EXPECT_EQ(la.substr(0, la.size() - 66), lb.substr(0, lb.size() - 66));
  EXPECT_NE(la, lb);
}

TEST(Session, AnAlteredByteIsFoundAtItsRecord) {
  testing::TempDir dir;
  auto lines = session_lines();
  lines[3][lines[3].find("a 1") + 2] = '0';  // "button a 1" -> "button a 0"
  const auto result = verify_session(write_lines(dir, lines));
  EXPECT_FALSE(result.intact);
  EXPECT_EQ(result.problem, "record 3 (line 4) altered: its content or hash no longer matches the chain");
}

TEST(Session, AnAlteredHashIsFoundAtItsRecord) {
  testing::TempDir dir;
  auto lines = session_lines();
  auto& last = lines[5].back();
  last = last == '0' ? '1' : '0';
  const auto result = verify_session(write_lines(dir, lines));
  EXPECT_FALSE(result.intact);
  EXPECT_EQ(result.problem, "record 5 (line 6) altered: its content or hash no longer matches the chain");
}

TEST(Session, ARemovedRecordIsNamed) {
  testing::TempDir dir;
  auto lines = session_lines();
  lines.erase(lines.begin() + 4);
  const auto result = verify_session(write_lines(dir, lines));
  EXPECT_FALSE(result.intact);
  EXPECT_EQ(result.problem, "record 4 removed (before line 5)");
}

TEST(Session, ARemovedAndRenumberedRecordBreaksTheChain) {
  testing::TempDir dir;
  auto lines = session_lines();
  lines.erase(lines.begin() + 4);
  // Renumbered by hand: the hashes no longer follow.
  for (std::size_t i = 4; i < lines.size(); ++i) lines[i].replace(0, 1, std::to_string(i));
  const auto result = verify_session(write_lines(dir, lines));
  EXPECT_FALSE(result.intact);
  EXPECT_EQ(result.problem, "record 4 (line 5) altered: its content or hash no longer matches the chain");
}

TEST(Session, ASwappedPairIsReordered) {
  testing::TempDir dir;
  auto lines = session_lines();
  std::swap(lines[5], lines[6]);
  const auto result = verify_session(write_lines(dir, lines));
  EXPECT_FALSE(result.intact);
  EXPECT_EQ(result.problem, "record 5 reordered: found at line 7, after record 6 (line 6)");
}

TEST(Session, CutShortItIsIntactButNotClosed) {
  testing::TempDir dir;
  auto lines = session_lines();
  lines.pop_back();
  const auto result = verify_session(write_lines(dir, lines));
  EXPECT_TRUE(result.intact);
  EXPECT_FALSE(result.closed);
}

TEST(Session, AnEventScriptIsNotASession) {
  testing::TempDir dir;
  const auto result = verify_session(dir.write("x.events", "0 connect pad\n"));
  EXPECT_FALSE(result.intact);
  EXPECT_EQ(result.problem, "record 0 (line 1) altered: not a record line");
  EXPECT_FALSE(is_session_start("0 connect pad"));
  EXPECT_TRUE(is_session_start(session_lines()[0]));
}

TEST(Session, RecordsReadBack) {
  testing::TempDir dir;
  RecordChain chain;
  SessionSettings settings{
      .robot = "HD1",
      .mapping_file = "/m/hd1.yaml",
      .rate_millihertz = 25'000,
      .weapons = true,
      .code = 0x3C,
      .center = 130,
      .port = "sim",
      .baud = 9600,
      .input = "sdl",
      .config = "",
      .sources = {{"/m/hd1.yaml", "robot: HD1\nextends: common.yaml\n"}, {"/m/common.yaml", "x: 1\n"}}};
  run::TickReport r;
  r.tick = 7;
  r.t_ms = 280;
  r.data[3] = 0xAB;
  r.result = link::SendResult::kBusy;
  std::string text;
  for (const auto& p :
       {payload::header(), payload::program("1.0"), payload::started("2024-05-01T12:00:00+0200", 42, "bench"),
        payload::settings(settings), payload::link(-1, link::LinkStatus{}), payload::frame(r, 2),
        payload::request(280, run::Request::kSuspend), payload::pause(1300), payload::layer(280, "arm"),
        payload::state(280, run::OpState::kNotEnabled),
        payload::gate(280, "drive = 140 while not enabled (neutral is 128)"), payload::input_end(400),
        payload::end(400, 10, 9, "end of the input")}) {
    text += chain.line(p);
  }
  const auto s = read_session(dir.write("r.andros-session", text));
  EXPECT_EQ(s.version, "1.0");
  ASSERT_EQ(s.gate_trips.size(), 1u);  // the frame gate's record of its own
  EXPECT_EQ(s.gate_trips[0].t_ms, 280);
  EXPECT_EQ(s.gate_trips[0].text, "drive = 140 while not enabled (neutral is 128)");
  EXPECT_EQ(s.started, "2024-05-01T12:00:00+0200");
  EXPECT_EQ(s.pid, 42);
  EXPECT_EQ(s.host, "bench");
  EXPECT_EQ(s.settings.robot, "HD1");
  EXPECT_EQ(s.settings.rate_millihertz, 25'000);
  EXPECT_EQ(s.settings.code, 0x3C);
  EXPECT_TRUE(s.settings.weapons);
  EXPECT_EQ(s.settings.center, 130);
  ASSERT_EQ(s.settings.sources.size(), 2u);
  EXPECT_EQ(s.settings.sources[0].text, "robot: HD1\nextends: common.yaml\n");
  ASSERT_EQ(s.frames.size(), 1u);
  EXPECT_EQ(s.frames[0].tick, 7);
  EXPECT_EQ(s.frames[0].gap, 2);
  EXPECT_EQ(s.frames[0].result, link::SendResult::kBusy);
  EXPECT_EQ(s.frames[0].data, r.data);
  ASSERT_EQ(s.requests.size(), 1u);
  EXPECT_EQ(s.requests[0].text, "suspend");
  EXPECT_EQ(s.pauses, std::vector<std::int64_t>{1300});
  ASSERT_EQ(s.layers.size(), 1u);
  EXPECT_EQ(s.layers[0].text, "arm");
  ASSERT_EQ(s.states.size(), 1u);
  EXPECT_EQ(s.states[0].state, run::OpState::kNotEnabled);
  EXPECT_EQ(s.input_end, 400);
  ASSERT_TRUE(s.end);
  EXPECT_EQ(s.end->frames_sent, 9u);
  EXPECT_EQ(s.live_ticks(), 11 - 2);
}

// Who stopped and who reset: records of their own, read back in order.
TEST(Session, StopAndResetRecordsReadBack) {
  testing::TempDir dir;
  RecordChain chain;
  std::string text;
  SessionSettings settings;
  settings.robot = "HD1";
  settings.mapping_file = "/m/hd1.yaml";
  settings.rate_millihertz = 25'000;
  settings.sources = {{"/m/hd1.yaml", "robot: HD1\n"}};
  for (const auto& p :
       {payload::header(), payload::program("1.0"), payload::settings(settings),
        payload::stop(120, run::StopBy::kOperator, {"Pad A", "/dev/input/event5", "", "0300abcd"}),
        payload::stop(160, run::StopBy::kSupervisor, {"Pad \"B\"\xff", "", "S/N 7", ""}),
        payload::reset(2200, run::StopBy::kSupervisor, {"Pad \"B\"\xff", "", "S/N 7", ""}),
        std::string("stop 2300 operator \"Old pad\""), std::string("reset 2350 operator"),
        std::string("frame 60 2400 sent 0000182000908080000000010020CC02 gap=60"), payload::end(2400, 60, 60, "x")}) {
    text += chain.line(p);
  }
  EXPECT_EQ(
      payload::stop(120, run::StopBy::kOperator, {"Pad A", "/dev/input/event5", "", "0300abcd"}),
      "stop 120 operator {\"guid\":\"0300abcd\",\"name\":\"Pad A\",\"path\":\"/dev/input/event5\",\"serial\":\"\"}");
  // A name that is not UTF-8 is written escaped (never an exception that ends the run).
  EXPECT_EQ(payload::reset(2200, run::StopBy::kSupervisor, {"B\xff", "", "", ""}),
            "reset 2200 supervisor {\"guid\":\"\",\"name\":\"B\\\\xFF\",\"path\":\"\",\"serial\":\"\"}");
  const auto s = read_session(dir.write("r.andros-session", text));
  ASSERT_EQ(s.stops.size(), 5u);
  EXPECT_FALSE(s.stops[0].reset);
  EXPECT_EQ(s.stops[0].by, run::StopBy::kOperator);
  EXPECT_EQ(s.stops[0].name, "Pad A");
  EXPECT_EQ(s.stops[0].pad, (input::PadIdentity{"Pad A", "/dev/input/event5", "", "0300abcd"}));
  EXPECT_EQ(s.stops[1].by, run::StopBy::kSupervisor);
  EXPECT_EQ(s.stops[1].name, "Pad \"B\"\xff");  // the bytes the pad gave, back from their escapes
  EXPECT_EQ(s.stops[1].pad.serial, "S/N 7");
  EXPECT_TRUE(s.stops[2].reset);
  EXPECT_EQ(s.stops[2].t_ms, 2200);
  EXPECT_EQ(s.stops[2].by, run::StopBy::kSupervisor);
  EXPECT_TRUE(s.stops[1].pad.same_pad(s.stops[2].pad));
  // An earlier version's records: a stop's name alone, a reset with nothing.
  EXPECT_EQ(s.stops[3].name, "Old pad");
  EXPECT_TRUE(s.stops[4].reset);
  EXPECT_TRUE(s.stops[4].pad.empty());
}

/// The lines of a session whose settings record is made from `settings` and
/// then rewritten by edit, the way an older recorder wrote it.
std::string session_text(const std::string& header, const SessionSettings& settings,
                         const std::function<std::string(std::string)>& edit) {
  RecordChain chain;
  std::string text;
  for (const auto& p : {header, payload::program("0.1.0"), edit(payload::settings(settings)),
                        payload::end(80, 1, 1, "x")}) {  // tick 1 at 12.5 Hz
    text += chain.line(p);
  }
  return text;
}

SessionSettings small_settings() {
  SessionSettings s;
  s.robot = "HD1";
  s.mapping_file = "/m/hd1.yaml";
  s.rate_millihertz = 12'500;
  s.sources = {{"/m/hd1.yaml", "robot: HD1\n"}};
  return s;
}

// The rate is written in millihertz under a name that says so.
TEST(Session, TheRateIsWrittenInMillihertz) {
  const auto line = payload::settings(small_settings());
  EXPECT_NE(line.find("\"rate_millihertz\":12500"), std::string::npos) << line;
  EXPECT_EQ(line.find("rate_mhz"), std::string::npos) << line;
  EXPECT_EQ(payload::header(), "andros-session 4");
}

// Format 1 named the same value `rate_mhz`: such a session still reads back.
TEST(Session, AFormat1SessionReadsBack) {
  testing::TempDir dir;
  const auto old = session_text("andros-session 1", small_settings(), [](std::string payload) {
    payload.replace(payload.find("rate_millihertz"), std::string("rate_millihertz").size(), "rate_mhz");
    // Texts as format 1 wrote them: the JSON string of the text itself, not of its printable text.
    payload.replace(payload.find("robot: HD1\\\\n"), std::string("robot: HD1\\\\n").size(), "robot: HD1\\n");
    return payload;
  });
  ASSERT_NE(old.find("\"rate_mhz\":12500"), std::string::npos);
  EXPECT_TRUE(verify_session(dir.write("old.andros-session", old)).intact);
  EXPECT_EQ(read_session(dir.write("old.andros-session", old)).settings.rate_millihertz, 12'500);
}

TEST(Session, AFormatFromTheFutureIsRefused) {
  testing::TempDir dir;
  const auto text = session_text("andros-session 4", small_settings(), [](std::string p) { return p; });
  EXPECT_THROW(read_session(dir.write("new.andros-session", text)), InputError);
}

}  // namespace
}  // namespace andros::record
