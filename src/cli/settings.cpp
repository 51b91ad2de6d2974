#include "andros/cli/settings.hpp"

#include <array>

#include "andros/base/text.hpp"
#include "andros/input/input_state.hpp"

namespace andros::cli {
namespace {

template <typename List>
std::string joined(const List& items) {
  std::string out;
  for (const auto& item : items) {
    if (!out.empty()) out += ", ";
    if constexpr (std::is_arithmetic_v<std::decay_t<decltype(item)>>) {
      out += std::to_string(item);
    } else {
      out += item;
    }
  }
  return out;
}

std::string code_text(std::uint8_t code) { return hex_byte(code); }

std::string rate_detail() {
  return "at most " + timing::rate_text(timing::max_rate_millihertz(protocol::kSwitchboxBaud)) + " Hz at " +
         std::to_string(protocol::kSwitchboxBaud) + " baud";
}

void parse_supervisor(std::string_view t, const SourcePos& p, Settings& s) {
  const std::string text(trim(t));
  if (text.empty()) throw InputError(p, "the supervisor's controller needs an INDEX, a NAME, a GUID or a PATH");
  if (text.find_first_not_of("0123456789") == std::string::npos) {
    (void)parse_integer(text, 0, input::kMaxJoystickIndex, "controller index", p);
  }
  s.supervisor = text;
  s.supervisor_pos = p;
}

// The rows, in the legacy file's key order (its four keys, then the bridge's),
// then the settings that only a flag sets.
const std::array<Setting, 20> kTable = {{
    {"", "--config", "FILE", kRun,
     "the config file (key=value, docs/running.md); default: "
     "$XDG_CONFIG_HOME/andros-bridge/andros-bridge.conf, then /etc/andros-bridge/andros-bridge.conf, if present",
     nullptr, [](std::string_view t, const SourcePos&, Settings& s) { s.config = std::string(t); },
     [](const Settings& s) { return s.config; }, false},
    {"baudrate", "--baud", "N", kRun | kMonitor, "the serial line's baud: {}", baud_list,
     [](std::string_view t, const SourcePos& p, Settings& s) { s.baud = parse_baud(t, p); },
     [](const Settings& s) { return std::to_string(s.baud); }, false},
    {"serialport", "--port", "PATH|sim|tcp:HOST:PORT", kRun,
     "where frames go: a serial device (refused at start while another program holds it), the built-in simulated "
     "vehicle (sim) or a TCP serial server",
     nullptr,
     [](std::string_view t, const SourcePos& p, Settings& s) {
       s.port = std::string(t);
       s.port_pos = p;
     },
     [](const Settings& s) { return s.port; }, false},
    {"robot", "--robot", "NAME", kRun | kReplay | kPlot,
     "the robot type (any case; the vehicle's name, HD-1 or V-A1, too), whose shipped mapping is used: {}",
     protocol::robot_list,
     [](std::string_view t, const SourcePos& p, Settings& s) {
       const auto robot = protocol::canonical_robot(t);
       if (!robot) throw InputError(p, "unknown robot " + quote(t) + " (one of " + protocol::robot_list() + ")");
       s.robot = *robot;
     },
     [](const Settings& s) { return s.robot; }, false},
    {"code", "--code", "HEX", kRun | kReplay | kPlot, "the switchbox's dip-switch code for byte 11, in hex", nullptr,
     [](std::string_view t, const SourcePos& p, Settings& s) { s.code = parse_code(t, p); },
     [](const Settings& s) { return code_text(s.code); }, false},
    {"rate", "--rate", "HZ", kRun | kReplay | kPlot,
     "frames per second, such as 25 or 12.5 (at least 1, at most 3 decimals); rate x 360 bits must fit the "
     "baud ({})",
     rate_detail, [](std::string_view t, const SourcePos& p, Settings& s) { s.rate = timing::parse_rate(t, p); },
     [](const Settings& s) { return timing::rate_text(s.rate.millihertz); }, false},
    {"mapping", "--mapping", "FILE", kRun | kReplay | kPlot, "a mapping file instead of the robot's shipped one",
     nullptr, [](std::string_view t, const SourcePos&, Settings& s) { s.mapping = std::string(t); },
     [](const Settings& s) { return s.mapping; }, true},
    {"weapons", "--weapons", "", kRun | kReplay | kPlot,
     "enable weapon signals (they still need the deadman and the arming input)", nullptr,
     [](std::string_view t, const SourcePos& p, Settings& s) { s.weapons = parse_weapons(t, p); },
     [](const Settings& s) { return std::string(s.weapons ? "enabled" : "disabled"); }, false},
    {"input", "--input", "sdl|FILE", kRun,
     "sdl: the live controller; FILE: an event script (docs/event-scripts.md) played in real time", nullptr,
     [](std::string_view t, const SourcePos&, Settings& s) { s.input = std::string(t); },
     [](const Settings& s) { return s.input; }, true},
    {"supervisor", "--supervisor", "INDEX|NAME|GUID|PATH", kRun,
     "a second controller, the supervisor's, chosen as --controller chooses (never the same one; each role keeps "
     "its own pad, and two pads SDL cannot tell apart are refused: docs/controllers.md): its stop and "
     "weapons consent are the mapping's 'supervisor:' buttons, and driving needs it connected too. Default: none",
     nullptr, parse_supervisor, [](const Settings& s) { return s.supervisor; }, false},
    {"record", "--no-record", "", kRun,
     "don't keep the flight recorder's session of this run (config: record=disabled; docs/recording.md)", nullptr,
     [](std::string_view t, const SourcePos& p, Settings& s) { s.record = parse_switch(t, "record", p); },
     [](const Settings& s) { return std::string(s.record ? "enabled" : "disabled"); }, false},
    {"record_dir", "--record-dir", "DIR", kRun,
     "where sessions are kept; default $STATE_DIRECTORY (the service's), else $XDG_STATE_HOME/andros-bridge, else "
     "~/.local/state/andros-bridge",
     nullptr, [](std::string_view t, const SourcePos&, Settings& s) { s.record_dir = std::string(t); },
     [](const Settings& s) { return s.record_dir; }, true},
    {"record_max_mb", "--record-max-mb", "MB", kRun,
     "the sessions kept take at most this many megabytes (10^6 bytes); the oldest are removed first, never the "
     "running one",
     nullptr,
     [](std::string_view t, const SourcePos& p, Settings& s) {
       s.record_max_mb = parse_integer(t, 1, 1'000'000'000, "record_max_mb", p);
     },
     [](const Settings& s) { return std::to_string(s.record_max_mb); }, false},
    {"record_max_days", "--record-max-days", "DAYS", kRun, "sessions last written longer ago than this are removed",
     nullptr,
     [](std::string_view t, const SourcePos& p, Settings& s) {
       s.record_max_days = static_cast<int>(parse_integer(t, 1, 100'000, "record_max_days", p));
     },
     [](const Settings& s) { return std::to_string(s.record_max_days); }, false},
    {"", "--code", "HEX", kMonitor, "also count frames whose byte 11 differs from this code as invalid", nullptr,
     [](std::string_view t, const SourcePos& p, Settings& s) { s.expected_code = parse_code(t, p); },
     [](const Settings& s) { return s.expected_code ? code_text(*s.expected_code) : std::string(); }, false},
    {"", "--rate", "HZ", kRecord,
     "how often the controller is read, per second (1..1000); the bridge's own rate makes a replay see each "
     "event in the same frame the live bridge did",
     nullptr,
     [](std::string_view t, const SourcePos& p, Settings& s) {
       s.read_rate_hz = static_cast<int>(parse_integer(t, 1, 1000, "rate", p));
     },
     [](const Settings& s) { return std::to_string(s.read_rate_hz); }, false},
    {"", "--format", "hex|raw|jsonl", kReplay, "{}: T HEX72 per line, 36 raw bytes per frame, or a JSON line per frame",
     [] { return joined(protocol::kReplayFormatNames); },
     [](std::string_view t, const SourcePos& p, Settings& s) { s.format = protocol::parse_replay_format(t, p); },
     [](const Settings& s) { return std::string(protocol::kReplayFormatNames[static_cast<std::size_t>(s.format)]); },
     false},
    {"", "--output", "FILE", kReplay,
     "write to FILE instead of standard output (- is standard output); FILE is replaced only once every input "
     "is checked and the whole replay written: a failure leaves it as it was",
     nullptr, [](std::string_view t, const SourcePos&, Settings& s) { s.output = std::string(t); },
     [](const Settings& s) { return s.output; }, false},
    {"", "--output,-o", "FILE", kRecord,
     "the script file, or - for standard output; a new FILE grows as events come, an existing one is "
     "replaced when the recording ends (and kept if it fails)",
     nullptr, [](std::string_view t, const SourcePos&, Settings& s) { s.script_output = std::string(t); },
     [](const Settings& s) { return s.script_output; }, false},
    {"", "--supervisor", "INDEX|NAME|GUID|PATH", kRecord,
     "record a second controller too, the supervisor's, chosen as --controller chooses (never the same one): "
     "its events are written 'T supervisor EVENT'",
     nullptr, parse_supervisor, [](const Settings& s) { return s.supervisor; }, false},
}};

}  // namespace

std::span<const Setting> settings_table() { return kTable; }

const Setting* find_key(std::string_view key) {
  const auto lower = to_lower(key);
  for (const auto& row : kTable) {
    if (!row.key.empty() && row.key == lower) return &row;
  }
  return nullptr;
}

std::string_view flag_name(const Setting& row) { return row.flag.substr(0, row.flag.find(',')); }

const Setting* find_flag(std::string_view flag, Command command) {
  for (const auto& row : kTable) {
    if ((row.commands & command) != 0 && flag_name(row) == flag) return &row;
  }
  return nullptr;
}

std::string help_text(const Setting& row) {
  std::string text(row.help);
  if (const auto at = text.find("{}"); at != std::string::npos) text.replace(at, 2, row.detail());
  // Wrapped by hand: this CLI11 prints a description as one line.
  constexpr std::size_t kWidth = 80;
  std::size_t line_start = 0;
  for (std::size_t space = text.find(' '); space != std::string::npos; space = text.find(' ', space + 1)) {
    const auto next = text.find(' ', space + 1);
    const auto word_end = next == std::string::npos ? text.size() : next;
    if (word_end - line_start > kWidth) {
      text[space] = '\n';
      line_start = space + 1;
    }
  }
  return text;
}

std::string default_text(const Setting& row) { return row.value_name.empty() ? std::string() : row.show(Settings{}); }

std::string baud_list() { return joined(kBauds); }

int parse_baud(std::string_view text, const SourcePos& pos) {
  const auto value = parse_integer(text, 1, 10'000'000, "baud", pos);
  for (const int b : kBauds) {
    if (b == value) return b;
  }
  throw InputError(pos, "baud " + std::string(text) + " is not one of " + baud_list());
}

bool parse_weapons(std::string_view text, const SourcePos& pos) { return parse_switch(text, "weapons", pos); }

bool parse_switch(std::string_view text, std::string_view name, const SourcePos& pos) {
  const auto v = to_lower(text);
  if (v == "enabled" || v == "true" || v == "yes" || v == "on" || v == "1") return true;
  if (v == "disabled" || v == "false" || v == "no" || v == "off" || v == "0") return false;
  throw InputError(pos, std::string(name) + " " + quote(text) + " must be enabled or disabled");
}

std::string_view switch_text(const Setting& row) {
  return flag_name(row).starts_with("--no-") ? "disabled" : "enabled";
}

}  // namespace andros::cli
