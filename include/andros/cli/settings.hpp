#pragma once
/// The settings of `run`, `replay`, `monitor` and `record` as one table
/// (docs/architecture.md, "Settings"): each row names a setting's config-file
/// key, its flag, the commands that take it, its help and its parser to a
/// typed value. The config file, the command-line options, the merge and
/// `--help` are all made from the table.

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "andros/base/error.hpp"
#include "andros/protocol/frame.hpp"
#include "andros/protocol/frame_output.hpp"
#include "andros/protocol/robots.hpp"
#include "andros/timing/rate.hpp"

namespace andros::cli {

/// The commands that take settings, as bits (a row lists those that use it).
enum Command : unsigned { kRun = 1U, kReplay = 2U, kMonitor = 4U, kRecord = 8U, kPlot = 16U };

inline constexpr std::uint8_t kDefaultCode = 0x01;
inline constexpr std::string_view kSimPort = "sim";
inline constexpr std::string_view kSdlInput = "sdl";
/// The flight recorder's rotation: sessions beyond these (in total size, in
/// age) are removed, oldest first, never the running one.
inline constexpr std::int64_t kDefaultRecordMaxMb = 500;
inline constexpr int kDefaultRecordMaxDays = 30;
/// The bauds the legacy packet generator offered; nothing else is accepted.
inline constexpr int kBauds[] = {9600, 19200, 38400, 57600, 115200};
/// How often `record` reads the controller: the bridge's frame rate, so that
/// a replay sees each event in the frame the live bridge did.
inline constexpr int kDefaultReadRateHz = static_cast<int>(timing::kDefaultRateMillihertz / timing::kMillihertzPerHz);

/// Every setting's typed value. A default-constructed Settings holds the defaults.
struct Settings {
  std::string config;       ///< `run --config`; empty: the default paths
  std::string config_file;  ///< the config file read; empty: none
  /// What the config file was when it was not a regular file ("a pipe",
  /// "a terminal"): read once at start, never again by a reload. Empty for a
  /// regular file.
  std::string config_stream;
  std::string robot{protocol::kDefaultRobot};  ///< canonical (upper-case) robot type
  std::string mapping;                         ///< a mapping file; empty: the robot's shipped one
  std::string port{kSimPort};                  ///< a device path, "sim" or "tcp:HOST:PORT"
  SourcePos port_pos{"--port"};                ///< where the port was set, for errors about it
  int baud = protocol::kSwitchboxBaud;
  std::uint8_t code = kDefaultCode;
  /// Parsed once; checked against the final baud after the merge, at the
  /// line or flag that set it.
  timing::Rate rate{timing::kDefaultRateMillihertz, "", SourcePos{"--rate"}};
  bool weapons = false;
  std::string input{kSdlInput};               ///< "sdl" or an event script's path
  std::string supervisor;                     ///< the supervisor's controller (INDEX|NAME|GUID); empty: none
  SourcePos supervisor_pos{"--supervisor"};   ///< where it was set, for errors about it
  std::optional<std::uint8_t> expected_code;  ///< `monitor --code`
  int read_rate_hz = kDefaultReadRateHz;      ///< `record --rate`
  protocol::ReplayFormat format = protocol::ReplayFormat::kHex;
  std::string output;               ///< `replay --output`; empty: standard output
  std::string script_output = "-";  ///< `record --output`; "-": standard output
  bool record = true;               ///< the flight recorder (docs/recording.md)
  std::string record_dir;           ///< where sessions go; empty: the state folder
  std::int64_t record_max_mb = kDefaultRecordMaxMb;
  int record_max_days = kDefaultRecordMaxDays;
};

/// One row of the table.
struct Setting {
  std::string_view key;         ///< config-file key (lower case); empty: command line only
  std::string_view flag;        ///< CLI11 names: "--rate", "--output,-o"
  std::string_view value_name;  ///< "HZ"; empty: a switch, which stands for "enabled" ("disabled" for a --no- one)
  unsigned commands;            ///< Command bits
  /// The help text; "{}" stands for detail() (a list made from its table).
  std::string_view help;
  std::string (*detail)();
  /// Parses text (from the file or the flag) into its field; InputError at pos.
  void (*parse)(std::string_view text, const SourcePos& pos, Settings& into);
  /// The field as text that parse takes back ("" when unset): the default in
  /// --help, and what the tests round-trip.
  std::string (*show)(const Settings& from);
  bool file_relative;  ///< a relative path in the file is taken from the file's directory
};

/// The table, in the legacy file's key order.
std::span<const Setting> settings_table();

/// The row with this config-file key (any case), or null.
const Setting* find_key(std::string_view key);

/// The row with this flag that `command` takes, or null.
const Setting* find_flag(std::string_view flag, Command command);

/// The primary flag of a row: "--output" for "--output,-o".
std::string_view flag_name(const Setting& row);

/// The row's help text, its list filled in, wrapped for --help.
std::string help_text(const Setting& row);

/// The default a row's option shows in --help ("" for none, and for a switch).
std::string default_text(const Setting& row);

/// "9600, 19200, ..." from kBauds.
std::string baud_list();

/// Value checks shared by the file and the flags; pos says where the text came from.
int parse_baud(std::string_view text, const SourcePos& pos);
bool parse_weapons(std::string_view text, const SourcePos& pos);
/// enabled/disabled (or true/false, yes/no, on/off, 1/0) for the setting name.
bool parse_switch(std::string_view text, std::string_view name, const SourcePos& pos);
/// What a switch given on the command line stands for: "enabled", or
/// "disabled" for a --no- one.
std::string_view switch_text(const Setting& row);

}  // namespace andros::cli
