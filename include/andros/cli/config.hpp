#pragma once
/// The run configuration (docs/running.md): the legacy packet generator's
/// `key=value` file read as is, plus the bridge's own keys, then the command
/// line on top. Parsing does no I/O beyond reading the file it is given.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "andros/base/error.hpp"
#include "andros/base/text_file.hpp"

namespace andros::cli {

inline constexpr int kDefaultBaud = 9600;
inline constexpr std::uint8_t kDefaultCode = 0x01;
inline constexpr std::string_view kSimPort = "sim";

/// The bauds the legacy packet generator offered; nothing else is accepted.
inline constexpr int kBauds[] = {9600, 19200, 38400, 57600, 115200};

struct RunConfig {
  std::string robot = "HD1";  ///< canonical (upper-case) robot type
  std::string mapping;        ///< a mapping file; empty = the robot's shipped mapping
  std::string port{kSimPort}; ///< a device path, "sim" or "tcp:HOST:PORT"
  SourcePos port_pos{"--port"};  ///< where the port was set, for errors about it
  int baud = kDefaultBaud;
  std::uint8_t code = kDefaultCode;
  /// The rate as written ("25", "12.5") and where, so that a rate the final
  /// baud cannot carry is reported at the line or flag that set it.
  std::string rate = "25";
  SourcePos rate_pos{"--rate"};
  bool weapons = false;
  std::string input = "sdl";  ///< "sdl" or an event script's path
};

/// Reads `key=value` lines into config. Keys: baudrate, serialport, robot,
/// code (the legacy four) and rate, mapping, weapons, input. A relative
/// `mapping` or `input` path is taken relative to the file's directory. An
/// unknown key or bad value throws InputError at FILE:LINE.
void parse_config(TextReader& in, RunConfig& config);

/// Opens and parses a config file (within kConfigLimits); a file that cannot
/// be read, a directory, a line or a file too long are InputErrors too.
void read_config_file(const std::string& path, RunConfig& config);

/// Where `run` looks for a config file when --config is not given, in order:
/// $XDG_CONFIG_HOME/andros-bridge/andros-bridge.conf (or ~/.config/...), then
/// /etc/andros-bridge/andros-bridge.conf. The first that exists is read.
std::vector<std::string> default_config_paths();

/// Value checks shared by the file and the flags; pos says where the text came from.
int parse_baud(std::string_view text, const SourcePos& pos);
bool parse_weapons(std::string_view text, const SourcePos& pos);

/// The rate in millihertz, once file and flags are merged: replay's
/// parse_rate, so both commands read the same text, checked against the
/// final baud (rate x 360 bits must fit). Throws InputError at rate_pos.
std::int64_t rate_millihertz(const RunConfig& config);

}  // namespace andros::cli
