#pragma once
/// Each subcommand registers itself on the top-level CLI11 app. A command's
/// callback runs during parsing, sets the exit code, and lets InputError and
/// RuntimeError escape to main(), which turns them into one line and a code.

#include <CLI/CLI.hpp>

namespace andros::cli {

void add_frame_command(CLI::App& app, int& exit_code);
void add_replay_command(CLI::App& app, int& exit_code);
void add_check_command(CLI::App& app, int& exit_code);
void add_run_command(CLI::App& app, int& exit_code);
/// `run` with the simulated vehicle shown on a local web page (docs/trainer.md).
void add_trainer_command(CLI::App& app, int& exit_code);
void add_monitor_command(CLI::App& app, int& exit_code);
void add_controllers_command(CLI::App& app, int& exit_code);
void add_record_command(CLI::App& app, int& exit_code);
/// Hidden: the command line as JSON (scripts/man/ makes the man page and completion from it).
void add_help_data_command(CLI::App& app, int& exit_code);
void add_sheet_command(CLI::App& app, int& exit_code);
void add_learn_command(CLI::App& app, int& exit_code);
void add_inputs_command(CLI::App& app, int& exit_code);
void add_verify_command(CLI::App& app, int& exit_code);
void add_sessions_command(CLI::App& app, int& exit_code);
void add_plot_command(CLI::App& app, int& exit_code);
void add_export_command(CLI::App& app, int& exit_code);

}  // namespace andros::cli
