// The flight recorder's folder (src/cli/session_files.hpp): where it is,
// session names, and rotation by total size and age.
#include <gtest/gtest.h>
#include <utime.h>

#include <cstdlib>
#include <string>

#include "cli/session_files.hpp"
#include "support/temp_dir.hpp"

namespace andros::cli {
namespace {

namespace fs = std::filesystem;

/// A session of size bytes last written at mtime.
fs::path make_session(const testing::TempDir& dir, const std::string& name, std::size_t size, std::time_t mtime) {
  const auto path = dir.write(name + ".andros-session", std::string(size, 'x'));
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
