// The one reading of a session (andros/record/session.hpp,
// read_checked_session): what the chain vouches for is what every command
// reads. A last line without its newline, NUL bytes after the last record and
// records after the chain breaks are never data; an end record holds no more
// than the session can; a session whose records say the disk filled is said
// so; what is not a regular file is refused at once.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "andros/base/error.hpp"
#include "andros/record/session.hpp"
#include "support/session_head.hpp"
#include "support/temp_dir.hpp"

namespace andros::record {
namespace {

const std::string kNoWeapon = "0600182000908080000000010020CC02";
const std::string kWeapon1 = "0600182100908080000000010020CC02";  // byte 3 bit 0: weapon_1

/// A drive's payloads to tick 15 at 25 Hz, enabled from 120 ms, not closed.
std::vector<std::string> drive_payloads() {
  auto out = testing::session_head();
  for (const auto& p : {"frame 0 0 sent " + kNoWeapon + " gap=0", std::string("state 120 enabled"),
                        "frame 15 600 sent " + kNoWeapon + " gap=0"})
    out.push_back(p);
  return out;
}

/// payloads chained; the last without its newline when `ended` is false.
std::filesystem::path write_chained(const testing::TempDir& dir, const std::vector<std::string>& payloads,
                                    bool ended = true, const std::string& tail = "") {
  RecordChain chain;
  std::string text;
  for (const auto& p : payloads) text += chain.line(p);
  if (!ended) text.pop_back();
  return dir.write("d.andros-session", text + tail);
}

std::vector<std::string> with(std::vector<std::string> payloads, const std::vector<std::string>& more) {
  payloads.insert(payloads.end(), more.begin(), more.end());
  return payloads;
}

std::string unreadable_text(const CheckedSession& checked) {
  return checked.unreadable ? checked.unreadable->what() : "";
}

// A whole record, chained, but without its newline: a write cut off, never
// data, whatever it says (the issue's forged partial lines).
TEST(SessionReading, ALastLineWithoutItsNewlineIsNeverData) {
  testing::TempDir dir;
  const auto base = drive_payloads();
  for (const auto& forged : {"frame 16 640 sent " + kWeapon1 + " gap=0",
                             std::string(R"(stop 640 supervisor {"name":"boss","path":"","serial":"","guid":""})"),
                             payload::end(9000, 225, 226, "end of the input")}) {
    const auto path = write_chained(dir, with(base, {forged}), false);
    const auto result = verify_session(path);
    EXPECT_TRUE(result.intact) << result.problem;
    EXPECT_EQ(result.cut_short_line, 8) << forged;
    EXPECT_EQ(result.records, 7u) << forged;
    EXPECT_FALSE(result.closed) << forged;
    const auto s = read_session(path);
    EXPECT_EQ(s.frames.size(), 2u) << forged;
    EXPECT_TRUE(s.stops.empty()) << forged;
    EXPECT_FALSE(s.end) << forged;
    EXPECT_EQ(s.frames_sent(), 16u) << forged;
  }
}

TEST(SessionReading, RecordsAfterTheChainBreaksAreNotData) {
  testing::TempDir dir;
  auto path = write_chained(dir, with(drive_payloads(), {"frame 16 640 sent " + kNoWeapon + " gap=0"}));
  // The frame at tick 15 given a weapon bit, its hash left: the chain breaks there.
  std::string text;
  {
    std::ifstream in(path);
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  text.replace(text.find("frame 15 600 sent " + kNoWeapon), 18 + kNoWeapon.size(), "frame 15 600 sent " + kWeapon1);
  path = dir.write("d.andros-session", text);
  const auto checked = read_checked_session(path);
  EXPECT_FALSE(checked.verdict.intact);
  EXPECT_EQ(checked.verdict.problem, "record 6 (line 7) altered: its content or hash no longer matches the chain");
  ASSERT_TRUE(checked.session) << unreadable_text(checked);
  ASSERT_EQ(checked.session->frames.size(), 1u);  // the records before the break
  EXPECT_EQ(read_session(path).frames.size(), 1u);
}

TEST(SessionReading, NulBytesAfterAClosedSessionLeaveItClosed) {
  testing::TempDir dir;
  const auto path =
      write_chained(dir, with(drive_payloads(), {payload::end(600, 15, 16, "SIGINT")}), true, std::string(4096, '\0'));
  const auto checked = read_checked_session(path);
  EXPECT_TRUE(checked.verdict.intact) << checked.verdict.problem;
  EXPECT_TRUE(checked.verdict.closed);
  EXPECT_EQ(checked.verdict.cut_short_line, 0);
  EXPECT_EQ(checked.verdict.nul_tail, 4096u);
  EXPECT_EQ(closing_text(checked),
            "closed: the run ended and its last record is here; 4096 NUL bytes after it (blocks a power loss left "
            "unwritten)");
  // Not closed, with NUL bytes after: still not closed.
  const auto open = read_checked_session(write_chained(dir, drive_payloads(), true, std::string(100, '\0')));
  EXPECT_FALSE(open.verdict.closed);
  EXPECT_EQ(open.verdict.nul_tail, 100u);
}

TEST(SessionReading, AnEndHoldsNoMoreThanTheSession) {
  testing::TempDir dir;
  const auto header = testing::session_head();
  // Before the first tick: tick -1 at 0 ms, no frames.
  EXPECT_TRUE(read_checked_session(write_chained(dir, with(header, {payload::end(0, -1, 0, "SIGINT")}))).session);
  for (const auto& end : {payload::end(9'000'000'000'000'000, -1, 0, "SIGINT"),
                          payload::end(0, -1, 5'000'000'000, "SIGINT"), payload::end(-1, -1, 0, "SIGINT")}) {
    const auto checked = read_checked_session(write_chained(dir, with(header, {end})));
    EXPECT_FALSE(checked.session) << end;
    ASSERT_TRUE(checked.unreadable) << end;
    EXPECT_EQ(checked.unreadable->pos().line, 5) << end;
  }
  // More frames than ticks 0 through the last.
  const auto many = read_checked_session(write_chained(dir, with(drive_payloads(), {payload::end(600, 15, 17, "x")})));
  EXPECT_EQ(unreadable_text(many), dir.path().string() +
                                       "/d.andros-session:8: error: 17 frames sent: not within a session that ended "
                                       "at tick 15 (at most 16)");
  EXPECT_TRUE(
      read_checked_session(write_chained(dir, with(drive_payloads(), {payload::end(600, 15, 16, "x")}))).session);
}

TEST(SessionReading, ASessionWhoseRecordsSayTheDiskFilledIsSaidSo) {
  testing::TempDir dir;
  const auto room = [&](const std::vector<std::string>& more) {
    return read_checked_session(write_chained(dir, with(drive_payloads(), more)));
  };
  const std::string stopped = "recording stopped at tick 15: the disk was full or a file-size limit was reached";
  // The last record a `dropped` one, with a reason or without: nothing could be written after it.
  // WHY as the writer says it (strerror()): a full disk, a file-size limit.
  for (const auto& last : {"dropped 3", "dropped 3 \"No space left on device\"", "dropped 12 \"File too large\""}) {
    const auto checked = room({last});
    ASSERT_TRUE(checked.session) << unreadable_text(checked);
    EXPECT_EQ(checked.session->stopped_for_room, 15) << last;
    EXPECT_EQ(closing_text(checked), "not closed: " + stopped) << last;
  }
  EXPECT_EQ(room({"dropped 3 \"No space left on device\""}).session->dropped_why, "No space left on device");
  // A reason of want of room, then records the writer still got in.
  EXPECT_EQ(room({"dropped 3 \"File too large\"", "state 640 not enabled"}).session->stopped_for_room, 15);
  // Records dropped, then more: not closed for another reason (a crash, the power); so too
  // the last record a `dropped` one for a reason that is not room (a queue full).
  for (const auto& more : std::vector<std::vector<std::string>>{
           {"dropped 3", "state 640 not enabled"}, {"dropped 2 \"the queue was full: the disk did not keep up\""}}) {
    const auto crash = room(more);
    EXPECT_FALSE(crash.session->stopped_for_room) << more.back();
    EXPECT_EQ(closing_text(crash).find("not closed: the run is still going"), 0u) << closing_text(crash);
  }
  // Closed (the writer keeps room for its last word): said all the same, the end after it.
  const auto closed = room({"dropped 3 \"No space left on device\"", payload::end(600, 15, 16, "SIGINT")});
  EXPECT_EQ(closed.session->stopped_for_room, 15);
  EXPECT_EQ(closing_text(closed), "closed: the run ended and its last record is here; " + stopped);
  // With no reason, records that go on to the end are not a stop for want of room.
  EXPECT_FALSE(room({"dropped 3", payload::end(600, 15, 16, "SIGINT")}).session->stopped_for_room);
}

// verify keeps one frame record at a time (Keep::kVerdict), the other
// readers them all: the rule that a frame record stands for 60 s at most is
// the same verdict for both, between two frame records and before the end.
TEST(SessionReading, FrameRecordsTooFarApartAreTheSameVerdictForEveryReader) {
  testing::TempDir dir;
  const auto far_frame = with(drive_payloads(), {"frame 1600 64000 sent " + kNoWeapon + " gap=0",
                                                 "frame 1601 64040 sent " + kWeapon1 + " gap=0"});
  const auto far_end = with(drive_payloads(), {payload::end(64000, 1600, 1601, "SIGINT")});
  for (const auto& payloads : {far_frame, far_end}) {
    const auto path = write_chained(dir, payloads);
    const auto all = read_checked_session(path, Keep::kRecords);
    const auto verdict = read_checked_session(path, Keep::kVerdict);
    ASSERT_TRUE(all.unreadable) << payloads.back();
    ASSERT_TRUE(verdict.unreadable) << payloads.back();
    EXPECT_EQ(unreadable_text(verdict), unreadable_text(all));
    EXPECT_NE(unreadable_text(all).find("ms after the frame record it repeats (line 7)"), std::string::npos)
        << unreadable_text(all);
  }
  // Records dropped waive the rule (the record may be the one dropped), for both.
  const auto path = write_chained(dir, with(far_frame, {"dropped 4 \"No space left on device\""}));
  EXPECT_FALSE(read_checked_session(path, Keep::kRecords).unreadable);
  EXPECT_FALSE(read_checked_session(path, Keep::kVerdict).unreadable)
      << unreadable_text(read_checked_session(path, Keep::kVerdict));
}

TEST(SessionReading, WhatIsNotARegularFileIsRefusedAtOnceSayingWhatItIs) {
  testing::TempDir dir;
  const auto fifo = dir.path() / "f.andros-session";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  try {
    (void)read_checked_session(fifo);
    ADD_FAILURE() << "a FIFO was read";
  } catch (const InputError& e) {
    EXPECT_EQ(e.message(), "is a FIFO, not a session file");
  }
  std::filesystem::create_directory(dir.path() / "d.andros-session");
  EXPECT_THROW(verify_session(dir.path() / "d.andros-session"), InputError);
  try {
    require_session_file("/dev/null");
    ADD_FAILURE() << "/dev/null taken for a session";
  } catch (const InputError& e) {
    EXPECT_EQ(e.message(), "is a character device, not a session file");
  }
}

}  // namespace
}  // namespace andros::record
