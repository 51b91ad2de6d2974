// `andros-bridge sessions`: the flight recorder's sessions, with what each
// holds, what an investigator looks for first (weapons fired, stops and
// resets, the controllers and the link lost: session_summary.hpp) and whether it is
// intact (docs/recording.md). A session is data: one that is not intact is
// listed with what the records before its break say and marked, one that
// cannot be read is listed as such; none is left out. Each is read as the
// other commands read it (record::read_checked_session), one at a time.
#include <spdlog/fmt/fmt.h>

#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "andros/base/error.hpp"
#include "andros/base/sink_text.hpp"
#include "andros/record/session.hpp"
#include "andros/record/session_replay.hpp"
#include "andros/trainer/course_file.hpp"
#include "andros/trainer/course_score.hpp"
#include "commands.hpp"
#include "session_files.hpp"
#include "session_summary.hpp"

namespace andros::cli {
namespace {

struct SessionsOptions {
  std::string dir;
  std::string format = "table";
};

/// One session as listed: what was read of it, and how far it can be trusted.
/// Only what the table and the JSON show is kept, not the session's records:
/// the folder is read a session at a time.
struct Row {
  std::string name;
  /// intact, intact, cut short, intact, not closed, intact, disk full, NOT INTACT, unreadable (the chain whole)
  std::string verdict;
  bool intact = false;
  std::string problem;  ///< verify's, or why it could not be read
  std::string note;     ///< how it ends, when that needs saying: stopped for want of room, a NUL tail
  bool readable = false;
  std::string started;
  std::int64_t length_ms = 0;
  std::string robot;
  std::uint64_t frames_sent = 0;
  bool supervised = false;
  std::uint64_t dropped = 0;
  SessionSummary summary;
  /// The replay made every record again the same (weapons fired and stops
  /// are then what the loop makes of the recorded input, not only what the
  /// records say); else why not.
  bool proven = false;
  std::string unproven;
  std::string course;  ///< a trainer run's course ("" for any other run)
  std::string score;   ///< and its score, a JSON object ("" when the run recorded none)
  /// The replay, fed to the course's scorer, gave the recorded score again (the same session, the same score).
  bool score_proven = false;
};

/// A trainer run's line under the table: its course and score, as its records say them.
std::string training_text(const Row& r) {
  std::string out = "trainer, course " + terminal_text(r.course) + ": ";
  if (r.score.empty()) return out + "no score recorded (the run did not end)";
  const auto j = nlohmann::json::parse(r.score);
  const auto stops = j.at("stops").size();
  return out + terminal_text(j.at("result").get<std::string>()) +
         fmt::format(
             ", {:.1f} s, gates {}/{}, contacts {}, stops {}, inputs not at rest {}, fired {} ({} off target, "
             "{} refused), tipped over: {}",
             j.at("time_s").get<double>(), j.at("gates").get<int>(), j.at("gates_total").get<int>(),
             j.at("contacts").get<int>(), stops, j.at("not_at_rest").get<int>(), j.at("fired").get<int>(),
             j.at("fired_off_target").get<int>(), j.at("fire_refused").get<int>(),
             j.at("tipped").get<bool>() ? "yes" : "no") +
         (r.score_proven ? "; the replay gives the same score" : "; the score NOT proven by replay");
}

/// Whether the replay proves the session's records: WEAPONS and STOPS are counted from them.
void prove(Row& row, const record::Session& session) {
  if (!row.intact) {
    row.unproven = "not intact";
    return;
  }
  try {
    // An earlier format's ticks are bounded by 24 h only: replayed when they are within its records' 60 s each.
    record::check_record_spacing(session, true);
    // A trainer run's course scores the replay's ticks as the live run's were.
    std::optional<trainer::CourseScorer> scorer;
    if (session.course) {
      scorer.emplace(vehicle::figures_for(session.settings.robot),
                     trainer::parse_course(session.course->path, session.course->text));
    }
    const auto result = record::replay_session(session, record::load_recorded_mapping, [&](const run::TickReport& r) {
      if (scorer) scorer->on_tick(r);
    });
    if (scorer && session.score) {
      row.score_proven =
          nlohmann::json::parse(trainer::score_json(scorer->score())) == nlohmann::json::parse(session.score->json);
    }
    row.proven = result.proven();
    if (!result.identical) row.unproven = result.difference;
    else if (!row.proven) row.unproven = std::to_string(result.unproven) + " records after the last frame record";
  } catch (const std::exception& e) {
    row.unproven = e.what();  // records dropped, a mapping that does not load, ticks its records do not hold
  }
}

std::string verdict_of(const record::CheckedSession& checked) {
  const auto& v = checked.verdict;
  if (!v.intact) return "NOT INTACT";
  if (checked.unreadable) return "unreadable";
  if (v.cut_short_line != 0) return "intact, cut short";
  if (v.closed) return checked.session->stopped_for_room ? "intact, disk full" : "intact";
  return checked.session->stopped_for_room ? "intact, disk full" : "intact, not closed";
}

/// What a session's end needs said beside the verdict, or "".
std::string note_of(const record::CheckedSession& checked) {
  if (checked.verdict.intact && checked.session && checked.session->stopped_for_room)
    return record::room_text(*checked.session);
  if (checked.verdict.intact && checked.verdict.nul_tail != 0) return record::closing_text(checked);
  return {};
}

Row read_row(const std::filesystem::path& path, std::string name) {
  Row row;
  row.name = std::move(name);
  try {
    // The one reading verify, replay, plot and export make: a NOT INTACT
    // session is listed with what the records before its break say.
    const auto checked = record::read_checked_session(path);
    row.intact = checked.verdict.intact;
    row.verdict = verdict_of(checked);
    row.problem = !checked.verdict.problem.empty() ? checked.verdict.problem
                  : checked.unreadable             ? checked.unreadable->what()
                                                   : "";
    row.note = note_of(checked);
    if (!checked.session) return row;
    const auto& s = *checked.session;
    row.readable = true;
    row.started = s.started;
    row.length_ms = s.length_ms();
    row.robot = s.settings.robot;
    row.frames_sent = s.frames_sent();
    row.supervised = s.settings.supervised;
    row.dropped = s.dropped;
    row.summary = summarize_session(s);
    if (s.course) row.course = s.course->name;
    if (s.score) row.score = s.score->json;
    prove(row, s);
  } catch (const std::exception& e) {
    row.readable = false;
    row.verdict = "unreadable";
    row.problem = e.what();
  }
  return row;
}

std::string duration_text(std::int64_t ms) {
  const std::int64_t s = ms / 1000;
  return fmt::format("{}:{:02}:{:02}", s / 3600, s / 60 % 60, s % 60);
}

/// "2024-05-01T12:00:00+0200" as "2024-05-01 12:00:00".
std::string start_text(const std::string& iso) {
  if (iso.size() < 19) return iso;
  std::string out = iso.substr(0, 19);
  out[10] = ' ';
  return out;
}

/// "0", or "3 (op 2, gate 1)": a count and its parts by whom.
std::string by_whom(const std::vector<std::pair<const char*, int>>& parts) {
  int total = 0;
  std::string list;
  for (const auto& [who, n] : parts) {
    total += n;
    if (n != 0) list += fmt::format("{}{} {}", list.empty() ? "" : ", ", who, n);
  }
  return total == 0 ? "0" : fmt::format("{} ({})", total, list);
}

constexpr const char* kRowFormat = "{:<19}  {:>8}  {:<9}  {:>7}  {:<7}  {:<23}  {:<16}  {:<16}  {:>9}  {:<18}  {}\n";

void print_table(const std::vector<Row>& rows) {
  std::cout << fmt::format(kRowFormat, "START", "LENGTH", "ROBOT", "FRAMES", "WEAPONS", "STOPS", "RESETS",
                           "CONTROLLERS LOST", "LINK LOST", "VERIFY", "FILE");
  int untrusted = 0;
  int unproven = 0;
  for (const auto& r : rows) {
    if (!r.intact || !r.readable) ++untrusted;
    if (!r.readable) {
      std::cout << fmt::format(kRowFormat, "?", "?", "?", "?", "?", "?", "?", "?", "?", r.verdict,
                               terminal_text(r.name));
      continue;
    }
    if (!r.proven) ++unproven;
    const auto& m = r.summary;
    const std::string mark = r.proven ? "" : "?";
    std::cout << fmt::format(kRowFormat, terminal_text(start_text(r.started)), duration_text(r.length_ms),
                             terminal_text(r.robot), r.frames_sent, (m.weapons_fired ? "FIRED" : "no") + mark,
                             by_whom({{"op", m.stops[0]}, {"sup", m.stops[1]}, {"gate", m.stops[2]}}) + mark,
                             by_whom({{"op", m.resets[0]}, {"sup", m.resets[1]}}),
                             by_whom({{"op", m.controllers_lost[0]}, {"sup", m.controllers_lost[1]}}), m.links_lost,
                             r.verdict, terminal_text(r.name));
  }
  if (untrusted != 0) {
    std::cout << fmt::format(
        "{} of {} sessions NOT INTACT or unreadable: what the table shows of them is what their records say, "
        "not evidence ('verify SESSION' names the first record altered)\n",
        untrusted, rows.size());
  }
  if (unproven != 0) {
    std::cout << fmt::format(
        "{} of {} sessions with WEAPONS and STOPS marked ?: what their records say, not proven by replay "
        "('replay SESSION' says why)\n",
        unproven, rows.size());
  }
  for (const auto& r : rows) {
    if (!r.note.empty()) std::cout << fmt::format("{}: {}\n", terminal_text(r.name), terminal_line(r.note));
  }
  for (const auto& r : rows) {
    if (!r.course.empty()) std::cout << fmt::format("{}: {}\n", terminal_text(r.name), training_text(r));
  }
}

nlohmann::json json_row(const Row& r) {
  nlohmann::json j = {{"file", json_text(r.name)},
                      {"verify", r.verdict},
                      {"intact", r.intact},
                      {"problem", json_text(r.problem)},
                      {"readable", r.readable}};
  if (!r.note.empty()) j["note"] = json_text(r.note);
  if (!r.readable) return j;
  const auto& m = r.summary;
  j["start"] = json_text(r.started);
  j["length_s"] = static_cast<double>(r.length_ms) / 1000.0;
  j["robot"] = json_text(r.robot);
  j["frames_sent"] = r.frames_sent;
  j["supervised"] = r.supervised;
  j["proven"] = r.proven;
  j["unproven"] = json_text(r.unproven);
  j["weapons_fired"] = m.weapons_fired;
  j["weapons"] = m.weapons;
  j["first_fire_s"] = m.first_fire_ms ? nlohmann::json(static_cast<double>(*m.first_fire_ms) / 1000.0) : nullptr;
  j["stops"] = {{"operator", m.stops[0]}, {"supervisor", m.stops[1]}, {"gate", m.stops[2]}};
  j["resets"] = {{"operator", m.resets[0]}, {"supervisor", m.resets[1]}};
  j["controllers_lost"] = {{"operator", m.controllers_lost[0]}, {"supervisor", m.controllers_lost[1]}};
  j["links_lost"] = m.links_lost;
  j["dropped"] = r.dropped;
  if (!r.course.empty()) {
    j["course"] = json_text(r.course);
    j["score"] = r.score.empty() ? nlohmann::json(nullptr) : nlohmann::json::parse(r.score);
    j["score_proven"] = r.score_proven;
  }
  return j;
}

void run_sessions(const SessionsOptions& opt) {
  if (opt.format != "table" && opt.format != "jsonl") {
    throw InputError(SourcePos{"--format"}, "expected table or jsonl, got " + quote(opt.format));
  }
  const auto dir = session_dir(opt.dir);
  const auto sessions = list_sessions(dir);
  // Names the other commands accept from any folder: bare in the default
  // folder (they look there), whole paths from another.
  const bool bare = dir == session_dir("");
  std::vector<Row> rows;
  rows.reserve(sessions.size());
  for (const auto& path : sessions) {
    rows.push_back(read_row(path, bare ? path.filename().string() : std::filesystem::absolute(path).string()));
  }
  if (opt.format == "jsonl") {
    for (const auto& r : rows) std::cout << json_row(r).dump() << "\n";
    return;
  }
  if (rows.empty()) {
    std::cout << "no sessions in " << terminal_text(dir.string()) << "\n";
    return;
  }
  std::cout << "sessions in " << terminal_text(dir.string()) << ":\n";
  print_table(rows);
}

}  // namespace

void add_sessions_command(CLI::App& app, int& exit_code) {
  auto opt = std::make_shared<SessionsOptions>();
  auto* cmd =
      app.add_subcommand("sessions",
                         "List the flight recorder's sessions (docs/recording.md), oldest first: start, length,\n"
                         "robot, frames sent, whether weapons fired (a weapon signal in a frame sent while\n"
                         "enabled), the stops by whom (op: the operator's stop button, sup: the supervisor's,\n"
                         "gate: the frame gate), the stops reset by whom (op, sup), the controllers lost (op,\n"
                         "sup), the link lost, and the verdict of 'verify'. WEAPONS and STOPS are proven by\n"
                         "replay (the loop run again makes every record the same); marked ? when not (what the\n"
                         "records say). A session that is not intact is listed with what the records before its\n"
                         "break say, marked NOT INTACT; one that cannot be read, as unreadable. A last line cut\n"
                         "short is never counted.");
  cmd->add_option("--record-dir,--dir", opt->dir,
                  "the folder to list (run's --record-dir; --dir is the same option's older name);\n"
                  "default $STATE_DIRECTORY, else $XDG_STATE_HOME/andros-bridge, else\n"
                  "~/.local/state/andros-bridge (as run)")
      ->type_name("DIR");
  cmd->add_option("--format", opt->format,
                  "table (for people) or jsonl (an object a session, for tools: its fields in\n"
                  "docs/recording.md)")
      ->type_name("table|jsonl")
      ->default_str("table");
  cmd->callback([opt, &exit_code] {
    run_sessions(*opt);
    exit_code = kExitOk;
  });
}

}  // namespace andros::cli
