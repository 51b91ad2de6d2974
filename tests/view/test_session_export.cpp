// The export an investigator reads alone (docs/recording.md, "Export"): on
// each tick's row, who stopped and with which pad, who reset and with which
// pad, a shutdown request apart from the stop buttons, and what the hands
// held (the deadman, each stop button, each reset, the consent), a press
// shorter than a tick included; text from outside never a formula, never a
// broken row.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>

#include "andros/input/events.hpp"
#include "andros/mapping/loader.hpp"
#include "andros/view/session_export.hpp"

namespace andros::view {
namespace {

constexpr const char* kExportMapping =
    "robot: HD1\ndeadman: leftshoulder\nestop: guide\nsupervisor: {stop: guide, weapons_consent: a}\n";

/// The operator's reset chord back + start, the supervisor's reset x: set
/// here, as the mapping's `stop_reset:` and `reset:` keys would.
mapping::ValidMapping with_resets(const std::vector<record::MappingSource>& sources) {
  auto m = *record::load_recorded_mapping(sources);
  const auto button = [](const char* name) { return mapping::InputUse{*input::parse_button_name(name), {}}; };
  m.stop_reset = {button("back"), button("start")};
  if (m.supervisor) m.supervisor->reset = {button("x")};
  return mapping::validate(m);
}

/// A supervised session at 25 Hz, ticks 0 to 20 (0 to 800 ms), one frame record.
record::Session session(const std::string& events) {
  record::Session s;
  s.settings.rate_millihertz = 25'000;
  s.settings.supervised = true;
  s.settings.sources = {{"/recorded/stops.yaml", kExportMapping}};
  s.events = input::parse_event_script(events, "session.events");
  s.frames = {record::FrameRecord{.tick = 0, .t_ms = 0}};
  s.end = record::EndRecord{.t_ms = 800, .last_tick = 20, .frames_sent = 21, .why = "SIGINT"};
  return s;
}

std::vector<nlohmann::json> jsonl(const record::Session& s,
                                  const record::SourcesLoader& load = record::load_recorded_mapping) {
  std::ostringstream out;
  EXPECT_EQ(export_session(s, ExportFormat::kJsonl, out, load), "");
  std::vector<nlohmann::json> rows;
  std::istringstream in(out.str());
  for (std::string line; std::getline(in, line);) rows.push_back(nlohmann::json::parse(line));
  return rows;
}

/// The column on each row, as text: "" for an empty string, "-" for null.
std::string column(const std::vector<nlohmann::json>& rows, const char* name) {
  std::string out;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto& v = rows[i].at(name);
    out += (i == 0 ? "" : "|") + (v.is_null() ? "-" : v.is_string() ? v.get<std::string>() : v.dump());
  }
  return out;
}

constexpr const char* kIncident = R"(0 connect Op pad
0 supervisor connect Sup pad
100 button leftshoulder 1
121 supervisor button guide 1
122 supervisor button guide 0
300 button back 1
310 button start 1
330 button back 0
340 button start 0
401 supervisor button x 1
402 supervisor button x 0
440 supervisor button guide 1
600 supervisor button guide 0
650 button back 1
700 button guide 1
)";

record::Session incident() {
  auto s = session(kIncident);
  s.states = {{0, run::OpState::kNotEnabled},   {120, run::OpState::kEnabled}, {160, run::OpState::kStopped},
              {400, run::OpState::kNotEnabled}, {520, run::OpState::kEnabled}, {720, run::OpState::kStopped}};
  const input::PadIdentity sup{.name = "Sup pad", .path = "/dev/input/event7", .serial = "S2", .guid = ""};
  s.stops = {{.t_ms = 160, .reset = false, .by = run::StopBy::kSupervisor, .name = "Sup pad", .pad = sup},
             {.t_ms = 400, .reset = true, .by = run::StopBy::kSupervisor, .name = "Sup pad", .pad = sup},
             // As a session of an earlier version records it: the name, no pad.
             {.t_ms = 720, .reset = false, .by = run::StopBy::kOperator, .name = "Op pad", .pad = {}}};
  return s;
}

