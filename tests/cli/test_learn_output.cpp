// What `learn --output FILE` writes over and extends, and how: a refused
// existing file, the folders of a fresh account, the second run on its own
// output, `extends: hd1`, names that are hostile to YAML.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

#include "andros/base/error.hpp"
#include "andros/cli/learn_session.hpp"
#include "andros/mapping/loader.hpp"
#include "support/input_error.hpp"
#include "support/learn_helpers.hpp"
#include "support/temp_dir.hpp"

namespace andros::cli {
namespace {

namespace fs = std::filesystem;
using Kind = mapping::LearnResult::Kind;
using test::button;
using test::reads;
using test::step_of;
using testing::input_error_text;

const std::string kHd1 = std::string(ANDROS_MAPPINGS_DIR) + "/hd1.yaml";

std::string read_all(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// HOME set to a fresh folder and XDG_CONFIG_HOME unset, for one test.
class FreshAccount : public ::testing::Test {
 protected:
  void SetUp() override {
    for (const char* name : {"HOME", "XDG_CONFIG_HOME"}) {
      const char* value = std::getenv(name);
      saved_.emplace_back(name, value ? std::optional<std::string>(value) : std::nullopt);
    }
    setenv("HOME", home_.path().c_str(), 1);
    unsetenv("XDG_CONFIG_HOME");
  }
  void TearDown() override {
    for (const auto& [name, value] : saved_) {
      if (value) setenv(name.c_str(), value->c_str(), 1);
      else unsetenv(name.c_str());
    }
  }
  [[nodiscard]] fs::path user_hd1() const { return home_.path() / ".config/andros-bridge/mappings/hd1.yaml"; }

  testing::TempDir home_;

 private:
  std::vector<std::pair<std::string, std::optional<std::string>>> saved_;
};

/// learn's end: what learn_target chose, the file written.
void learn_and_write(mapping::LearnPlan& plan, const LearnTarget& target, const fs::path& output) {
  write_learned(plan, plan.extending_yaml(target.extends, target.over), output);
}

TEST_F(FreshAccount, TheDocumentedOutputIsMadeWithItsFoldersAndExtendsTheRobot) {
  auto base = mapping::load_robot_mapping("hd1");
  const auto target = learn_target(*base, user_hd1(), false);
  EXPECT_EQ(target.extends, "hd1");
  mapping::LearnPlan plan(*base);
  ASSERT_EQ(plan.assign(step_of(plan, "base layer, front_art_up"), button("paddle1")).kind, Kind::kChanged);
  learn_and_write(plan, target, user_hd1());
  const auto text = read_all(user_hd1());
  EXPECT_NE(text.find("\nextends: \"hd1\"\n"), std::string::npos) << text;
  // --robot hd1 now finds it, and it extends the shipped file, not itself.
  const auto loaded = mapping::load_robot_mapping("hd1");
  ASSERT_GE(loaded->chain.size(), 2U);  // the shipped hd1.yaml extends common.yaml
  EXPECT_EQ(fs::path(loaded->chain.at(0)), fs::weakly_canonical(user_hd1()));
  EXPECT_EQ(fs::path(loaded->chain.at(1)), fs::weakly_canonical(kHd1));
  EXPECT_TRUE(plan.matches(*loaded));
  // Copied to another account, it still loads: it names the robot, not a path.
  testing::TempDir other;
  fs::copy_file(user_hd1(), other.path() / "copy.yaml");
  setenv("HOME", other.path().c_str(), 1);
  EXPECT_TRUE(plan.matches(*mapping::load_mapping(other.path() / "copy.yaml")));
}

TEST_F(FreshAccount, TheSecondRunOnItsOwnOutputNeedsForceAndKeepsTheFirstRunsChanges) {
  {
    auto base = mapping::load_robot_mapping("hd1");
    mapping::LearnPlan plan(*base);
    ASSERT_EQ(plan.assign(step_of(plan, "base layer, front_art_up"), button("paddle1")).kind, Kind::kChanged);
    learn_and_write(plan, learn_target(*base, user_hd1(), false), user_hd1());
  }
  auto base = mapping::load_robot_mapping("hd1");  // the first run's output
  EXPECT_EQ(input_error_text([&] { learn_target(*base, user_hd1(), false); }),
            "--output: error: '" + user_hd1().string() +
                "' exists: give --force to replace it (it is replaced only once the new file is written whole)");
  const auto target = learn_target(*base, user_hd1(), true);
  EXPECT_EQ(target.extends, "hd1");
  mapping::LearnPlan plan(*base);
  ASSERT_EQ(plan.assign(step_of(plan, "base layer, rear_art_up"), button("paddle2")).kind, Kind::kChanged);
  learn_and_write(plan, target, user_hd1());
  const auto loaded = mapping::load_robot_mapping("hd1");
  EXPECT_TRUE(plan.matches(*loaded)) << read_all(user_hd1());
  EXPECT_TRUE(reads(loaded->bindings, "paddle1")) << "the first run's change is kept";
  EXPECT_TRUE(reads(loaded->bindings, "paddle2"));
  EXPECT_EQ(fs::path(loaded->chain.at(1)), fs::weakly_canonical(kHd1));
}

TEST_F(FreshAccount, AFileTheMappingExtendsIsRefusedAndANameIsNeverCut) {
  const auto long_folder = home_.path() / (std::string(100, 'x') + "-the-end-of-the-name");
  fs::create_directories(long_folder);
  fs::copy_file(kHd1, long_folder / "hd1.yaml");
  fs::copy_file(std::string(ANDROS_MAPPINGS_DIR) + "/common.yaml", long_folder / "common.yaml");
  auto base = mapping::load_mapping(long_folder / "hd1.yaml");
  EXPECT_EQ(input_error_text([&] { learn_target(*base, long_folder / "common.yaml", true); }),
            "--output: error: '" + (long_folder / "common.yaml").string() +
                "' is a file the mapping learned from extends: it would extend itself; write to another file");
  const auto notes = home_.path() / "notes.txt";
  std::ofstream(notes) << "an operator's notes\n";
  EXPECT_NE(input_error_text([&] { learn_target(*base, notes, false); }).find("exists: give --force"),
            std::string::npos);
  EXPECT_EQ(read_all(notes), "an operator's notes\n");
  std::ofstream(home_.path() / "afile") << "x";
  EXPECT_EQ(input_error_text([&] { learn_target(*base, home_.path() / "afile/mine.yaml", false); }),
            "--output: error: '" + (home_.path() / "afile").string() + "' is not a folder");
  // Not the shipped file for its robot: named by its absolute path.
  EXPECT_EQ(learn_target(*base, home_.path() / "mine.yaml", false).extends,
            fs::weakly_canonical(long_folder / "hd1.yaml").string());
}

TEST_F(FreshAccount, ALayerNameWithANewlineIsWrittenAsAQuotedKey) {
  const auto file = home_.path() / "odd.yaml";
  std::ofstream(file) << "robot: HD1\ndeadman: leftshoulder\nbindings:\n  - signal: tool_on\n    button: a\n"
                         "layers:\n  \"two\\nlines \\\"quoted\\\" \\\\ \\e[2J\":\n    hold: rightshoulder\n"
                         "    bindings:\n      - signal: front_art_up\n        button: dpup\n";
  auto base = mapping::load_mapping(file);
  mapping::LearnPlan plan(*base);
  const auto step = step_of(plan, "layer 'two\\nlines \"quoted\" \\\\ \\x1B[2J', front_art_up");
  ASSERT_EQ(plan.assign(step, button("paddle1")).kind, Kind::kChanged);
  const auto output = home_.path() / "mine.yaml";
  learn_and_write(plan, learn_target(*base, output, false), output);
  const auto text = read_all(output);
  EXPECT_NE(text.find("  \"two\\nlines \\\"quoted\\\" \\\\ \\x1B[2J\":\n"), std::string::npos) << text;
  EXPECT_TRUE(plan.matches(*mapping::load_mapping(output)));
}

TEST_F(FreshAccount, AFileThatDoesNotLoadIsNamedAsTheOutputNeverATemporary) {
  const auto output = home_.path() / "mine.yaml";
  EXPECT_EQ(input_error_text([&] { mapping::load_mapping_text("robot: HD1\ndeadman: a\nbad: 1\n", output); }),
            output.string() +
                ":3:1: error: unknown key 'bad' in a mapping file (expected robot, extends, center, constants, "
                "deadman, deadman_panic, estop, stop_reset, stop_reset_hold, enable_timeout, supervisor, brake, scale, "
                "feedback, "
                "bindings, layers)");
  EXPECT_FALSE(fs::exists(output));
}

TEST_F(FreshAccount, AFileThatCannotBeWrittenIsShownSoThatTheSessionIsNotLost) {
  auto base = mapping::load_mapping(kHd1);
  mapping::LearnPlan plan(*base);
  ASSERT_EQ(plan.assign(step_of(plan, "base layer, front_art_up"), button("paddle1")).kind, Kind::kChanged);
  std::ofstream(home_.path() / "afile") << "x";
  const auto output = home_.path() / "afile/mappings/mine.yaml";  // its folder cannot be made
  const auto text = plan.extending_yaml(kHd1);
  std::FILE* out = std::tmpfile();
  EXPECT_THROW(write_learned_or_show(plan, text, output, out), RuntimeError);
  std::rewind(out);
  std::string shown(4096, '\0');
  shown.resize(std::fread(shown.data(), 1, shown.size(), out));
  std::fclose(out);
  EXPECT_EQ(shown, output.string() + " not written; the learned mapping, to keep:\n" + text);
}

TEST_F(FreshAccount, ASymlinkedOutputKeepsItsLink) {
  auto base = mapping::load_mapping(kHd1);
  fs::create_directories(home_.path() / "real");
  const auto link = home_.path() / "mine.yaml";
  fs::create_symlink("real/mine.yaml", link);
  mapping::LearnPlan plan(*base);
  ASSERT_EQ(plan.assign(step_of(plan, "base layer, front_art_up"), button("paddle1")).kind, Kind::kChanged);
  learn_and_write(plan, learn_target(*base, link, true), link);
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_TRUE(plan.matches(*mapping::load_mapping(home_.path() / "real/mine.yaml")));
}

}  // namespace
}  // namespace andros::cli
