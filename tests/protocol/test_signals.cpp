#include <gtest/gtest.h>

#include <fstream>
#include <initializer_list>
#include <set>
#include <string>
#include <vector>

#include "andros/protocol/robots.hpp"
#include "andros/protocol/signals.hpp"
#include "andros/protocol/words.hpp"

namespace andros::protocol {
namespace {

TEST(Signals, NamesAreUnique) {
  std::set<std::string_view> names;
  for (const auto& s : kSignals) EXPECT_TRUE(names.insert(s.name).second) << s.name;
}

TEST(Signals, EveryBitOfTheSwitchBytesIsASignalOrFixed) {
  // Bytes 0-5, 10 and 13 are all switches: each bit is a signal or a fixed bit, once.
  for (const std::uint8_t byte : std::initializer_list<std::uint8_t>{0, 1, 2, 3, 4, 5, 10, 13}) {
    for (std::uint8_t bit = 0; bit < 8; ++bit) {
      int owners = is_fixed_bit(byte, bit) ? 1 : 0;
      for (const auto& s : kSignals) owners += (s.byte == byte && s.bit == bit) ? 1 : 0;
      EXPECT_EQ(owners, 1) << "byte " << int{byte} << " bit " << int{bit};
    }
  }
}

TEST(Signals, WholeBytesAreTheAnalogAndConstantOnes) {
  std::set<int> bytes;
  for (const auto& s : kSignals) {
    if (!s.is_bit()) bytes.insert(s.byte);
    EXPECT_EQ(!s.is_bit(),
              s.kind == SignalKind::kCentred || s.kind == SignalKind::kLevel || s.kind == SignalKind::kConstant)
        << s.name;
  }
  EXPECT_EQ(bytes, (std::set<int>{6, 7, 8, 9, 11, 12, 14}));
}

// The opposing pairs of docs/mapping.md's safety rules (never both 1).
TEST(Signals, OpposingPairsOfTheSafetyRules) {
  const std::pair<const char*, const char*> pairs[] = {
      {"front_art_up", "front_art_down"},
      {"rear_art_up", "rear_art_down"},
      {"pt_left", "pt_right"},
      {"pt_up", "pt_down"},
      {"focus_down", "focus_up"},
      {"iris_up", "iris_down"},
      {"zoom_down", "zoom_up"},
      {"fiber_unwind", "fiber_takeup"},
      {"shoulder_cw", "shoulder_ccw"},
      {"torso_left", "torso_right"},
      {"wrist_cw", "wrist_ccw"},
      {"gripper_rot_ccw", "gripper_rot_cw"},
      {"gripper_open", "gripper_close"},
      {"elbow_cw", "elbow_ccw"},
      {"pt_extend_up", "pt_extend_down"},
      {"wrist_extend_left", "wrist_extend_right"},
      {"graphics_down", "graphics_up"},
      {"speed_high", "speed_low"},
  };
  std::size_t with_partner = 0;
  for (const auto& s : kSignals) with_partner += s.partner.empty() ? 0U : 1U;
  EXPECT_EQ(with_partner, 2 * std::size(pairs));
  for (const auto& [a, b] : pairs) {
    const auto ia = find_signal(a);
    ASSERT_TRUE(ia) << a;
    EXPECT_EQ(partner_of(*ia), find_signal(b)) << a;
  }
}

// docs/protocol.md's signal kinds: weapons 0 in the neutral frame, selectors kept.
TEST(Signals, WeaponsAndSelectorsAreTheDocumentedLists) {
  std::set<std::string_view> weapons, selectors;
  for (const auto& s : kSignals) {
    if (s.kind == SignalKind::kWeapon) weapons.insert(s.name);
    if (s.kind == SignalKind::kSelector) selectors.insert(s.name);
  }
  EXPECT_EQ(weapons, (std::set<std::string_view>{"weapon_1", "weapon_2", "weapon_3", "weapon_4", "weapon_5", "weapon_6",
                                                 "shotgun", "laser", "enable_key"}));
  EXPECT_EQ(selectors, (std::set<std::string_view>{"speed_high", "speed_low", "inset_3", "inset_4", "inset_video_1",
                                                   "inset_video_2", "main_video_2", "main_video_3", "main_video_4"}));
}

TEST(Signals, Lookup) {
  EXPECT_EQ(kSignals[signal_id("safety")].byte, 0);
  EXPECT_EQ(kSignals[signal_id("safety")].bit, 1);
  EXPECT_EQ(kSignals[signal_id("battery")].byte, 14);
  EXPECT_FALSE(find_signal("Safety"));
  EXPECT_FALSE(find_signal(""));
}

// Issue 19, finding 10: one table of operator words, and docs/robots.md's
// list of it says the same, row for row.
TEST(SignalWords, DocsRobotsListsTheTableRowForRow) {
  std::ifstream in(ANDROS_DOCS_DIR "/robots.md");
  ASSERT_TRUE(in) << "docs/robots.md";
  std::string line;
  while (std::getline(in, line) && line != "## Operator words") {
  }
  ASSERT_EQ(line, "## Operator words");
  std::vector<std::string> rows;
  while (std::getline(in, line) && !line.starts_with("## ")) {
    if (line.starts_with("| `")) rows.push_back(line);
  }
  ASSERT_EQ(rows.size(), kSignalWords.size());
  for (std::size_t i = 0; i < kSignalWords.size(); ++i) {
    const auto& w = kSignalWords[i];
    const std::string grows = w.more.empty() ? "" : std::string(w.more) + " / " + std::string(w.less);
    EXPECT_EQ(rows[i], "| `" + std::string(w.signal) + "` | " + std::string(w.words) + " | " + grows + " |");
  }
}

TEST(SignalWords, EveryAnalogByteSaysWhichWayItGrows) {
  for (std::size_t i = 0; i < kSignalCount; ++i) {
    const auto kind = kSignals[i].kind;
    const bool analog = kind == SignalKind::kCentred || kind == SignalKind::kLevel;
    EXPECT_EQ(!kSignalWords[i].more.empty(), analog) << kSignals[i].name;
    EXPECT_FALSE(kSignalWords[i].words.empty()) << kSignals[i].name;
  }
  EXPECT_EQ(words(signal_id("zoom_down")).words, "zoom out");
  EXPECT_EQ(words(signal_id("fiber_takeup")).words, "reel in tether");
  EXPECT_EQ(words(signal_id("drive")).more, "forward");
}

// Issue 19, finding 11: the vehicles' names are robot types too.
TEST(Robots, TheVehiclesNamesAreAcceptedInAnyCase) {
  EXPECT_EQ(canonical_robot("HD-1"), "HD1");
  EXPECT_EQ(canonical_robot("hd-1"), "HD1");
  EXPECT_EQ(canonical_robot("V-A1"), "VA1");
  EXPECT_EQ(canonical_robot("wolverine"), "WOLVERINE");
  EXPECT_EQ(canonical_robot("HD-2"), std::nullopt);
  EXPECT_EQ(canonical_robot("HD_1"), std::nullopt);
}

}  // namespace
}  // namespace andros::protocol