/// Runs of values, joined as column() joins them: {{3, "0"}, {2, "1"}} is "0|0|0|1|1".
std::string runs(std::initializer_list<std::pair<int, std::string>> spans) {
  std::string out;
  bool first = true;
  for (const auto& [n, value] : spans) {
    for (int i = 0; i < n; ++i, first = false) out += (first ? "" : "|") + value;
  }
  return out;
}

TEST(SessionExport, EachRowSaysWhoStoppedAndWhoResetWithWhichPad) {
  const auto rows = jsonl(incident());
  ASSERT_EQ(rows.size(), 21U);
  const std::string sup = "Sup pad (path /dev/input/event7, serial S2)";
  EXPECT_EQ(
      column(rows, "state"),
      runs({{3, "not enabled"}, {1, "enabled"}, {6, "stopped"}, {3, "not enabled"}, {5, "enabled"}, {3, "stopped"}}));
  // The supervisor's stop latched from tick 4 (160) to its reset at tick 10
  // (400); the operator's from tick 18 (720), recorded with a name and no pad.
  EXPECT_EQ(column(rows, "stopped_by"), runs({{4, ""}, {6, "supervisor"}, {8, ""}, {3, "operator"}}));
  EXPECT_EQ(column(rows, "stop_pad"), runs({{4, ""}, {6, sup}, {8, ""}, {3, "Op pad"}}));
  // Who reset, from the reset to the next enable (tick 13).
  EXPECT_EQ(column(rows, "reset_by"), runs({{10, ""}, {3, "supervisor"}, {8, ""}}));
  EXPECT_EQ(column(rows, "reset_pad"), runs({{10, ""}, {3, sup}, {8, ""}}));
}

TEST(SessionExport, EachInputIsOneOnTheRowsItWasHeldSinceTheRowBefore) {
  const auto rows = jsonl(incident(), with_resets);
  ASSERT_EQ(rows.size(), 21U);
  // The deadman from 100 on: its row is tick 3 (120).
  EXPECT_EQ(column(rows, "operator_deadman"), runs({{3, "0"}, {18, "1"}}));
  // The supervisor's tap at 121-122, shorter than a tick, on tick 4's row;
  // its hold from 440 to 600 on ticks 11 to 15, while enabled from tick 13.
  EXPECT_EQ(column(rows, "supervisor_stop"), runs({{4, "0"}, {1, "1"}, {6, "0"}, {5, "1"}, {5, "0"}}));
  // back + start held together from 310 to 330: ticks 8 (to 320) and 9
  // (from 320); back alone from 650 is not the chord.
  EXPECT_EQ(column(rows, "operator_reset"), runs({{8, "0"}, {2, "1"}, {11, "0"}}));
  // x tapped at 401-402: tick 11.
  EXPECT_EQ(column(rows, "supervisor_reset"), runs({{11, "0"}, {1, "1"}, {9, "0"}}));
  EXPECT_EQ(column(rows, "operator_estop"), runs({{18, "0"}, {3, "1"}}));
  EXPECT_EQ(column(rows, "supervisor_consent"), runs({{21, "0"}}));
}

TEST(SessionExport, AColumnOfAnInputTheMappingHasNoneOfIsThereAndEmpty) {
  // The recorded mapping has no reset keys: the columns are there, empty.
  auto rows = jsonl(incident());
  EXPECT_EQ(column(rows, "operator_reset"), runs({{21, "-"}}));
  EXPECT_EQ(column(rows, "supervisor_reset"), runs({{21, "-"}}));
  // A reload at 200 to a mapping with no stop buttons and no supervisor: empty from tick 5.
  auto s = incident();
  record::ReloadRecord reload;
  reload.t_ms = 200;
  reload.outcome.ok = true;
  reload.settings = s.settings;
  reload.settings->sources = {{"/recorded/plain.yaml", "robot: HD1\ndeadman: leftshoulder\n"}};
  s.reloads = {reload};
  rows = jsonl(s);
  EXPECT_EQ(column(rows, "supervisor_stop"), runs({{4, "0"}, {1, "1"}, {16, "-"}}));
  EXPECT_EQ(column(rows, "operator_estop"), runs({{5, "0"}, {16, "-"}}));
  EXPECT_EQ(column(rows, "operator_deadman"), runs({{3, "0"}, {18, "1"}}));

  // A recorded mapping that does not load: every input column empty, and why.
  s = incident();
  s.settings.sources = {{"/recorded/bad.yaml", "robot: HD1\n"}};
  std::ostringstream out;
  EXPECT_NE(export_session(s, ExportFormat::kCsv, out).find("the recorded mapping cannot be read"), std::string::npos);
  std::istringstream in(out.str());
  std::string header;
  std::string row;
  std::getline(in, header);
  std::getline(in, row);
  EXPECT_NE(header.find(",link,operator_deadman,operator_estop,operator_reset,supervisor_stop,supervisor_reset,"
                        "supervisor_consent,"),
            std::string::npos)
      << header;
  EXPECT_NE(row.find(",sent,,,,,,,"), std::string::npos) << row;
}

