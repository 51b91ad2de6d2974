// The shipped mappings: every file loads, every robot type has one, every
// signal is reachable from the pad, every binding carries a comment, and a
// standard session replays the same through every robot type.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <set>
#include <sstream>

#include "andros/base/text.hpp"
#include "andros/mapping/loader.hpp"
#include "andros/protocol/robots.hpp"
#include "andros/run/replay.hpp"
#include "support/replay_data.hpp"

namespace andros::mapping {
namespace {

namespace fs = std::filesystem;
const fs::path kShipped = ANDROS_MAPPINGS_DIR;
const std::string kData = ANDROS_TEST_DATA_DIR;

// The shipped file itself, whatever a user keeps in ~/.config.
ValidMapping shipped(std::string_view robot) { return load_mapping(find_robot_mapping(robot, {kShipped})); }

std::vector<fs::path> shipped_files() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(kShipped)) {
    if (entry.path().extension() == ".yaml") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

TEST(ShippedMappings, EveryFileLoadsAndValidates) {
  const auto files = shipped_files();
  ASSERT_EQ(files.size(), protocol::kRobotTypes.size() + 1) << "one file per robot type plus common.yaml";
  for (const auto& file : files) {
    const auto m = load_mapping_file(file);
    EXPECT_NO_THROW(validate(m, m.robot.has_value())) << file;
    EXPECT_EQ(m.robot.has_value(), file.filename() != "common.yaml") << file;
  }
}

TEST(ShippedMappings, EveryRobotTypeIsFoundByName) {
  for (const auto robot : protocol::kRobotTypes) {
    const std::string lower = to_lower(robot);
    const auto path = find_robot_mapping(lower, {kShipped});
    EXPECT_EQ(path.filename(), lower + ".yaml");
    const auto m = load_mapping(path);
    EXPECT_EQ(m->robot, std::string(robot));
  }
}

std::set<protocol::SignalId> targets(const Mapping& m) {
  std::set<protocol::SignalId> out;
  for (const auto ref : all_bindings(m)) {
    std::visit(
        [&](const auto& r) {
          using R = std::decay_t<decltype(r)>;
          if constexpr (std::is_same_v<R, PairBinding>) out.insert(r.signals.begin(), r.signals.end());
          else if constexpr (std::is_same_v<R, AxisBinding> || std::is_same_v<R, KnobBinding>) out.insert(r.analog);
          else if constexpr (std::is_same_v<R, SelectorBinding>) {
            for (const auto& p : r.positions) out.insert(p.begin(), p.end());
          } else out.insert(r.signal);
        },
        binding_at(m, ref).rule);
  }
  return out;
}

TEST(ShippedMappings, EverySignalIsReachableFromAStandardPad) {
  for (const auto robot : protocol::kRobotTypes) {
    const auto m = *shipped(robot);
    const auto reached = targets(m);
    for (std::size_t i = 0; i < protocol::kSignalCount; ++i) {
      const auto kind = protocol::kSignals[i].kind;
      if (kind == protocol::SignalKind::kInterlock || kind == protocol::SignalKind::kConstant) continue;
      EXPECT_TRUE(reached.count(static_cast<protocol::SignalId>(i)))
          << robot << ": " << protocol::kSignals[i].name << " is not bound";
    }
    // Only the inputs an Xbox-layout pad has (no guide, paddles, touchpad, numbers).
    for (const auto ref : all_bindings(m)) {
      for (const auto& u : binding_at(m, ref).inputs) {
        const auto name = input::input_name(u.key);
        EXPECT_TRUE(u.key.kind == input::InputKind::kPadButton || u.key.kind == input::InputKind::kPadAxis) << name;
        EXPECT_TRUE(name != "guide" && name != "misc1" && !name.starts_with("paddle") && name != "touchpad") << name;
      }
    }
    const auto deadman = input::input_name(m.deadman->key);
    EXPECT_TRUE(deadman == "leftshoulder" || deadman == "rightshoulder" || deadman.ends_with("trigger")) << deadman;
  }
}

// Weapons are never latched past the deadman (docs/mapping.md's safety rules): a layer that holds a
// weapon is a hold layer, and the base layer holds none.
TEST(ShippedMappings, WeaponsAreOnlyInHeldLayers) {
  const auto is_weapon = [](const Binding& b) { return std::holds_alternative<WeaponBinding>(b.rule); };
  for (const auto& file : shipped_files()) {
    const auto m = load_mapping_file(file);
    EXPECT_FALSE(std::any_of(m.bindings.begin(), m.bindings.end(), is_weapon)) << file;
    for (const auto& layer : m.layers) {
      if (std::any_of(layer.bindings.begin(), layer.bindings.end(), is_weapon)) {
        EXPECT_FALSE(layer.toggle) << file << ": layer " << layer.name;
      }
    }
  }
}

TEST(ShippedMappings, EveryBindingCarriesAComment) {
  const std::regex binding_line(R"(^\s*- (signal|analog|selector):)");
  for (const auto& file : shipped_files()) {
    std::istringstream in(testing::read_text(file));
    std::string line;
    int n = 0;
    while (std::getline(in, line)) {
      ++n;
      if (std::regex_search(line, binding_line)) {
        EXPECT_NE(line.find('#'), std::string::npos) << file << ":" << n;
      }
    }
  }
}

class StandardSession : public ::testing::TestWithParam<std::string_view> {};

TEST_P(StandardSession, ReplaysTheSameThroughEveryRobotType) {
  const auto robot = GetParam();
  for (const bool weapons : {false, true}) {
    SCOPED_TRACE(weapons ? "--weapons" : "no --weapons");
    testing::expect_replay(shipped(robot), weapons, timing::kDefaultRateMillihertz, kData + "/standard_session.events",
                           kData + (weapons ? "/standard_session_weapons.expected" : "/standard_session.expected"));
  }
}

INSTANTIATE_TEST_SUITE_P(RobotTypes, StandardSession, ::testing::ValuesIn(protocol::kRobotTypes),
                         [](const auto& param_info) { return std::string(param_info.param); });

}  // namespace
}  // namespace andros::mapping
