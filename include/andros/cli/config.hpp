#pragma once
/// The config file (docs/running.md): the legacy packet generator's
/// `key=value` file read as is, plus the bridge's own keys, all rows of the
/// settings table. Parsing does no I/O beyond reading the file it is given.

#include <string>
#include <vector>

#include "andros/base/text_file.hpp"
#include "andros/cli/settings.hpp"

namespace andros::cli {

/// Reads `key=value` lines into settings: the keys of the settings table. A
/// relative path for a row that says so (`mapping`, `input`) is taken from
/// the file's directory. An unknown key or bad value throws InputError at
/// FILE:LINE:COL. The rate is checked against the baud by the merge.
void parse_config(TextReader& in, Settings& settings);

/// Opens and parses a config file (within kConfigLimits); a file that cannot
/// be read, a directory, a line or a file too long are InputErrors too.
void read_config_file(const std::string& path, Settings& settings);

/// Where `run` looks for a config file when --config is not given, in order:
/// $XDG_CONFIG_HOME/andros-bridge/andros-bridge.conf (or ~/.config/...), then
/// /etc/andros-bridge/andros-bridge.conf. The first that exists is read.
std::vector<std::string> default_config_paths();

}  // namespace andros::cli