TEST(SessionExport, TheShutdownRequestIsNotAStopColumn) {
  auto s = incident();
  s.requests = {{760, "stop"}};
  s.states.push_back({760, run::OpState::kShuttingDown});
  const auto rows = jsonl(s);
  EXPECT_EQ(column(rows, "shutdown_requested"), runs({{19, "0"}, {2, "1"}}));
  EXPECT_FALSE(rows[0].contains("stop"));
  // An event script's `stop`, recorded as its event, stands for the signal.
  auto scripted = session(std::string(kIncident) + "760 stop\n");
  scripted.states = s.states;
  EXPECT_EQ(column(jsonl(scripted), "shutdown_requested"), runs({{19, "0"}, {2, "1"}}));
  std::ostringstream out;
  export_session(s, ExportFormat::kCsv, out);
  EXPECT_EQ(out.str().substr(0, out.str().find(",operator_deadman")),
            "t,tick,state,stopped_by,stop_pad,reset_by,reset_pad,shutdown_requested,layer,link");
}

/// RFC 4180's fields of one CSV record (quoted fields may hold commas, quotes doubled).
std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      out.back() += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      out.emplace_back();
    } else {
      out.back() += c;
    }
  }
  return out;
}

TEST(SessionExport, TextFromOutsideIsNeverAFormulaNorABrokenRow) {
  auto s = incident();
  s.layers = {{0, "=HYPERLINK(\"http://evil\",\"x\")"},
              {200, "+1"},
              {240, "-2"},
              {280, "@SUM(A1)"},
              {320, "a\nb,\xff\x1b[31m"},
              {360, "\tlead"},
              {400, "arm"}};
  s.stops[0].pad.name = "=cmd|' /C calc'!A0";
  std::ostringstream out;
  export_session(s, ExportFormat::kCsv, out);
  std::istringstream in(out.str());
  std::vector<std::vector<std::string>> rows;
  for (std::string line; std::getline(in, line);) rows.push_back(fields(line));
  ASSERT_EQ(rows.size(), 22U) << "a newline in a name split a row";
  for (const auto& r : rows) ASSERT_EQ(r.size(), rows[0].size());
  const auto index = [&rows](const char* name) {
    return static_cast<std::size_t>(std::find(rows[0].begin(), rows[0].end(), name) - rows[0].begin());
  };
  const auto layer = index("layer");
  EXPECT_EQ(rows[1][layer], "'=HYPERLINK(\"http://evil\",\"x\")");
  EXPECT_EQ(rows[6][layer], "'+1");
  EXPECT_EQ(rows[7][layer], "'-2");
  EXPECT_EQ(rows[8][layer], "'@SUM(A1)");
  EXPECT_EQ(rows[9][layer], "a\\nb,\\xFF\\x1B[31m");
  EXPECT_EQ(rows[10][layer], "\\tlead");
  EXPECT_EQ(rows[11][layer], "arm");
  EXPECT_EQ(rows[5][index("stop_pad")], "'=cmd|' /C calc'!A0 (path /dev/input/event7, serial S2)");
  // Every cell valid UTF-8: JSONL takes the same text.
  const auto json = jsonl(s);
  EXPECT_EQ(json[8].at("layer"), "a\\nb,\\xFF\\x1B[31m");
}

}  // namespace
}  // namespace andros::view
