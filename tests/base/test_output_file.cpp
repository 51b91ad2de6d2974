// OutputFile: the one way a command writes its output file.
#include "andros/base/output_file.hpp"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/un.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "andros/base/error.hpp"
#include "support/temp_dir.hpp"

namespace andros {
namespace {

namespace fs = std::filesystem;
using testing::TempDir;

std::string read_all(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::string> names_in(const fs::path& folder) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(folder)) out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

/// What the code throws as a RuntimeError, or "no error".
template <typename Action>
std::string runtime_error_text(Action&& action) {
  try {
    action();
  } catch (const RuntimeError& e) {
    return e.what();
  }
  return "no error";
}

mode_t mode_of(const fs::path& file) {
  struct stat st {};
  EXPECT_EQ(::lstat(file.c_str(), &st), 0) << file;
  return st.st_mode;
}

// A disk that fills after the first few bytes.
int full_disk(int fd, std::string_view text) {
  if (text.size() > 4 && ::write(fd, text.data(), 4) != 4) return EIO;
  return ENOSPC;
}

bool root() { return ::geteuid() == 0; }

TEST(OutputFile, ANewFileGetsTheTextAndTheUsualModeAndNoTemporaryIsLeft) {
  TempDir dir;
  const auto file = dir.path() / "sheet.svg";
  write_output_file(file.string(), "page");
  EXPECT_EQ(read_all(file), "page");
  const mode_t mask = ::umask(0);
  ::umask(mask);
  EXPECT_EQ(mode_of(file) & 07777, 0666 & ~mask);
  EXPECT_EQ(names_in(dir.path()), std::vector<std::string>{"sheet.svg"});
}

TEST(OutputFile, AnOldFileIsReplacedWholeAndKeepsItsMode) {
  TempDir dir;
  const auto file = dir.write("frames.txt", "old frames\n");
  fs::permissions(file, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  OutputFile out(file.string());
  out.write("new ");
  EXPECT_EQ(read_all(file), "old frames\n") << "the old file stays whole until commit";
  out.write("frames\n");
  out.commit();
  EXPECT_EQ(read_all(file), "new frames\n");
  EXPECT_EQ(mode_of(file) & 07777, 0640);
  EXPECT_EQ(names_in(dir.path()), std::vector<std::string>{"frames.txt"});
}

TEST(OutputFile, AFullDiskLeavesTheOldFileAndRemovesTheTemporary) {
  TempDir dir;
  const auto file = dir.write("sheet.svg", "the good old sheet");
  const auto error = runtime_error_text([&] { write_output_file(file.string(), std::string(100, 'x'), full_disk); });
  EXPECT_EQ(error, "cannot write '" + file.string() + "': No space left on device");
  EXPECT_EQ(read_all(file), "the good old sheet");
  EXPECT_EQ(names_in(dir.path()), std::vector<std::string>{"sheet.svg"});
}

TEST(OutputFile, AFullDiskMakesNoNewFile) {
  TempDir dir;
  const auto file = dir.path() / "new.svg";
  EXPECT_NE(runtime_error_text([&] { write_output_file(file.string(), "x", full_disk); }), "no error");
  EXPECT_TRUE(names_in(dir.path()).empty());
}

TEST(OutputFile, AStreamThatFailsEndsInAnErrorWithTheReasonAtCommit) {
  TempDir dir;
  const auto file = dir.write("frames.jsonl", "old\n");
  OutputFile out(file.string(), full_disk);
  out.stream() << "a frame" << std::flush;
  EXPECT_FALSE(out.stream().good());
  EXPECT_EQ(runtime_error_text([&] { out.commit(); }), "cannot write '" + file.string() + "': No space left on device");
  EXPECT_EQ(read_all(file), "old\n");
}

TEST(OutputFile, LeftWithoutCommitTheOldFileStaysAndTheTemporaryGoes) {
  TempDir dir;
  const auto file = dir.write("events.txt", "old events\n");
  {
    OutputFile out(file.string());
    out.write("half a recording");
    EXPECT_TRUE(out.flush());
    EXPECT_EQ(names_in(dir.path()).size(), 2U) << "a temporary beside it";
  }
  EXPECT_EQ(read_all(file), "old events\n");
  EXPECT_EQ(names_in(dir.path()), std::vector<std::string>{"events.txt"});
}

TEST(OutputFile, ALiveOutputMakesANewFileAsWrittenButReplacesAnOldOneOnlyAtCommit) {
  TempDir dir;
  const auto fresh = dir.path() / "new.events";
  {
    OutputFile out(fresh.string(), nullptr, OutputFile::NewFile::kAsWritten);
    out.write("0 connect pad\n");
    ASSERT_TRUE(out.flush());
    EXPECT_EQ(read_all(fresh), "0 connect pad\n") << "a killed recording keeps what it saw";
  }
  const auto old = dir.write("old.events", "old\n");
  OutputFile out(old.string(), nullptr, OutputFile::NewFile::kAsWritten);
  out.write("new\n");
  ASSERT_TRUE(out.flush());
  EXPECT_EQ(read_all(old), "old\n");
  out.commit();
  EXPECT_EQ(read_all(old), "new\n");
}

TEST(OutputFile, ASymlinkIsFollowedItsTargetReplacedAndTheLinkKept) {
  TempDir dir;
  fs::create_directory(dir.path() / "real");
  const auto target = dir.write("real/out.txt", "old");
  fs::create_symlink("real/out.txt", dir.path() / "link.txt");
  write_output_file((dir.path() / "link.txt").string(), "new");
  EXPECT_TRUE(fs::is_symlink(dir.path() / "link.txt"));
  EXPECT_EQ(fs::read_symlink(dir.path() / "link.txt"), "real/out.txt");
  EXPECT_EQ(read_all(target), "new");
  EXPECT_EQ(names_in(dir.path() / "real"), std::vector<std::string>{"out.txt"});
}

TEST(OutputFile, ADanglingSymlinkHasItsTargetWritten) {
  TempDir dir;
  fs::create_symlink(dir.path() / "to-be.txt", dir.path() / "link.txt");
  write_output_file((dir.path() / "link.txt").string(), "made");
  EXPECT_TRUE(fs::is_symlink(dir.path() / "link.txt"));
  EXPECT_EQ(read_all(dir.path() / "to-be.txt"), "made");
}

TEST(OutputFile, AFifoIsWrittenInPlaceAndStaysAFifo) {
  TempDir dir;
  const auto fifo = dir.path() / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(reader, 0);
  write_output_file(fifo.string(), "through");
  char buf[16] = {};
  EXPECT_EQ(::read(reader, buf, sizeof buf), 7);
  EXPECT_EQ(std::string(buf), "through");
  ::close(reader);
  EXPECT_TRUE(S_ISFIFO(mode_of(fifo)));
  EXPECT_EQ(names_in(dir.path()), std::vector<std::string>{"pipe"});
}

TEST(OutputFile, ASocketIsNeverReplacedOrRemoved) {
  TempDir dir;
  const auto path = dir.path() / "sock";
  const int s = ::socket(AF_UNIX, SOCK_STREAM, 0);
  sockaddr_un addr{};
  addr.sun_family = AF_UNIX;
  std::snprintf(addr.sun_path, sizeof addr.sun_path, "%s", path.c_str());
  ASSERT_EQ(::bind(s, reinterpret_cast<sockaddr*>(&addr), sizeof addr), 0);
  EXPECT_EQ(runtime_error_text([&] { write_output_file(path.string(), "x"); }),
            "cannot open '" + path.string() + "' for writing: No such device or address");
  EXPECT_TRUE(S_ISSOCK(mode_of(path)));
  ::close(s);
}

TEST(OutputFile, ADeviceNodeIsWrittenInPlaceAndAFullOneIsKept) {
  if (!root()) GTEST_SKIP() << "mknod needs root";
  TempDir dir;
  const auto null = dir.path() / "null";
  const auto full = dir.path() / "full";
  ASSERT_EQ(::mknod(null.c_str(), S_IFCHR | 0666, makedev(1, 3)), 0);
  ASSERT_EQ(::mknod(full.c_str(), S_IFCHR | 0666, makedev(1, 7)), 0);
  write_output_file(null.string(), "gone");
  EXPECT_TRUE(S_ISCHR(mode_of(null)));
  EXPECT_EQ(runtime_error_text([&] { write_output_file(full.string(), "x"); }),
            "cannot write '" + full.string() + "': No space left on device");
  EXPECT_TRUE(S_ISCHR(mode_of(full)));
  EXPECT_EQ(names_in(dir.path()), (std::vector<std::string>{"full", "null"}));
}

TEST(OutputFile, TheOwnerIsKeptWhenThatIsAllowed) {
  if (!root()) GTEST_SKIP() << "giving a file to another owner needs root";
  TempDir dir;
  const auto file = dir.write("hd1.yaml", "old");
  ASSERT_EQ(::chown(file.c_str(), 1234, 5678), 0);
  write_output_file(file.string(), "new");
  struct stat st {};
  ASSERT_EQ(::stat(file.c_str(), &st), 0);
  EXPECT_EQ(st.st_uid, 1234U);
  EXPECT_EQ(st.st_gid, 5678U);
}

TEST(OutputFile, AFolderOrAMissingFolderIsRefusedWithTheReason) {
  TempDir dir;
  EXPECT_EQ(runtime_error_text([&] { write_output_file(dir.path().string(), "x"); }),
            "cannot open '" + dir.path().string() + "' for writing: Is a directory");
  const auto missing = dir.path() / "no" / "such.svg";
  EXPECT_EQ(runtime_error_text([&] { write_output_file(missing.string(), "x"); }),
            "cannot open '" + missing.string() + "' for writing: No such file or directory");
}

TEST(OutputFile, AReadOnlyFolderLeavesTheOldFileWithTheReason) {
  if (root()) GTEST_SKIP() << "root writes into a read-only folder (tests/cli/test_output_files.sh runs it as nobody)";
  TempDir dir;
  fs::create_directory(dir.path() / "ro");
  const auto file = dir.write("ro/sheet.svg", "old");
  fs::permissions(dir.path() / "ro", fs::perms::owner_read | fs::perms::owner_exec);
  EXPECT_EQ(runtime_error_text([&] { write_output_file(file.string(), "new"); }),
            "cannot open '" + file.string() + "' for writing: Permission denied");
  fs::permissions(dir.path() / "ro", fs::perms::owner_all);
  EXPECT_EQ(read_all(file), "old");
}

TEST(OutputFile, DashIsStandardOutputNeverAFileNamedDash) {
  TempDir dir;
  const auto captured = dir.path() / "stdout";
  std::fflush(stdout);
  const int saved = ::dup(STDOUT_FILENO);
  const int fd = ::open(captured.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  ASSERT_GE(fd, 0);
  ::dup2(fd, STDOUT_FILENO);
  ::close(fd);
  const auto cwd = fs::current_path();
  fs::current_path(dir.path());
  write_output_file("-", "to stdout");
  fs::current_path(cwd);
  ::dup2(saved, STDOUT_FILENO);
  ::close(saved);
  EXPECT_EQ(read_all(captured), "to stdout");
  EXPECT_FALSE(fs::exists(dir.path() / "-"));
}

TEST(OutputFile, ALongPathIsNamedWholeInTheError) {
  TempDir dir;
  const auto file = dir.path() / (std::string(120, 'a') + "-the-part-that-matters") / "x.svg";
  const auto error = runtime_error_text([&] { write_output_file(file.string(), "x"); });
  EXPECT_NE(error.find("-the-part-that-matters/x.svg'"), std::string::npos) << error;
}

}  // namespace
}  // namespace andros
