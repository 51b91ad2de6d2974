// The flight recorder's folder (src/cli/session_files.hpp): where it is,
// session names, and rotation by total size and age.
#include <gtest/gtest.h>
#include <utime.h>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <string>

#include "andros/base/unique_fd.hpp"
#include "andros/record/record_sink.hpp"
#include "cli/session_files.hpp"
#include "support/temp_dir.hpp"

namespace andros::cli {
namespace {

namespace fs = std::filesystem;

/// A session (its first line says so) of size bytes last written at mtime.
fs::path make_session(const testing::TempDir& dir, const std::string& name, std::size_t size, std::time_t mtime,
                      const std::string& first_line = "0 andros-session 2 " + std::string(64, '0') + "\n") {
  std::string text = first_line;
  text.resize(std::max(size, text.size()), 'x');
  const auto path = dir.write(name + ".andros-session", text);
  utimbuf times{mtime, mtime};
  utime(path.c_str(), &times);
  return path;
}

std::uint64_t total_size(const fs::path& dir) {
  std::uint64_t total = 0;
  for (const auto& p : list_sessions(dir)) total += fs::file_size(p);
  return total;
}

constexpr std::time_t kNow = 1'700'000'000;
constexpr std::int64_t kDay = 24 * 3600;

TEST(SessionFiles, RotationKeepsTheTotalUnderItsCapRemovingTheOldestFirst) {
  testing::TempDir dir;
  for (int i = 0; i < 10; ++i) make_session(dir, "2024010" + std::to_string(i) + "-000000-1", 1000, kNow - 3600);
  const auto current = make_session(dir, "20240201-000000-9", 2500, kNow);
  dir.write("notes.txt", std::string(100000, 'y'));  // not a session: never counted, never removed
  const auto removed = rotate_sessions(dir.path(), RotationLimits{6000, 30 * kDay}, current, kNow);
  EXPECT_LE(total_size(dir.path()), 6000u);
  EXPECT_EQ(removed.size(), 7u);  // 12,500 bytes -> 5,500
  EXPECT_EQ(removed.front().filename(), "20240100-000000-1.andros-session");
  EXPECT_TRUE(fs::exists(current));
  EXPECT_TRUE(fs::exists(dir.path() / "notes.txt"));
  EXPECT_TRUE(fs::exists(dir.path() / "20240109-000000-1.andros-session"));  // the newest old one stays
}

TEST(SessionFiles, TheRunningSessionIsNeverRemovedEvenOverTheCap) {
  testing::TempDir dir;
  const auto old = make_session(dir, "20240101-000000-1", 10, kNow - 100 * kDay);
  const auto current = make_session(dir, "20240102-000000-2", 50000, kNow);
  rotate_sessions(dir.path(), RotationLimits{1000, 30 * kDay}, current, kNow);
  EXPECT_TRUE(fs::exists(current));
  EXPECT_FALSE(fs::exists(old));
}

TEST(SessionFiles, SessionsPastTheirAgeAreRemovedWhateverTheSize) {
  testing::TempDir dir;
  const auto old = make_session(dir, "20240101-000000-1", 10, kNow - 31 * kDay);
  const auto young = make_session(dir, "20240102-000000-2", 10, kNow - 29 * kDay);
  const auto removed = rotate_sessions(dir.path(), RotationLimits{1'000'000, 30 * kDay}, fs::path(), kNow);
  EXPECT_EQ(removed, std::vector<fs::path>{old});
  EXPECT_TRUE(fs::exists(young));
}

TEST(SessionFiles, AFileNamedLikeASessionThatIsNotOneIsNeverRemovedNorListed) {
  testing::TempDir dir;
  const auto notes = make_session(dir, "20200101-000000-1", 5000, kNow - 400 * kDay, "my notes, not a session\n");
  const auto empty = make_session(dir, "20200101-000000-2", 0, kNow - 400 * kDay, "");
  const auto old = make_session(dir, "20200102-000000-1", 5000, kNow - 400 * kDay);
  const auto removed = rotate_sessions(dir.path(), RotationLimits{1000, 30 * kDay}, fs::path(), kNow);
  EXPECT_EQ(removed, std::vector<fs::path>{old});
  EXPECT_TRUE(fs::exists(notes));
  EXPECT_TRUE(fs::exists(empty));
  EXPECT_TRUE(list_sessions(dir.path()).empty());
}

TEST(SessionFiles, ALinkNamedLikeASessionIsNeitherFollowedNorRemoved) {
  testing::TempDir dir;
  testing::TempDir elsewhere;
  const auto target = make_session(elsewhere, "20200101-000000-1", 5000, kNow - 400 * kDay);
  const auto link = dir.path() / "20200101-000000-1.andros-session";
  fs::create_symlink(target, link);
  EXPECT_TRUE(rotate_sessions(dir.path(), RotationLimits{1000, 30 * kDay}, fs::path(), kNow).empty());
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_TRUE(fs::exists(target));
}

TEST(SessionFiles, ASessionAWriterHoldsLockedIsNeverRemoved) {
  testing::TempDir dir;
  const auto other = make_session(dir, "20200101-000000-1", 5000, kNow - 400 * kDay);
  {
    // Another bridge writing in this folder holds its session locked.
    const UniqueFd held(::open(other.c_str(), O_RDONLY | O_CLOEXEC));
    ASSERT_EQ(::flock(held.get(), LOCK_EX | LOCK_NB), 0);
    EXPECT_TRUE(rotate_sessions(dir.path(), RotationLimits{1000, 30 * kDay}, fs::path(), kNow).empty());
    EXPECT_TRUE(fs::exists(other));
  }
  // Closed: it is rotation's again.
  EXPECT_EQ(rotate_sessions(dir.path(), RotationLimits{1000, 30 * kDay}, fs::path(), kNow),
            std::vector<fs::path>{other});
}

TEST(SessionFiles, TheRecordersFileIsLockedWhileItIsOpen) {
  testing::TempDir dir;
  const auto path = dir.path() / "20200101-000000-1.andros-session";
  {
    record::FileRecordSink sink(path.string());
    std::string error;
    ASSERT_TRUE(sink.write("0 andros-session 2 " + std::string(64, '0') + "\n", error)) << error;
    const UniqueFd other(::open(path.c_str(), O_RDONLY | O_CLOEXEC));
    EXPECT_NE(::flock(other.get(), LOCK_EX | LOCK_NB), 0);
    EXPECT_EQ(errno, EWOULDBLOCK);
    EXPECT_TRUE(rotate_sessions(dir.path(), RotationLimits{0, 0}, fs::path(), kNow + 400 * kDay).empty());
  }
  EXPECT_EQ(rotate_sessions(dir.path(), RotationLimits{0, 0}, fs::path(), kNow + 400 * kDay).size(), 1u);
}

TEST(SessionFiles, TheRunningSessionIsKeptByWhateverPathItIsNamed) {
  testing::TempDir dir;
  const auto current = make_session(dir, "20240102-000000-2", 50000, kNow - 400 * kDay);
  const auto same = dir.path() / "." / current.filename();
  EXPECT_TRUE(rotate_sessions(dir.path(), RotationLimits{1000, 30 * kDay}, same, kNow).empty());
  EXPECT_TRUE(fs::exists(current));
}

TEST(SessionFiles, TheFolderFollowsTheServiceThenXdgThenHome) {
  const auto keep = [](const char* name) {
    const char* v = std::getenv(name);
    return v == nullptr ? std::optional<std::string>() : std::optional<std::string>(v);
  };
  const auto state = keep("STATE_DIRECTORY");
  const auto xdg = keep("XDG_STATE_HOME");
  const auto home = keep("HOME");
  setenv("HOME", "/home/op", 1);
  unsetenv("STATE_DIRECTORY");
  unsetenv("XDG_STATE_HOME");
  EXPECT_EQ(session_dir(""), fs::path("/home/op/.local/state/andros-bridge"));
  setenv("XDG_STATE_HOME", "relative/ignored", 1);  // the spec: only an absolute path counts
  EXPECT_EQ(session_dir(""), fs::path("/home/op/.local/state/andros-bridge"));
  setenv("XDG_STATE_HOME", "/x/state", 1);
  EXPECT_EQ(session_dir(""), fs::path("/x/state/andros-bridge"));
  setenv("STATE_DIRECTORY", "/var/lib/andros-bridge:/var/lib/other", 1);
  EXPECT_EQ(session_dir(""), fs::path("/var/lib/andros-bridge"));
  EXPECT_EQ(session_dir("/given"), fs::path("/given"));
  const auto restore = [](const char* name, const std::optional<std::string>& v) {
    if (v) setenv(name, v->c_str(), 1);
    else unsetenv(name);
  };
  restore("STATE_DIRECTORY", state);
  restore("XDG_STATE_HOME", xdg);
  restore("HOME", home);
}

TEST(SessionFiles, ANameSaysWhenAndWhichProcess) {
  const auto path = new_session_path("/d", kNow, 4242);
  EXPECT_EQ(path.parent_path(), fs::path("/d"));
  EXPECT_TRUE(path.filename().string().ends_with("-4242.andros-session")) << path;
  EXPECT_EQ(path.filename().string().size(), std::string("20231114-221320-4242.andros-session").size());
}

}  // namespace
}  // namespace andros::cli
