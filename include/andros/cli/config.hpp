#pragma once
/// The config file (docs/running.md): the legacy packet generator's
/// `key=value` file read as is, plus the bridge's own keys, all rows of the
/// settings table. Parsing does no I/O beyond reading the file it is given.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "andros/base/text_file.hpp"
#include "andros/cli/settings.hpp"

namespace andros::cli {

/// Reads `key=value` lines into settings: the keys of the settings table. A
/// relative path for a row that says so (`mapping`, `input`) is taken from
/// the file's directory. An unknown key or bad value throws InputError at
/// FILE:LINE:COL. The rate is checked against the baud by the merge.
void parse_config(TextReader& in, Settings& settings);

/// A path a file names (a config's `mapping`, an event script's `reload
/// MAPPING`), relative to that file's own folder as a user expects; an
/// absolute one as it is. For standard input ("-") the current folder.
std::string beside(const std::string& file_name, std::string_view path);

/// Which config files a read takes.
enum class ConfigRead : std::uint8_t {
  kStart,   ///< any file that can be read, a pipe too (`--config <(...)`), waited for
  kReload,  ///< a regular file only: a reload never waits on a pipe, a FIFO or a terminal
};

/// Opens and parses a config file (within kConfigLimits); a file that cannot
/// be read, a directory, a line or a file too long are InputErrors too, and
/// for kReload anything but a regular file (`FILE: error: is a pipe, not a
/// regular file`). Notes the file in settings.config_file, and in
/// settings.config_stream what it was if not a regular file.
void read_config_file(const std::string& path, Settings& settings, ConfigRead read = ConfigRead::kStart);

/// Where `run` looks for a config file when --config is not given, in order:
/// $XDG_CONFIG_HOME/andros-bridge/andros-bridge.conf (or ~/.config/...), then
/// /etc/andros-bridge/andros-bridge.conf. The first that exists is read.
std::vector<std::string> default_config_paths();

}  // namespace andros::cli
