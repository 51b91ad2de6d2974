// `andros-bridge verify SESSION`: is the flight recorder's session as it was
// written (docs/recording.md)?
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "andros/base/error.hpp"
#include "andros/base/sink_text.hpp"
#include "andros/record/session.hpp"
#include "commands.hpp"
#include "session_files.hpp"

namespace andros::cli {
namespace {

int run_verify(const std::string& path) {
  std::error_code ec;
  // Anything else that is there (a FIFO, a device) is refused by the reading, saying what it is.
  if (!std::filesystem::exists(path, ec)) throw InputError(SourcePos{path}, "no such session file");
  const auto checked = record::read_checked_session(path, record::Keep::kVerdict);
  const auto& result = checked.verdict;
  if (!result.intact) {
    std::cout << "NOT INTACT: " << terminal_line(result.problem) << "\n";
    return kExitRuntime;
  }
  // Half a record at the end is a run cut off, told apart from an edit: the records before it stand.
  if (result.cut_short_line != 0) std::cout << record::cut_short_text(result) << "\n";
  else std::cout << "intact (" << result.records << " records)\n";
  // A whole chain of records that are not a session's (crafted, or another program's): what
  // sessions, replay, plot and export refuse is not vouched for here either.
  if (checked.unreadable) std::cout << "unreadable: " << checked.unreadable->what() << "\n";
  std::cout << record::closing_text(checked) << "\n";
  std::cout << "last hash: " << result.last_hash << "\n";
  return checked.unreadable ? kExitRuntime : kExitOk;
}

}  // namespace

void add_verify_command(CLI::App& app, int& exit_code) {
  auto path = std::make_shared<std::string>();
  auto* cmd =
      app.add_subcommand("verify",
                         "Check a flight recorder session's hash chain (docs/recording.md): prints 'intact (N\n"
                         "records)' and the last record's hash (exit 0), or the first record that was altered,\n"
                         "removed or reordered (exit 1). A last line without its newline is 'cut short' and never\n"
                         "read; records whose chain is whole but which are not a session's are 'unreadable'\n"
                         "(exit 1), as sessions, replay, plot and export find them: all read it the same way.");
  cmd->add_option("SESSION", *path,
                  "a session file, or its bare name as 'andros-bridge sessions' prints it (looked up in\n"
                  "the sessions' folder)")
      ->required();
  cmd->callback([path, &exit_code] { exit_code = run_verify(find_session(*path)); });
}

}  // namespace andros::cli
