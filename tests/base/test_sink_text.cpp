#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "andros/base/sink_text.hpp"
#include "andros/base/text.hpp"
#include "support/hostile_text.hpp"

namespace andros {
namespace {

using testing::kHostileTexts;
using testing::raw_text_in;

TEST(SinkText, NoSinkHoldsAHostileStringRaw) {
  for (const auto& text : kHostileTexts) {
    const std::vector<std::pair<const char*, std::string>> outputs = {{"terminal_text", terminal_text(text)},
                                                                      {"terminal_line", terminal_line(text)},
                                                                      {"json_text", json_text(text)},
                                                                      {"csv_cell", csv_cell(text)},
                                                                      {"svg_text", svg_text(text)}};
    for (const auto& [sink, out] : outputs) {
      EXPECT_EQ(raw_text_in(out), std::nullopt) << sink;
    }
  }
}

TEST(SinkText, JsonTextIsJsonAndGivesTheBytesBack) {
  for (const auto& text : kHostileTexts) {
    const nlohmann::json j = json_text(text);
    std::string dumped;
    EXPECT_NO_THROW(dumped = j.dump()) << printable_text(text);  // type_error.316 for invalid UTF-8
    EXPECT_EQ(unescape_text(nlohmann::json::parse(dumped).get<std::string>(), SourcePos{"test"}), text);
    EXPECT_EQ(unescape_text(terminal_text(text), SourcePos{"test"}), text);
  }
}

TEST(SinkText, ACsvCellIsNeverAFormula) {
  // OWASP's CSV injection: = + - @ tab CR first make a spreadsheet read a formula.
  EXPECT_EQ(csv_cell("=HYPERLINK(\"http://x\",\"y\")"), "\"'=HYPERLINK(\"\"http://x\"\",\"\"y\"\")\"");
  EXPECT_EQ(csv_cell("+1"), "'+1");
  EXPECT_EQ(csv_cell("-1"), "'-1");
  EXPECT_EQ(csv_cell("@SUM(1)"), "'@SUM(1)");
  EXPECT_EQ(csv_cell("\t=1"), "\\t=1");  // escaped first: the tab is two characters, not a tab
  EXPECT_EQ(csv_cell("arm"), "arm");
  EXPECT_EQ(csv_cell("a,b"), "\"a,b\"");
  EXPECT_EQ(csv_cell(""), "");
  for (const auto& text : kHostileTexts) {
    const auto cell = csv_cell(text);
    const auto first = cell.starts_with('"') ? cell.substr(1, 1) : cell.substr(0, 1);
    EXPECT_EQ(first.find_first_of("=+-@\t\r"), std::string::npos) << cell;
  }
}

TEST(SinkText, SvgTextIsXmlText) {
  EXPECT_EQ(svg_text("<a href=\"x\">&'"), "&lt;a href=&quot;x&quot;&gt;&amp;&apos;");
  EXPECT_EQ(svg_text("caf\xc3\xa9"), "caf\xc3\xa9");             // UTF-8 stays
  EXPECT_EQ(svg_text("rtl\xe2\x80\xae"), "rtl\\xE2\\x80\\xAE");  // shown, never obeyed
  EXPECT_EQ(svg_text(std::string("nul\0", 4)), "nul\\x00");      // XML 1.0 has no NUL
  EXPECT_EQ(svg_text("bad\xff"), "bad\\xFF");
}

TEST(SinkText, ALineKeepsItsQuotedPiecesAsTheyAre) {
  // A message whose names quote() escaped: shown as made, a raw byte in it escaped.
  EXPECT_EQ(terminal_line("unknown event 'conn\\x00ect'"), "unknown event 'conn\\x00ect'");
  EXPECT_EQ(terminal_line("layer: a\nb"), "layer: a\\nb");
  EXPECT_EQ(terminal_text("a\\b"), "a\\\\b");
}

}  // namespace
}  // namespace andros
