#include <fcntl.h>
#include <gtest/gtest.h>
#include <poll.h>
#include <unistd.h>

#include <spdlog/logger.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <string>

#include "andros/base/unique_fd.hpp"
#include "andros/view/log_sink.hpp"
#include "support/hostile_text.hpp"

namespace andros::view {
namespace {

struct Pipe {
  UniqueFd read;
  UniqueFd write;
};

Pipe make_pipe() {
  int fds[2];
  EXPECT_EQ(pipe2(fds, O_CLOEXEC), 0);
  return {UniqueFd(fds[0]), UniqueFd(fds[1])};
}

/// What arrives on fd within timeout_ms (until it has been quiet for 50 ms).
std::string drain(int fd, int timeout_ms) {
  std::string out;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeout_ms);
  while (std::chrono::steady_clock::now() < deadline) {
    pollfd p{fd, POLLIN, 0};
    if (poll(&p, 1, 50) != 1) {
      if (!out.empty()) break;
      continue;
    }
    char buf[4096];
    const long n = ::read(fd, buf, sizeof buf);
    if (n <= 0) break;
    out.append(buf, static_cast<std::size_t>(n));
  }
  return out;
}

/// Fills the pipe until a write would block, as a reader that stopped reading leaves it.
void fill(int fd) {
  const int flags = fcntl(fd, F_GETFL);
  fcntl(fd, F_SETFL, flags | O_NONBLOCK);
  const std::string chunk(4096, 'f');
  while (::write(fd, chunk.data(), chunk.size()) > 0) {
  }
  fcntl(fd, F_SETFL, flags);
}

TEST(FdLogSink, WritesLinesInOrder) {
  auto out = make_pipe();
  FdLogSink sink(out.write.get(), {});
  sink.write_line("one");
  sink.write_line("two");
  EXPECT_TRUE(sink.flush_for(2000));
  EXPECT_EQ(drain(out.read.get(), 2000), "one\ntwo\n");
  EXPECT_FALSE(sink.failed());
}

TEST(FdLogSink, TextFromOutsideIsShownOnOneLineNeverObeyed) {
  // A layer's name, a mapping's path, a link's detail, logged as they are:
  // each message is one line, with no control byte, invalid UTF-8 or bidi override in it.
  auto out = make_pipe();
  auto sink = std::make_shared<FdLogSink>(out.write.get(), FdLogSink::Options{});
  spdlog::logger logger("test", sink);
  logger.set_pattern("%l: %v");
  for (const auto& text : testing::kHostileTexts) logger.info("layer: {}", text);
  sink->write_line("andros-bridge: error: " + testing::kHostileTexts[0]);  // an error's what(), a path raw in it
  EXPECT_TRUE(sink->flush_for(2000));
  const auto lines = drain(out.read.get(), 2000);
  EXPECT_EQ(testing::raw_text_in(lines, true), std::nullopt);
  EXPECT_EQ(std::count(lines.begin(), lines.end(), '\n'), static_cast<long>(testing::kHostileTexts.size()) + 1)
      << lines;
  EXPECT_NE(lines.find("info: layer: x\\n2024-01-01"), std::string::npos) << lines;
  EXPECT_NE(lines.find("info: layer: rtl\\xE2\\x80\\xAEevil\n"), std::string::npos) << lines;
}

TEST(FdLogSink, AClosedReaderIsDroppedOnceWithANote) {
  // SIGPIPE keeps its default here: the writer thread blocks it, so the write fails with EPIPE.
  auto out = make_pipe();
  auto note = make_pipe();
  FdLogSink sink(out.write.get(), {.name = "the test pipe", .note_fd = note.write.get()});
  out.read.reset();  // the reader went away (`| head -1` exited)
  for (int i = 0; i < 100; ++i) sink.write_line("line " + std::to_string(i));
  EXPECT_TRUE(sink.flush_for(2000));
  EXPECT_TRUE(sink.failed());
  for (int i = 0; i < 10; ++i) sink.write_line("after");
  EXPECT_TRUE(sink.flush_for(2000));
  EXPECT_GE(sink.dropped(), 10u);
  const std::string said = drain(note.read.get(), 1000);
  EXPECT_EQ(said, "andros-bridge: log: the test pipe: Broken pipe; no more log lines go there\n");
}

TEST(FdLogSink, AReaderThatNeverReadsNeverBlocksTheCaller) {
  auto out = make_pipe();
  fill(out.write.get());
  FdLogSink sink(out.write.get(), {.max_lines = 16, .flush_wait_ms = 50});
  const std::string line(1000, 'x');
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < 10'000; ++i) sink.write_line(line);  // 10 MB into a 64 KB pipe nobody reads
  const auto took = std::chrono::steady_clock::now() - start;
  EXPECT_LT(took, std::chrono::seconds(5));  // generous: the point is that it returns at all
  EXPECT_FALSE(sink.flush_for(100));         // still stuck, and flush says so within its bound
  EXPECT_FALSE(sink.failed());
  EXPECT_GT(sink.dropped(), 9000u);
  // Reading again: the writer goes on, and says how many lines it dropped.
  const std::string got = drain(out.read.get(), 5000);
  EXPECT_NE(got.find("log lines dropped: standard error was not taking them"), std::string::npos);
}

TEST(FdLogSink, DestructionDoesNotWaitOnAStuckReader) {
  auto out = make_pipe();
  fill(out.write.get());
  const std::string line(4096, 'y');
  const auto start = std::chrono::steady_clock::now();
  {
    FdLogSink sink(out.write.get(), {.flush_wait_ms = 100});
    for (int i = 0; i < 100; ++i) sink.write_line(line);
  }
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
  // The writer thread, still stuck in write(), ends when the pipe is read or closed.
  drain(out.read.get(), 3000);
}

}  // namespace
}  // namespace andros::view
