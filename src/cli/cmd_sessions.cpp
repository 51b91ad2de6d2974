// `andros-bridge sessions`: the flight recorder's sessions, with what each
// holds and whether it is intact (docs/recording.md).
#include <spdlog/fmt/fmt.h>

#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "andros/base/error.hpp"
#include "andros/record/session.hpp"
#include "commands.hpp"
#include "session_files.hpp"

namespace andros::cli {
namespace {

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

void run_sessions(const std::string& dir_given) {
  const auto dir = session_dir(dir_given);
  const auto sessions = list_sessions(dir);
  if (sessions.empty()) {
    std::cout << "no sessions in " << dir.string() << "\n";
    return;
  }
  std::cout << "sessions in " << dir.string() << ":\n";
  std::cout << fmt::format("{:<19}  {:>8}  {:<9}  {:>7}  {:<18}  {}\n", "START", "LENGTH", "ROBOT", "FRAMES", "VERIFY",
                           "FILE");
  // Names the other commands accept from any folder: bare in the default
  // folder (they look there), whole paths from another.
  const bool bare = dir == session_dir("");
  for (const auto& path : sessions) {
    const auto name = bare ? path.filename().string() : std::filesystem::absolute(path).string();
    std::string verdict;
    try {
      const auto check = record::verify_session(path);
      verdict = !check.intact               ? "NOT INTACT"
                : check.cut_short_line != 0 ? "intact, cut short"
                : check.closed              ? "intact"
                                            : "intact, not closed";
      const auto s = record::read_session(path);
      std::cout << fmt::format("{:<19}  {:>8}  {:<9}  {:>7}  {:<18}  {}\n", start_text(s.started),
                               duration_text(s.length_ms()), s.settings.robot, s.frames_sent(), verdict, name);
    } catch (const std::exception& e) {
      std::cout << fmt::format("{:<19}  {:>8}  {:<9}  {:>7}  {:<18}  {}\n", "?", "?", "?", "?",
                               verdict.empty() ? "unreadable" : verdict, name);
    }
  }
}

}  // namespace

void add_sessions_command(CLI::App& app, int& exit_code) {
  auto dir = std::make_shared<std::string>();
  auto* cmd =
      app.add_subcommand("sessions",
                         "List the flight recorder's sessions (docs/recording.md), oldest first: start, length,\n"
                         "robot, frames sent and the verdict of 'verify'.");
  cmd->add_option("--record-dir,--dir", *dir,
                  "the folder to list (run's --record-dir; --dir is the same option's older name);\n"
                  "default $STATE_DIRECTORY, else $XDG_STATE_HOME/andros-bridge, else\n"
                  "~/.local/state/andros-bridge (as run)")
      ->type_name("DIR");
  cmd->callback([dir, &exit_code] {
    run_sessions(*dir);
    exit_code = kExitOk;
  });
}

}  // namespace andros::cli
