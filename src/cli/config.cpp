#include "andros/cli/config.hpp"

#include <cctype>
#include <cstdlib>
#include <filesystem>

#include "andros/base/text.hpp"
#include "andros/protocol/robots.hpp"
#include "andros/timing/rate.hpp"

namespace andros::cli {
namespace {

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r");
  return s.substr(first, last - first + 1);
}

std::string lower(std::string_view s) {
  std::string out(s);
  for (auto& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

/// A path in the file relative to the file's own directory, as a user expects.
std::string relative_to(const std::string& file_name, std::string_view value) {
  const std::filesystem::path p(value);
  if (p.is_absolute() || value == "sdl") return std::string(value);
  return (std::filesystem::path(file_name).parent_path() / p).lexically_normal().string();
}

}  // namespace

int parse_baud(std::string_view text, const SourcePos& pos) {
  const auto value = parse_integer(text, 1, 10'000'000, "baud", pos);
  for (const int b : kBauds) {
    if (b == value) return b;
  }
  throw InputError(pos, "baud " + std::string(text) +
                            " is not one of 9600, 19200, 38400, 57600, 115200");
}

bool parse_weapons(std::string_view text, const SourcePos& pos) {
  const auto v = lower(text);
  if (v == "enabled" || v == "true" || v == "yes" || v == "on" || v == "1") return true;
  if (v == "disabled" || v == "false" || v == "no" || v == "off" || v == "0") return false;
  throw InputError(pos, "weapons " + quote(text) + " must be enabled or disabled");
}

std::int64_t rate_millihertz(const RunConfig& config) {
  return timing::parse_rate(config.rate, config.baud, config.rate_pos);
}

void parse_config(TextReader& in, RunConfig& config) {
  const std::string& file_name = in.name();
  while (const auto next = in.next_line()) {
    const std::string_view line = *next;
    const int line_no = in.line_number();
    const auto text = trim(line);
    if (text.empty() || text.front() == '#') continue;
    const SourcePos line_pos{file_name, line_no, 0};
    const auto eq = text.find('=');
    if (eq == std::string_view::npos) {
      throw InputError(SourcePos{file_name, line_no, 1},
                       "expected key=value, got " + quote(text));
    }
    const auto key = lower(trim(text.substr(0, eq)));
    const auto value = trim(text.substr(eq + 1));
    // Column of the value, for errors about it (1-based, in the raw line).
    const int value_col = static_cast<int>(line.find('=')) + 2 +
                          static_cast<int>(text.substr(eq + 1).find_first_not_of(" \t"));
    const SourcePos pos{file_name, line_no, value.empty() ? 0 : value_col};
    if (value.empty()) throw InputError(line_pos, quote(key) + " has no value");

    if (key == "baudrate") {
      config.baud = parse_baud(value, pos);
    } else if (key == "serialport") {
      config.port = std::string(value);
      config.port_pos = pos;
    } else if (key == "robot") {
      const auto robot = protocol::canonical_robot(value);
      if (!robot) {
        throw InputError(pos, "unknown robot " + quote(value) + " (one of " + protocol::robot_list() + ")");
      }
      config.robot = *robot;
    } else if (key == "code") {
      config.code = parse_code(value, pos);
    } else if (key == "rate") {
      // The text is checked now, at its line; against the baud once all is read.
      timing::parse_rate(value, kBauds[std::size(kBauds) - 1], pos);
      config.rate = std::string(value);
      config.rate_pos = pos;
    } else if (key == "mapping") {
      config.mapping = relative_to(file_name, value);
    } else if (key == "weapons") {
      config.weapons = parse_weapons(value, pos);
    } else if (key == "input") {
      config.input = relative_to(file_name, value);
    } else {
      throw InputError(SourcePos{file_name, line_no, 1},
                       "unknown key " + quote(key) +
                           " (known: baudrate, serialport, robot, code, rate, mapping, weapons, input)");
    }
  }
}

void read_config_file(const std::string& path, RunConfig& config) {
  auto in = TextReader::open(path, kConfigLimits);
  parse_config(in, config);
}

std::vector<std::string> default_config_paths() {
  std::vector<std::string> paths;
  const char* xdg = std::getenv("XDG_CONFIG_HOME");
  const char* home = std::getenv("HOME");
  if (xdg != nullptr && *xdg != '\0') {
    paths.push_back(std::string(xdg) + "/andros-bridge/andros-bridge.conf");
  } else if (home != nullptr && *home != '\0') {
    paths.push_back(std::string(home) + "/.config/andros-bridge/andros-bridge.conf");
  }
  paths.emplace_back("/etc/andros-bridge/andros-bridge.conf");
  return paths;
}

}  // namespace andros::cli
