// The program, run by main() (main.cpp): the commands, their parse, and what
// escapes them turned into a line and an exit code.
#include "program.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>
#include <string_view>
#include <vector>

#include "andros/base/error.hpp"
#include "andros/base/error_list.hpp"
#include "andros/base/sink_text.hpp"
#include "andros/base/version.hpp"
#include "andros/timing/rate.hpp"
#include "andros/view/log_sink.hpp"
#include "commands.hpp"

namespace {

// Output that never reached its file is a failure even when the command went
// well (as coreutils' close_stdout): a full disk must not pass for a complete
// capture. An error already reported keeps its own line and code.
int check_stdout(int exit_code, andros::view::FdLogSink& log) {
  errno = 0;
  const bool flushed = std::fflush(stdout) == 0;  // std::cout writes through stdout's buffer (synced)
  const int error = errno;
  if (flushed && std::ferror(stdout) == 0) return exit_code;
  if (exit_code != andros::kExitOk) return exit_code;
  log.write_line(std::string("andros-bridge: error: standard output: ") +
                 (error != 0 ? std::strerror(error) : "write error"));
  return andros::kExitRuntime;
}

// An empty value would read as "not given" and fall back to a default
// (`--mapping ""` running the shipped mapping): no option takes one.
void refuse_empty_values(CLI::App& app) {
  const auto takes_value = [](CLI::Option* o) { return !o->get_positional() && o->get_items_expected_min() > 0; };
  for (auto* option : app.get_options(takes_value)) {
    option->check([name = option->get_name()](const std::string& value) -> std::string {
      if (value.empty()) {
        throw andros::InputError(andros::SourcePos{name}, "empty value (give one, or leave the option out)");
      }
      return {};
    });
  }
  for (auto* sub : app.get_subcommands([](CLI::App*) { return true; })) refuse_empty_values(*sub);
}

// Started with stdin, stdout or stderr closed (`2>&-`), the first file the
// program opens (the serial port) would take that number, and log lines or the
// status view would go out on the vehicle's link: each closed one is held on
// /dev/null instead, before anything else is opened.
void keep_standard_descriptors_taken() {
  for (int fd = STDIN_FILENO; fd <= STDERR_FILENO; ++fd) {
    if (fcntl(fd, F_GETFD) != -1 || errno != EBADF) continue;
    const int null = open("/dev/null", O_RDWR);  // the lowest free number: this one
    if (null < 0) std::abort();                  // no /dev/null: nothing safe to run on
  }
}

/// The commands, "frame, replay, ...", as --help lists them (not the hidden help-data).
std::string command_list(CLI::App& app) {
  std::string out;
  for (const auto* sub : app.get_subcommands([](CLI::App* s) { return !s->get_group().empty(); })) {
    out += (out.empty() ? "" : ", ") + sub->get_name();
  }
  return out;
}

/// What CLI11 says of a missing or mistyped command ("A subcommand is
/// required") names neither: say which word was not a command and list them.
/// Empty when the first word is a command or an option.
std::string command_error(CLI::App& app, int argc, char** argv) {
  if (argc < 2) return "no command given (one of: " + command_list(app) + ")";
  const std::string_view word = argv[1];
  if (word.starts_with('-')) return {};
  for (const auto* sub : app.get_subcommands([](CLI::App*) { return true; })) {
    if (sub->check_name(std::string(word))) return {};
  }
  return "unknown command " + andros::quote(word) + " (one of: " + command_list(app) + ")";
}

/// Parses (which runs the chosen command) and turns what escapes into a line and a code.
int run(CLI::App& app, int argc, char** argv, const int& exit_code, andros::view::FdLogSink& log) {
  if (const auto error = command_error(app, argc, argv); !error.empty()) {
    log.write_line("andros-bridge: error: " + error + " (see --help)");
    return andros::kExitBadInput;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --version
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    log.write_line(std::string("andros-bridge: error: ") + e.what() + " (see --help)");
    return andros::kExitBadInput;
  } catch (const andros::InputError& e) {
    // With no file to name, say which program is talking. Several errors of
    // one input, a line each: a log line is one line (a newline in it is escaped).
    const auto* several = dynamic_cast<const andros::InputErrors*>(&e);
    for (const auto& one : several != nullptr ? several->errors() : std::vector<andros::InputError>{e}) {
      log.write_line((one.pos().file.empty() ? "andros-bridge: " : "") + std::string(one.what()));
    }
    return andros::kExitBadInput;
  } catch (const std::exception& e) {
    log.write_line(std::string("andros-bridge: error: ") + e.what());
    return andros::kExitRuntime;
  }
  return exit_code;
}

}  // namespace

// What run() does not catch, such as no memory or no thread for the log
// before any command runs, ends the program with a line, not an abort.
int andros::cli::program_main(int argc, char** argv) try {
  // A write past a file-size limit (`ulimit -f`, RLIMIT_FSIZE) fails with
  // EFBIG, for every command: the flight recorder drops and warns, an output
  // file says so, and a run goes on driving (SIGXFSZ's default ends the process).
  std::signal(SIGXFSZ, SIG_IGN);
  keep_standard_descriptors_taken();
  // Log lines go to stderr through a queue and a thread of their own (which
  // blocks every signal, SIGPIPE included): stdout carries data (frame
  // decode, `record -o -`) or the status view. Error lines take the same
  // queue, so they keep their order.
  const auto log = andros::view::install_stderr_log();

  CLI::App app{
      "andros-bridge: drive an Andros robot with a gamepad. Reads the controller, maps it\n"
      "through a per-robot YAML mapping and streams the Remotec switchbox's 36-byte\n"
      "command frames to the vehicle's serial link at " +
          andros::timing::rate_text(andros::timing::kDefaultRateMillihertz) + " Hz, with the safety rules applied.",
      "andros-bridge"};
  app.set_version_flag("--version", std::string("andros-bridge ") + andros::kVersion);
  app.require_subcommand(1);
  app.footer(
      "Exit codes: 0 success, 1 runtime failure (also output lost to a full disk), 2 bad input.\n"
      "Run 'andros-bridge COMMAND --help' for a command's options.");
  int exit_code = andros::kExitOk;
  andros::cli::add_frame_command(app, exit_code);
  andros::cli::add_replay_command(app, exit_code);
  andros::cli::add_check_command(app, exit_code);
  andros::cli::add_run_command(app, exit_code);
  andros::cli::add_trainer_command(app, exit_code);
  andros::cli::add_monitor_command(app, exit_code);
  andros::cli::add_controllers_command(app, exit_code);
  andros::cli::add_record_command(app, exit_code);
  andros::cli::add_help_data_command(app, exit_code);
  andros::cli::add_sheet_command(app, exit_code);
  andros::cli::add_learn_command(app, exit_code);
  andros::cli::add_inputs_command(app, exit_code);
  andros::cli::add_verify_command(app, exit_code);
  andros::cli::add_sessions_command(app, exit_code);
  andros::cli::add_plot_command(app, exit_code);
  andros::cli::add_export_command(app, exit_code);
  refuse_empty_values(app);

  return check_stdout(run(app, argc, argv, exit_code, *log), *log);
} catch (const std::exception& e) {
  std::fprintf(stderr, "andros-bridge: error: %s\n", andros::terminal_line(e.what()).c_str());
  return andros::kExitRuntime;
} catch (...) {
  std::fprintf(stderr, "andros-bridge: error: an unknown exception\n");
  return andros::kExitRuntime;
}
