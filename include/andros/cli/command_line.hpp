#pragma once
/// The settings table on a command's command line: its options, and the merge
/// of defaults, the config file and the flags given (docs/running.md).

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "andros/cli/config.hpp"
#include "andros/cli/settings.hpp"

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace andros::cli {

/// The flags given on a command line, copied: what a reload merges over the
/// config file again on a thread of its own, which must not reach into the
/// CLI11 app.
struct GivenFlags {
  Command command = kRun;
  /// Each flag given: its row and its text ("enabled" for a switch), in the table's order.
  std::vector<std::pair<const Setting*, std::string>> values;
  /// The text given for a flag by its primary name ("--rate"); nullopt when not given.
  [[nodiscard]] std::optional<std::string> given(std::string_view flag) const;
};

/// The flags one command takes, declared on its CLI11 app from the table.
/// Holds the text CLI11 writes while parsing: keep it alive (in a shared_ptr,
/// as the commands' own options) until the callback has run.
class CommandLine {
 public:
  CommandLine(CLI::App& cmd, Command command);
  CommandLine(const CommandLine&) = delete;
  CommandLine& operator=(const CommandLine&) = delete;

  [[nodiscard]] Command command() const { return command_; }
  /// The text given for a flag (by its primary name, "--rate"); a switch
  /// given is "enabled"; nullopt when not given.
  [[nodiscard]] std::optional<std::string> given(std::string_view flag) const;
  /// Every flag given, copied.
  [[nodiscard]] GivenFlags given_flags() const;

 private:
  struct Entry {
    const Setting* row;
    CLI::Option* option;
    std::string text;
  };
  Command command_;
  std::vector<Entry> entries_;  ///< sized once: CLI11 holds pointers into it
};

/// A command's settings: the defaults, then (for `run`) the config file,
/// `--config` or else the first default path that exists, then each flag
/// given; a `--robot` flag also drops a mapping from the file. Then the rate
/// is checked against the final baud, at the line or flag that set it.
/// The one call that (re)reads the config file and merges it with the flags.
Settings resolve_settings(const CommandLine& flags);

/// The same from copied flags. kReload reads only a regular config file and
/// logs nothing (safe on a thread of its own; the reload's own line names
/// the file).
Settings resolve_settings(const GivenFlags& flags, ConfigRead read);

/// The first of default_config_paths() that exists, "" for none. A place that
/// cannot be looked into (a HOME the user may not read) is passed over, and
/// said in the log when warn is true: it holds no config this run could read,
/// and the next place may.
std::string find_default_config(bool warn);

/// Applies the flags given to settings (the last step of resolve_settings).
void apply_flags(const GivenFlags& flags, Settings& settings);

}  // namespace andros::cli
