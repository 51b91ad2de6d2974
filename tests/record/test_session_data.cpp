// A session is data, never a path (run/session_replay.hpp): the recorded
// mapping chain is read in memory, its paths only labels, its `extends`
// taken from the chain itself and never from this machine's mappings.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "andros/base/error.hpp"
#include "andros/base/text_file.hpp"
#include "andros/mapping/loader.hpp"
#include "andros/record/session_replay.hpp"
#include "support/temp_dir.hpp"

namespace andros::record {
namespace {

namespace fs = std::filesystem;

std::string shipped(const std::string& name) {
  return read_text_file(std::string(ANDROS_MAPPINGS_DIR) + "/" + name, kMappingLimits);
}

/// Sets an environment variable for the test's length.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const std::string& value) : name_(name) {
    if (const char* v = std::getenv(name)) old_ = v;
    setenv(name, value.c_str(), 1);
  }
  ~ScopedEnv() {
    if (old_) setenv(name_, old_->c_str(), 1);
    else unsetenv(name_);
  }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  const char* name_;
  std::optional<std::string> old_;
};

/// hd1.yaml and its base, as a session records them.
std::vector<MappingSource> recorded_hd1(const std::string& folder) {
  return {{folder + "/hd1.yaml", shipped("hd1.yaml")}, {folder + "/common.yaml", shipped("common.yaml")}};
}

TEST(SessionData, ARecordedPathWithDotDotIsOnlyALabelNothingIsWritten) {
  testing::TempDir dir;
  fs::create_directories(dir.path() / "a/b");
  const ScopedEnv tmp("TMPDIR", (dir.path() / "a/b").string());
  const auto mapping = load_recorded_mapping(recorded_hd1("../../escaped"));
  EXPECT_EQ(mapping->robot, "HD1");
  EXPECT_FALSE(fs::exists(dir.path() / "a/escaped"));
  EXPECT_TRUE(fs::is_empty(dir.path() / "a/b"));
}

TEST(SessionData, AnAbsoluteRecordedPathIsNeverCreated) {
  testing::TempDir dir;
  const auto where = (dir.path() / "abs").string();
  const auto mapping = load_recorded_mapping(recorded_hd1(where));
  EXPECT_EQ(mapping->file, where + "/hd1.yaml");  // the label, as recorded
  EXPECT_FALSE(fs::exists(where));
}

TEST(SessionData, ExtendsARobotTakesTheRecordedBaseNotTheLocalOne) {
  testing::TempDir dir;
  // Today's local hd1.yaml is not what was recorded: it must not be read.
  fs::create_directories(dir.path() / "andros-bridge/mappings");
  dir.write("andros-bridge/mappings/hd1.yaml", "robot: HD1\nbindings: [ this is not what was recorded\n");
  const ScopedEnv config("XDG_CONFIG_HOME", dir.path().string());
  std::vector<MappingSource> sources{
      {"/home/op/.config/andros-bridge/mappings/mine.yaml", "robot: HD1\nextends: hd1\ncenter: 126\n"}};
  for (auto& s : recorded_hd1("/usr/share/andros-bridge/mappings")) sources.push_back(s);
  const auto mapping = load_recorded_mapping(sources);
  EXPECT_EQ(mapping->center, 126);
  const auto base = load_recorded_mapping(recorded_hd1("/x"));
  EXPECT_EQ(mapping->bindings.size(), base->bindings.size());
  EXPECT_EQ(mapping->chain.size(), 3u);
}

TEST(SessionData, ExtendsNamingAFileTheSessionDidNotRecordIsAnError) {
  testing::TempDir dir;
  dir.write("base.yaml", shipped("common.yaml"));  // on the disk, beside the label: never read
  const std::vector<MappingSource> sources{{(dir.path() / "mine.yaml").string(), "robot: HD1\nextends: base.yaml\n"}};
  try {
    (void)load_recorded_mapping(sources);
    FAIL() << "a base that is not recorded was found";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the session recorded no 'base.yaml' next in the mapping's chain"),
              std::string::npos)
        << e.what();
  }
}

TEST(SessionData, ARecordedBaseOfAnotherNameIsNotTaken) {
  const std::vector<MappingSource> sources{{"/r/mine.yaml", "robot: HD1\nextends: hd1\n"},
                                           {"/r/common.yaml", shipped("common.yaml")}};
  EXPECT_THROW((void)load_recorded_mapping(sources), InputError);
}

}  // namespace
}  // namespace andros::record
