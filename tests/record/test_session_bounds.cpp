// Reading a session honestly and within bounds (run/session.hpp): half a
// record at the end is a run cut short, not tampering; a line is refused
// past kMaxSessionLine while it is read; ticks and times are checked against
// what a session holds, at the record that breaks them.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "andros/base/error.hpp"
#include "andros/base/text_file.hpp"
#include "andros/record/session.hpp"
#include "support/session_head.hpp"
#include "support/temp_dir.hpp"

namespace andros::record {
namespace {

const std::string kData(32, '0');  // 16 data bytes, as a frame record holds them

/// Payloads of a small session that read_session takes: 25 Hz, hd1's text.
std::vector<std::string> payloads(const std::string& end = payload::end(400, 10, 11, "SIGINT")) {
  auto out = testing::session_head();
  for (const auto& p : {"frame 0 0 sent " + kData + " gap=0", std::string("state 0 not enabled"),
                        "frame 4 160 sent " + std::string(31, '0') + "1 gap=0", end})
    out.push_back(p);
  return out;
}

/// The chained lines of payloads, each with its newline.
std::vector<std::string> chained(const std::vector<std::string>& payloads) {
  RecordChain chain;
  std::vector<std::string> out;
  for (const auto& p : payloads) out.push_back(chain.line(p));
  return out;
}

std::filesystem::path write(const testing::TempDir& dir, const std::vector<std::string>& lines,
                            const std::string& tail = "") {
  std::string text;
  for (const auto& l : lines) text += l;
  return dir.write("s.andros-session", text + tail);
}

int error_line(const std::filesystem::path& path) {
  try {
    (void)read_session(path);
  } catch (const InputError& e) {
    return e.pos().line;
  }
  return 0;
}

std::string error_text(const std::filesystem::path& path) {
  try {
    (void)read_session(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SessionBounds, HalfARecordAtTheEndIsACutNotAnAlteration) {
  testing::TempDir dir;
  auto lines = chained(payloads());
  lines.back() = lines.back().substr(0, lines.back().size() / 2);  // the write cut off mid-record
  const auto path = write(dir, lines);
  const auto result = verify_session(path);
  EXPECT_TRUE(result.intact) << result.problem;
  EXPECT_EQ(result.cut_short_line, 8);
  EXPECT_EQ(result.records, 7u);
  EXPECT_FALSE(result.closed);
  EXPECT_EQ(cut_short_text(result),
            "cut short at line 8: the run was cut off, power lost or disk full; the 7 records before it are intact");
  // Read, listed and plotted from what is there.
  const auto s = read_session(path);
  EXPECT_EQ(s.cut_short_line, 8);
  EXPECT_EQ(s.frames.size(), 2u);
  EXPECT_FALSE(s.end);
  EXPECT_EQ(s.frames_sent(), 5u);  // ticks 0..3 as recorded at 0, then tick 4
}

TEST(SessionBounds, BlocksAPowerLossLeftUnwrittenAreNotRecords) {
  testing::TempDir dir;
  const auto path = write(dir, chained(payloads()), std::string(4096, '\0'));
  const auto result = verify_session(path);
  EXPECT_TRUE(result.intact) << result.problem;
  EXPECT_EQ(result.nul_tail, 4096u);
  EXPECT_TRUE(result.closed);  // its end record is there (test_session_reading.cpp)
}

TEST(SessionBounds, AnAlteredLastRecordWithItsNewlineIsStillAltered) {
  testing::TempDir dir;
  auto lines = chained(payloads());
  lines.back()[lines.back().find("SIGINT")] = 'X';
  const auto result = verify_session(write(dir, lines));
  EXPECT_FALSE(result.intact);
  EXPECT_EQ(result.cut_short_line, 0);
  EXPECT_EQ(result.problem, "record 7 (line 8) altered: its content or hash no longer matches the chain");
}

TEST(SessionBounds, AHalfLineInTheMiddleIsAnAlteration) {
  testing::TempDir dir;
  auto lines = chained(payloads());
  lines[5] = lines[5].substr(0, 20) + "\n";
  const auto result = verify_session(write(dir, lines));
  EXPECT_FALSE(result.intact);
  EXPECT_EQ(result.problem, "record 5 (line 6) altered: not a record line");
}

TEST(SessionBounds, ALineLongerThanTheCapIsRefusedWhileItIsRead) {
  testing::TempDir dir;
  // 300 MB of one line, sparse on the disk: read no further than the cap.
  const auto path = write(dir, {chained(payloads())[0]});
  ASSERT_EQ(::truncate(path.c_str(), 300'000'000), 0);
  VerifyResult result;
  ASSERT_NO_THROW(result = verify_session(path));
  EXPECT_FALSE(result.intact);
  EXPECT_EQ(result.problem,
            "record 1 (line 2) altered: line longer than 4 MiB (the limit for a session), longer "
            "than any record");
  EXPECT_EQ(error_line(path), 2);
}

TEST(SessionBounds, AnEndTickFarPastTheLastFrameIsAnErrorAtItsLine) {
  testing::TempDir dir;
  // One number edited, the chain made again.
  const auto edited = write(dir, chained(payloads(payload::end(400, 100'000'000'000, 11, "SIGINT"))));
  EXPECT_EQ(error_line(edited), 8);
  EXPECT_NE(error_text(edited).find("tick 100000000000: not within a session"), std::string::npos)
      << error_text(edited);
  // Its time edited to match: still past what a session holds.
  const auto both = write(dir, chained(payloads(payload::end(4'000'000'000'000, 100'000'000'000, 11, "SIGINT"))));
  EXPECT_EQ(error_line(both), 8);
  // Within a day, a tick that does not fall at its time.
  const auto astray = write(dir, chained(payloads(payload::end(400, 2'000'000, 11, "SIGINT"))));
  EXPECT_NE(error_text(astray).find("tick 2000000 falls at 80000000 ms at 25 Hz, not 400"), std::string::npos)
      << error_text(astray);
  // Before the last frame record.
  const auto early = write(dir, chained(payloads(payload::end(120, 3, 11, "SIGINT"))));
  EXPECT_NE(error_text(early).find("before the last frame record's"), std::string::npos) << error_text(early);
}

TEST(SessionBounds, FrameRecordsAreCheckedAgainstTheirRateAndGaps) {
  testing::TempDir dir;
  auto p = payloads();
  p[6] = "frame 4 161 sent " + kData + " gap=0";
  EXPECT_EQ(error_line(write(dir, chained(p))), 7);
  p[6] = "frame 4 160 sent " + kData + " gap=4";  // skipped ticks 0..3, but tick 0 ran
  EXPECT_EQ(error_line(write(dir, chained(p))), 7);
  p[6] = "state 99999999999 enabled";
  EXPECT_EQ(error_line(write(dir, chained(p))), 7);
  p = payloads();
  p[3] = "settings " + std::string(R"({"robot":"HD1","mapping":"m","rate_millihertz":1,"weapons":false,)") +
         R"("code":"00","center":128,"port":"p","baud":9600,"input":"i","config":"","files":[{"path":"m",)" +
         R"("sha256":"2d711642b726b04401627ca9fbac32f5c8530fb1903cc4db02258717921a4881","text":"x"}]})";
  EXPECT_EQ(error_line(write(dir, chained(p))), 4);
}

}  // namespace
}  // namespace andros::record
