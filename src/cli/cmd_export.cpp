// `andros-bridge export SESSION --format csv|jsonl`: a session as a table, a
// row per tick (docs/recording.md, "Export").
#include <spdlog/spdlog.h>

#include <memory>
#include <string>

#include "andros/base/error.hpp"
#include "andros/base/output_file.hpp"
#include "andros/record/session.hpp"
#include "andros/trainer/trainer_replay.hpp"
#include "andros/view/session_export.hpp"
#include "commands.hpp"
#include "session_files.hpp"

namespace andros::cli {
namespace {

struct ExportOptions {
  std::string session;
  std::string format = "csv";
  std::string output;
};

void run_export(const ExportOptions& opt) {
  const auto format = view::parse_export_format(opt.format, SourcePos{"--format"});
  // The one reading verify makes: the records of the chain's intact part,
  // never a last line cut short; what is left out is said.
  const auto checked = record::read_checked_session(opt.session);
  if (checked.unreadable) throw *checked.unreadable;
  const auto& verdict = checked.verdict;
  if (!verdict.intact) {
    spdlog::warn("NOT INTACT: {}: exported the {} records before it, not evidence (andros-bridge verify)",
                 verdict.problem, verdict.records);
  } else if (verdict.cut_short_line != 0) {
    spdlog::warn("{}", record::cut_short_text(verdict));
  }
  if (verdict.intact && checked.session->stopped_for_room) spdlog::warn("{}", record::room_text(*checked.session));
  // Written as the rows come: a failed write leaves FILE as it was.
  OutputFile out(opt.output.empty() ? "-" : opt.output);
  const auto why_no_inputs = view::export_session(*checked.session, format, out.stream(), record::load_recorded_mapping,
                                                  trainer::recorded_course(*checked.session));
  out.commit();
  if (!why_no_inputs.empty()) spdlog::warn("the input columns are empty: {}", why_no_inputs);
}

}  // namespace

void add_export_command(CLI::App& app, int& exit_code) {
  auto opt = std::make_shared<ExportOptions>();
  auto* cmd =
      app.add_subcommand("export",
                         "Write a flight recorder session (docs/recording.md) as a table, one row per tick\n"
                         "the live loop ran: the time (one strictly increasing column, in seconds), the\n"
                         "operating state; who stopped (stopped_by: operator, supervisor or gate) and\n"
                         "with which pad (stop_pad), who reset the last stop and with which pad\n"
                         "(reset_by, reset_pad); shutdown_requested (a SIGINT, SIGTERM...: not a stop\n"
                         "button); the layer; what the link did with the frame; what the hands held,\n"
                         "read from the recorded input with the recorded mapping (operator_deadman,\n"
                         "operator_estop, operator_reset, supervisor_stop, supervisor_reset,\n"
                         "supervisor_consent: 1 when held at any moment since the row before, so that a\n"
                         "press shorter than a tick shows; empty when the mapping has no such input);\n"
                         "then every signal of the frame by name (drive, pivot...); then where the\n"
                         "trainer's vehicle model is after the tick (vehicle_x, vehicle_y, vehicle_heading,\n"
                         "front_flipper, rear_flipper, arm_torso, arm_shoulder, arm_elbow, arm_wrist,\n"
                         "arm_wrist_extension, gripper_opening, gripper_rotation; docs/trainer.md). For a\n"
                         "spreadsheet, PlotJuggler or Python's csv module, as it is. Read as verify reads it: a last\n"
                         "line cut short is left out, and of a session that is not intact only the records\n"
                         "before the break are exported, with a warning.");
  cmd->add_option("SESSION", opt->session,
                  "a session file, or its bare name as 'sessions' prints it (looked up in the\n"
                  "sessions' folder)")
      ->required();
  cmd->add_option("--format", opt->format, "csv (a header row, then a row a tick) or jsonl (an object a line)")
      ->type_name("csv|jsonl")
      ->default_str("csv");
  cmd->add_option("--output", opt->output,
                  "write to FILE instead of standard output (- is standard output); a failed\n"
                  "write leaves FILE as it was (docs/running.md, Output files)")
      ->type_name("FILE");
  cmd->callback([opt, &exit_code] {
    opt->session = find_session(opt->session);  // a bare session name, as `sessions` prints it
    run_export(*opt);
    exit_code = kExitOk;
  });
}

}  // namespace andros::cli
