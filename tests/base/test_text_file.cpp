// TextReader: the one bounded way text inputs are read.
#include "andros/base/text_file.hpp"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>

#include <string>
#include <vector>

#include "andros/base/error.hpp"
#include "support/input_error.hpp"
#include "support/temp_dir.hpp"

namespace andros {
namespace {

constexpr TextLimits kSmall{"test file", 32, 8};

std::vector<std::string> lines_of(TextReader& text) {
  std::vector<std::string> out;
  while (const auto line = text.next_line()) out.emplace_back(*line);
  return out;
}

std::string error_of(TextReader text) {
  return testing::input_error_text([&] { lines_of(text); });
}

TEST(TextReader, SplitsLinesWithOrWithoutAFinalNewline) {
  TextReader a("one\n\ntwo\r\nthree", "a", kSmall);
  EXPECT_EQ(lines_of(a), (std::vector<std::string>{"one", "", "two\r", "three"}));
  EXPECT_EQ(a.line_number(), 4);
  TextReader b("", "b", kSmall);
  EXPECT_TRUE(lines_of(b).empty());
}

TEST(TextReader, LineAndSizeLimitsAreInclusive) {
  EXPECT_EQ(error_of(TextReader("12345678\n", "f", kSmall)), "no error");
  EXPECT_EQ(error_of(TextReader("ok\n123456789\n", "f", kSmall)),
            "f:2: error: line longer than 8 bytes (the limit for a test file)");
  EXPECT_EQ(error_of(TextReader("ok\n123456789", "f", kSmall)),
            "f:2: error: line longer than 8 bytes (the limit for a test file)");
  // 32 bytes exactly, then one more line.
  const std::string full = "1234567\n1234567\n1234567\n1234567\n";
  EXPECT_EQ(error_of(TextReader(full, "f", kSmall)), "no error");
  EXPECT_EQ(error_of(TextReader(full + "x", "f", kSmall)),
            "f:5: error: more than 32 bytes (the limit for a test file)");
}

TEST(TextReader, NamesTheLimitsAsTheDocsDo) {
  EXPECT_EQ(format_size(64 * kKiB), "64 KiB");
  EXPECT_EQ(format_size(256 * kMiB), "256 MiB");
  EXPECT_EQ(format_size(1000), "1000 bytes");
}

TEST(TextReader, AFileReadsLikeTheSameTextInMemoryAndRewinds) {
  const testing::TempDir dir;
  const auto path = dir.write("f.txt", "a\nbb\nccc\n");
  auto file = TextReader::open(path.string(), kSmall);
  ASSERT_TRUE(file.can_rewind());
  EXPECT_EQ(lines_of(file), (std::vector<std::string>{"a", "bb", "ccc"}));
  file.rewind();
  EXPECT_EQ(lines_of(file), (std::vector<std::string>{"a", "bb", "ccc"}));
  EXPECT_EQ(file.line_number(), 3);
}

TEST(TextReader, RefusesADirectoryAndAMissingFile) {
  const testing::TempDir dir;
  try {
    (void)TextReader::open(dir.path().string(), kEventScriptLimits);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.message(), "is a directory, not an event script");
    EXPECT_EQ(e.pos().file, dir.path().string());
  }
  EXPECT_THROW((void)TextReader::open((dir.path() / "none").string(), kConfigLimits), InputError);
}

TEST(TextReader, AFifoWithNoWriterIsWaitedForUntilAStopRequest) {
  const testing::TempDir dir;
  const auto fifo = (dir.path() / "fifo").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  int asked = 0;
  auto text = TextReader::open(fifo, kSmall, [&asked] { return ++asked >= 3; });
  EXPECT_FALSE(text.can_rewind());
  EXPECT_THROW(lines_of(text), ReadStopped);
  EXPECT_EQ(asked, 3);
}

TEST(TextReader, APipeHeldOpenEndsOnAStopRequestAfterWhatWasWritten) {
  int fds[2];
  ASSERT_EQ(::pipe(fds), 0);
  ASSERT_EQ(::write(fds[1], "ab\ncd", 5), 5);
  bool stop = false;
  auto text = TextReader::open("/dev/fd/" + std::to_string(fds[0]), kSmall, [&stop] { return stop; });
  EXPECT_EQ(*text.next_line(), "ab");
  stop = true;  // "cd" has no newline yet and the writer stays: only a stop ends the wait
  EXPECT_THROW((void)text.next_line(), ReadStopped);
  ::close(fds[0]);
  ::close(fds[1]);
}

TEST(TextReader, HeldInMemoryAStreamCanBeRewound) {
  int fds[2];
  ASSERT_EQ(::pipe(fds), 0);
  ASSERT_EQ(::write(fds[1], "x\ny\n", 4), 4);
  ::close(fds[1]);
  auto text = hold_in_memory(TextReader::open("/dev/fd/" + std::to_string(fds[0]), kSmall));
  ::close(fds[0]);
  ASSERT_TRUE(text.can_rewind());
  EXPECT_EQ(lines_of(text), (std::vector<std::string>{"x", "y"}));
  text.rewind();
  EXPECT_EQ(lines_of(text), (std::vector<std::string>{"x", "y"}));
}

TEST(TextReader, OpenRegularRefusesAnythingButARegularFileWithoutWaiting) {
  const testing::TempDir dir;
  const auto refused = [](const std::string& path) {
    return testing::input_error_text([&] { (void)TextReader::open_regular(path, kConfigLimits); });
  };
  // A FIFO with no writer: open() would hand back a reader that waits for one.
  const auto fifo = (dir.path() / "fifo").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(refused(fifo), fifo + ": error: is a pipe, not a regular file");
  int fds[2];
  ASSERT_EQ(::pipe(fds), 0);  // --config <(...): a pipe, drained at start
  const auto pipe_path = "/dev/fd/" + std::to_string(fds[0]);
  EXPECT_EQ(refused(pipe_path), pipe_path + ": error: is a pipe, not a regular file");
  EXPECT_EQ(TextReader::open(pipe_path, kConfigLimits).kind(), "a pipe");
  ::close(fds[0]);
  ::close(fds[1]);
  EXPECT_EQ(refused("/dev/null"), "/dev/null: error: is a character device, not a regular file");
  EXPECT_EQ(refused(dir.path().string()), dir.path().string() + ": error: is a directory, not a regular file");
  const auto socket_path = (dir.path() / "sock").string();
  const int sock = ::socket(AF_UNIX, SOCK_STREAM, 0);
  sockaddr_un addr{};
  addr.sun_family = AF_UNIX;
  std::strncpy(addr.sun_path, socket_path.c_str(), sizeof addr.sun_path - 1);
  ASSERT_EQ(::bind(sock, reinterpret_cast<const sockaddr*>(&addr), sizeof addr), 0);
  EXPECT_EQ(refused(socket_path), socket_path + ": error: is a socket, not a regular file");
  ::close(sock);
  // A regular file, also behind a symbolic link, reads as open() reads it.
  const auto file = dir.write("a.conf", "x\n").string();
  std::filesystem::create_symlink(file, dir.path() / "link.conf");
  for (const auto& path : {file, (dir.path() / "link.conf").string()}) {
    auto text = TextReader::open_regular(path, kSmall);
    EXPECT_EQ(text.kind(), "a regular file");
    EXPECT_EQ(lines_of(text), (std::vector<std::string>{"x"}));
  }
  EXPECT_NE(refused((dir.path() / "none").string()).find("cannot read the config file"), std::string::npos);
}

TEST(TextReader, AnEndlessStreamStopsAtTheLineLimit) {
  auto text = TextReader::open("/dev/zero", kEventScriptLimits);
  EXPECT_EQ(error_of(std::move(text)), "/dev/zero:1: error: line longer than 4 KiB (the limit for an event script)");
}

}  // namespace
}  // namespace andros
