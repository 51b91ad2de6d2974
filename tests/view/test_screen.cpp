#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "andros/view/screen.hpp"

namespace andros::view {
namespace {

std::vector<std::string> texts(const Screen& screen, TermSize size) {
  std::vector<std::string> out;
  for (const auto& line : screen.fit(size)) out.push_back(plain(line, static_cast<std::size_t>(size.cols)));
  return out;
}

std::vector<Line> lines(const std::string& prefix, int n) {
  std::vector<Line> out;
  for (int i = 0; i < n; ++i) out.emplace_back(prefix + std::to_string(i));
  return out;
}

TEST(Screen, PinnedLinesAlwaysShowFirstAndInOrder) {
  Screen s;
  s.pin(Line("title"));
  s.block(lines("log", 30), 0, true);
  s.pin(Line("state"));
  const auto shown = texts(s, {80, 4});
  ASSERT_EQ(shown.size(), 4u);
  EXPECT_EQ(shown[0], "title");
  EXPECT_EQ(shown[1], "state");
  EXPECT_EQ(shown[2], "log0");
  EXPECT_EQ(shown[3], "log1");
}

TEST(Screen, NeverMoreLinesThanRows) {
  Screen s;
  for (int i = 0; i < 10; ++i) s.pin(Line("pin" + std::to_string(i)));
  s.block(lines("b", 5), 1);
  EXPECT_EQ(s.fit({80, 3}).size(), 3u);
  EXPECT_EQ(texts(s, {80, 3}).back(), "pin2");
  EXPECT_EQ(s.fit({80, 24}).size(), 15u);
}

TEST(Screen, BlocksByPriorityShownInTheirOwnOrder) {
  Screen s;
  s.pin(Line("head"));
  s.block(lines("low", 3), 1);
  s.block(lines("high", 3), 5);
  // 1 + 3 rows: only the high block fits whole; the low one (not shrinkable) is dropped.
  EXPECT_EQ(texts(s, {80, 4}), (std::vector<std::string>{"head", "high0", "high1", "high2"}));
  // With room for both, the low block keeps its place before the high one.
  EXPECT_EQ(texts(s, {80, 7}), (std::vector<std::string>{"head", "low0", "low1", "low2", "high0", "high1", "high2"}));
}

TEST(Screen, AShrinkableBlockGivesItsFirstLines) {
  Screen s;
  s.block(lines("fixed", 2), 2);
  s.block(lines("log", 10), 1, true);
  EXPECT_EQ(texts(s, {80, 5}), (std::vector<std::string>{"fixed0", "fixed1", "log0", "log1", "log2"}));
}

TEST(Screen, ATailBlockGivesItsLastLines) {
  Screen s;
  s.pin(Line("head"));
  s.tail(lines("log", 10), 0);
  EXPECT_EQ(texts(s, {80, 3}), (std::vector<std::string>{"head", "log8", "log9"}));
  EXPECT_EQ(s.fit({80, 30}).size(), 11u);
}

// Issue 28, item 1: a line wider than the screen wraps under itself (its
// parts keep their styles, each counts as a row), never cut at the edge.
TEST(Screen, ALineTooWideWrapsWithItsStyles) {
  Screen s;
  s.pin(Line("0123456789", Style::kAlert).add("abcdef", Style::kGood));
  EXPECT_EQ(s.render({12, 5}, false), "0123456789ab\n  cdef\n");
  EXPECT_EQ(s.render({12, 5}, true), "\x1b[1;31m0123456789\x1b[0m\x1b[1;32mab\x1b[0m\n  \x1b[1;32mcdef\x1b[0m\n");
  // At spaces where it can, under its label when it hangs there.
  Screen label;
  label.pin(Line("state       ").add("NOT ENABLED: deadman held since connect", Style::kAlert).hang(12));
  EXPECT_EQ(label.render({30, 5}, false),
            "state       NOT ENABLED:\n            deadman held since\n            connect\n");
  // Each part is a row: a block that no longer fits is left out whole.
  Screen rows;
  rows.pin(Line("a long pinned line that wraps"));
  rows.block({Line("block")}, 1);
  EXPECT_EQ(texts(rows, {16, 3}), (std::vector<std::string>{"a long pinned", "  line that", "  wraps"}));
  EXPECT_EQ(rows.fit({16, 4}).size(), 4U);
  // Printed whole to a file or pipe: one line, not wrapped.
  EXPECT_EQ(rows.text(), "a long pinned line that wraps\nblock\n");
}

TEST(Screen, AOneRowLineIsCutToTheWidthWithoutBreakingEscapes) {
  Screen s;
  s.pin(Line("0123456789", Style::kAlert).add("abcdef", Style::kGood).one_row());
  EXPECT_EQ(s.render({12, 5}, false), "0123456789ab\n");
  const std::string coloured = s.render({12, 5}, true);
  EXPECT_EQ(coloured, "\x1b[1;31m0123456789\x1b[0m\x1b[1;32mab\x1b[0m\n");
  // A UTF-8 name is cut between characters, never inside one.
  Screen u;
  u.pin(Line("pad \xc3\xa9\xc3\xa9\xc3\xa9").one_row());
  EXPECT_EQ(u.render({5, 1}, false), "pad \xc3\xa9\n");
  // Wrapped, UTF-8 counts by character too.
  Screen w;
  w.pin(Line("\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9"));
  EXPECT_EQ(w.render({4, 3}, false), "\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9\n  \xc3\xa9\xc3\xa9\n");
}

TEST(Screen, ControlCharactersFromNamesAreNotObeyed) {
  const Line line("evil\x1b[2Jname\n");
  EXPECT_EQ(plain(line, 80), "evil\\x1B[2Jname\\n");
}

TEST(Screen, ColourFollowsNoColorAndTheTerminalType) {
  EXPECT_TRUE(colour_wanted(nullptr, "xterm-256color"));
  EXPECT_TRUE(colour_wanted("", "tmux-256color"));  // NO_COLOR set but empty: no effect
  EXPECT_FALSE(colour_wanted("1", "xterm-256color"));
  EXPECT_FALSE(colour_wanted(nullptr, "dumb"));
  EXPECT_FALSE(colour_wanted(nullptr, "vt100"));
  EXPECT_FALSE(colour_wanted(nullptr, nullptr));
}

// Issue 19, finding 7: a log line wider than the screen wraps under its text,
// whole, instead of being cut.
TEST(Screen, WrapTextBreaksAtSpacesAndKeepsEveryCharacter) {
  const std::string line =
      "12:00:01 warning: reload refused: /home/op/.config/andros-bridge/mappings/hd1.yaml:12:5: error: unknown signal";
  const auto parts = wrap_text(line, 40, 9);
  ASSERT_GE(parts.size(), 3U);
  std::string joined;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    EXPECT_LE(parts[i].size(), 40U) << parts[i];
    if (i > 0) {
      EXPECT_TRUE(parts[i].starts_with("         ")) << parts[i];  // under the text, past the time
      joined += ' ';
    }
    joined += i > 0 ? parts[i].substr(9) : parts[i];
  }
  // Broken at spaces, or inside a word longer than a line: nothing lost.
  std::string squeezed;
  for (const char c : joined)
    if (c != ' ') squeezed += c;
  std::string want;
  for (const char c : line)
    if (c != ' ') want += c;
  EXPECT_EQ(squeezed, want);
  EXPECT_EQ(parts[0], "12:00:01 warning: reload refused:");
  EXPECT_EQ(wrap_text("short", 40, 9), std::vector<std::string>{"short"});
  // UTF-8 counts by character.
  EXPECT_EQ(wrap_text("\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9", 2, 0),
            (std::vector<std::string>{"\xc3\xa9\xc3\xa9", "\xc3\xa9\xc3\xa9"}));
}

}  // namespace
}  // namespace andros::view
