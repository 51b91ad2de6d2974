// The recorder under a full disk and a file-size limit (run/record_sink.hpp,
// run/recorder.hpp): records are written whole or not at all, the file is cut
// back to its last whole record, and a `dropped N` record says what went
// missing where it fits; the chain stays intact.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <fstream>
#include <sstream>
#include <string>

#include "andros/record/recorder.hpp"
#include "support/temp_dir.hpp"

namespace andros::record {
namespace {

std::string file_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// A payload of about 100 bytes.
std::string event(int i) { return "event " + std::to_string(i * 40) + " axis lefty " + std::string(70, '1'); }

TEST(RecordLimits, AFileSizeLimitCutsBackToTheLastWholeRecordAndSaysWhatWasDropped) {
  testing::TempDir dir;
  const auto path = dir.path() / "limited.andros-session";
  // In a child: the limit is the process's own (`ulimit -f`).
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    std::signal(SIGXFSZ, SIG_IGN);  // as main() does
    const rlimit limit{10'000, 10'000};
    setrlimit(RLIMIT_FSIZE, &limit);
    SessionWriter writer(std::make_unique<FileRecordSink>(path.string()));
    writer.push(payload::header());
    for (int i = 0; i < 300; ++i) writer.push(event(i));
    writer.push(payload::end(12000, 300, 0, "end"));
    const bool whole = writer.close(5000);
    _exit(!whole && writer.lost() > 0 && writer.error() == "File too large" ? 0 : 3);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status)) << "the child ended by signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 0);
  const auto text = file_text(path);
  EXPECT_LE(text.size(), 10'000u);
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n');  // whole records only
  const auto result = verify_session(path);
  EXPECT_TRUE(result.intact) << result.problem;
  // The room kept for the last word: the records that say why, and the end, fit (issue 34).
  EXPECT_TRUE(result.closed) << text.substr(text.size() > 600 ? text.size() - 600 : 0);
  EXPECT_NE(text.find(" dropped "), std::string::npos) << "no dropped record";
  EXPECT_NE(text.find("\"File too large\""), std::string::npos) << "the dropped record does not say why";
}

/// A disk that is full for a while: two writes fail (the sink takes back what went out of them).
class FullForAWhileSink final : public RecordSink {
 public:
  explicit FullForAWhileSink(std::string& file) : file_(file) {}
  FullForAWhileSink(const FullForAWhileSink&) = delete;
  FullForAWhileSink& operator=(const FullForAWhileSink&) = delete;
  bool write(std::string_view text, std::string& error) override {
    ++writes_;
    if (writes_ == 2 || writes_ == 3) {  // full: the batch, then its first record alone, fail (taken back whole)
      error = "No space left on device";
      return false;
    }
    file_ += text;
    return true;
  }
  bool sync(std::string&) override { return true; }

 private:
  std::string& file_;
  int writes_ = 0;
};

TEST(RecordLimits, AfterAFailedWriteTheChainGoesOnFromTheLastWholeRecordWithADroppedRecord) {
  testing::TempDir dir;
  // A writer that fails its second write, then writes again.
  std::string text;
  auto sink = std::make_unique<FullForAWhileSink>(text);
  SessionWriter writer(std::move(sink));
  writer.push(payload::header());
  // Let the first write happen on its own before the rest come.
  for (int spin = 0; spin < 5000 && writer.written() == 0; ++spin) usleep(1000);
  ASSERT_EQ(writer.written(), 1u);
  for (int i = 0; i < 5; ++i) writer.push(event(i));
  for (int spin = 0; spin < 5000 && writer.lost() == 0; ++spin) usleep(1000);
  writer.push(payload::end(200, 5, 0, "end"));
  EXPECT_FALSE(writer.close(5000));
  EXPECT_EQ(writer.error(), "No space left on device");
  const auto path = dir.write("s.andros-session", text);
  const auto result = verify_session(path);
  EXPECT_TRUE(result.intact) << result.problem << "\n" << text;
  EXPECT_TRUE(result.closed);
  // The records lost are said where they went missing, before the end.
  EXPECT_NE(text.find(" dropped " + std::to_string(writer.lost()) + " "), std::string::npos) << text;
}

/// A sink that keeps what it is given.
class MemorySink final : public RecordSink {
 public:
  explicit MemorySink(std::string& text) : text_(text) {}
  MemorySink(const MemorySink&) = delete;
  MemorySink& operator=(const MemorySink&) = delete;
  bool write(std::string_view text, std::string&) override {
    text_ += text;
    return true;
  }
  bool sync(std::string&) override { return true; }

 private:
  std::string& text_;
};

TEST(RecordLimits, OneStopRequestIsOneRecordHoweverManyTicksAnswerIt) {
  std::string text;
  {
    SessionWriter writer(std::make_unique<MemorySink>(text));
    Recorder recorder(writer);
    recorder.pumped(40, {});
    recorder.request(run::Request::kShutdown);  // Ctrl-C: the stop is asked again on each tick of the shutdown
    recorder.pumped(80, {});
    recorder.request(run::Request::kShutdown);
    recorder.pumped(120, {});
    recorder.request(run::Request::kShutdown);
    recorder.request(run::Request::kReload);
    writer.close(5000);
  }
  EXPECT_EQ(text.find("request 80"), std::string::npos) << text;
  EXPECT_NE(text.find(" request 40 stop "), std::string::npos) << text;
  EXPECT_NE(text.find(" request 120 reload "), std::string::npos) << text;
}

TEST(RecordLimits, ARecordLongerThanAReaderTakesIsDroppedNotWritten) {
  std::string text;
  SessionWriter writer(std::make_unique<MemorySink>(text));
  EXPECT_TRUE(writer.push(payload::header()));
  EXPECT_FALSE(writer.push("settings " + std::string(kMaxSessionLine, 'x')));
  EXPECT_EQ(writer.dropped(), 1u);
  writer.close(5000);
  EXPECT_NE(text.find(" dropped 1 "), std::string::npos) << text.substr(0, 200);
  EXPECT_LT(text.size(), std::size_t{1000});
}

}  // namespace
}  // namespace andros::record
