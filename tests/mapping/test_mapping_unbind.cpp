// `unbind:` in an extending file: it drops the extended file's binding read by
// an input, in the base layer or in a layer of the same name, and nothing else.
#include <gtest/gtest.h>

#include "andros/mapping/loader.hpp"
#include "support/learn_helpers.hpp"
#include "support/temp_dir.hpp"

namespace andros::mapping {
namespace {

using MappingDir = testing::TempDir;
using test::reads;

const std::string kUnbindBase =
    "deadman: leftshoulder\n"
    "bindings:\n"
    "  - signal: front_art_up\n    button: dpup\n"
    "  - signal: front_art_down\n    button: dpdown\n"
    "  - signal: pt_up\n    button: 3\n"
    "  - signal: [pt_left, pt_right]\n    axis: 3\n"
    "layers:\n"
    "  arm:\n    hold: rightshoulder\n    bindings:\n"
    "      - signal: gripper_open\n        button: a\n"
    "      - signal: gripper_close\n        button: b\n";

/// base.yaml (kUnbindBase) and mine.yaml (robot HD1, extends base.yaml, then rest), loaded.
Mapping extend(const std::string& rest) {
  MappingDir dir;
  dir.write("base.yaml", kUnbindBase);
  return *load_mapping(dir.write("mine.yaml", "robot: HD1\nextends: base.yaml\n" + rest));
}

TEST(MappingUnbind, DropsTheBaseBindingOfThatInputOnly) {
  const auto m = extend("bindings:\n  - unbind: dpup\n  - signal: front_art_up\n    button: paddle1\n");
  EXPECT_FALSE(reads(m.bindings, "dpup"));
  EXPECT_TRUE(reads(m.bindings, "paddle1"));
  EXPECT_TRUE(reads(m.bindings, "dpdown"));
  EXPECT_EQ(m.bindings.size(), 4U);
}

TEST(MappingUnbind, WithoutItTheOldInputStaysBound) {
  // Why learn writes unbind: a binding on a new input replaces nothing.
  const auto m = extend("bindings:\n  - signal: front_art_up\n    button: paddle1\n");
  EXPECT_TRUE(reads(m.bindings, "dpup"));
  EXPECT_TRUE(reads(m.bindings, "paddle1"));
}

TEST(MappingUnbind, InALayerDropsThatLayersBindingAndLeavesTheBaseLayer) {
  const auto m = extend("layers:\n  arm:\n    hold: rightshoulder\n    bindings:\n      - unbind: a\n");
  ASSERT_EQ(m.layers.size(), 1U);
  EXPECT_FALSE(reads(m.layers[0].bindings, "a"));
  EXPECT_TRUE(reads(m.layers[0].bindings, "b"));
  EXPECT_EQ(m.bindings.size(), 4U);
}

TEST(MappingUnbind, ANumberDropsTheJoystickButtonAndAxisOfThatNumber) {
  const auto m = extend("bindings:\n  - unbind: 3\n");
  EXPECT_FALSE(reads(m.bindings, "3"));
  EXPECT_EQ(m.bindings.size(), 2U);
}

}  // namespace
}  // namespace andros::mapping
