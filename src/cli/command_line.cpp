#include "andros/cli/command_line.hpp"

#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <filesystem>

namespace andros::cli {

std::string find_default_config(bool warn) {
  for (const auto& path : default_config_paths()) {
    std::error_code error;
    if (std::filesystem::exists(path, error)) return path;
    if (error && warn) spdlog::warn("config: cannot look for {}: {}; going on without it", path, error.message());
  }
  return {};
}

CommandLine::CommandLine(CLI::App& cmd, Command command) : command_(command) {
  for (const auto& row : settings_table()) {
    if ((row.commands & command) != 0) entries_.push_back(Entry{&row, nullptr, {}});
  }
  for (auto& entry : entries_) {
    const auto& row = *entry.row;
    const std::string names(row.flag);
    if (row.value_name.empty()) {
      entry.option = cmd.add_flag(names)->description(help_text(row));
    } else {
      entry.option = cmd.add_option(names, entry.text, help_text(row))
                         ->type_name(std::string(row.value_name))
                         ->default_str(default_text(row));
    }
  }
}

std::optional<std::string> GivenFlags::given(std::string_view flag) const {
  for (const auto& [row, text] : values) {
    if (flag_name(*row) == flag) return text;
  }
  return std::nullopt;
}

std::optional<std::string> CommandLine::given(std::string_view flag) const {
  for (const auto& entry : entries_) {
    if (flag_name(*entry.row) != flag || entry.option->count() == 0) continue;
    return entry.row->value_name.empty() ? std::string(switch_text(*entry.row)) : entry.text;
  }
  return std::nullopt;
}

GivenFlags CommandLine::given_flags() const {
  GivenFlags flags{command_, {}};
  for (const auto& entry : entries_) {
    if (entry.option->count() == 0) continue;
    flags.values.emplace_back(entry.row,
                              entry.row->value_name.empty() ? std::string(switch_text(*entry.row)) : entry.text);
  }
  return flags;
}

void apply_flags(const GivenFlags& flags, Settings& settings) {
  for (const auto& [row, text] : flags.values) row->parse(text, SourcePos{std::string(flag_name(*row))}, settings);
  // A robot on the command line beats a mapping from the file.
  if (flags.given("--robot") && !flags.given("--mapping")) settings.mapping.clear();
}

Settings resolve_settings(const CommandLine& flags) {
  return resolve_settings(flags.given_flags(), ConfigRead::kStart);
}

Settings resolve_settings(const GivenFlags& flags, ConfigRead read) {
  Settings settings;
  if (find_flag("--config", flags.command) != nullptr) {
    const auto given = flags.given("--config");
    const std::string file = given ? *given : find_default_config(read == ConfigRead::kStart);
    if (!file.empty()) {
      read_config_file(file, settings, read);
      if (read == ConfigRead::kStart) spdlog::info("config: {}", file);
    }
  }
  apply_flags(flags, settings);
  if (settings.port.empty()) {
    throw InputError(SourcePos{"--port"}, "the port is empty (a device path, sim or tcp:HOST:PORT)");
  }
  // Frames at the rate must fit the baud (replay's is the switchbox's).
  if ((find_key("rate")->commands & flags.command) != 0) timing::check_rate_fits(settings.rate, settings.baud);
  return settings;
}

}  // namespace andros::cli
