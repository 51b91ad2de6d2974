// andros-bridge: a gamepad in, the Andros switchbox's serial frames out.
#include <CLI/CLI.hpp>
#include <exception>
#include <string>

#include "andros/error.hpp"
#include "andros/io/log_sink.hpp"
#include "andros/version.hpp"
#include "commands.hpp"

int main(int argc, char** argv) {
  // Log lines go to stderr through a queue and a thread of their own (which
  // blocks every signal, SIGPIPE included): stdout carries data (frame
  // decode, `record -o -`) or the status view.
  const auto log = andros::io::install_stderr_log();

  CLI::App app{
      "andros-bridge: drive an Andros robot with a gamepad. Reads the controller, maps it\n"
      "through a per-robot YAML mapping and streams the Remotec switchbox's 36-byte\n"
      "command frames to the vehicle's serial link at 25 Hz, with the safety rules applied.",
      "andros-bridge"};
  app.set_version_flag("--version", std::string("andros-bridge ") + andros::kVersion);
  app.require_subcommand(1);
  app.footer("Exit codes: 0 success, 1 runtime failure, 2 bad input.\n"
             "Run 'andros-bridge COMMAND --help' for a command's options.");
  int exit_code = andros::kExitOk;
  andros::cli::add_frame_command(app, exit_code);
  andros::cli::add_replay_command(app, exit_code);
  andros::cli::add_check_command(app, exit_code);
  andros::cli::add_run_command(app, exit_code);
  andros::cli::add_monitor_command(app, exit_code);
  andros::cli::add_controllers_command(app, exit_code);
  andros::cli::add_record_command(app, exit_code);

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --version
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    log->write_line(std::string("andros-bridge: error: ") + e.what() + " (see --help)");
    return andros::kExitBadInput;
  } catch (const andros::InputError& e) {
    // With no file to name, say which program is talking.
    log->write_line((e.pos().file.empty() ? "andros-bridge: " : "") + std::string(e.what()));
    return andros::kExitBadInput;
  } catch (const std::exception& e) {
    log->write_line(std::string("andros-bridge: error: ") + e.what());
    return andros::kExitRuntime;
  }
  return exit_code;
}
