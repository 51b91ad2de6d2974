#include "andros/cli/config.hpp"

#include <cstdlib>
#include <filesystem>
#include <map>

#include "andros/base/text.hpp"

namespace andros::cli {
namespace {

/// A path in the file relative to the file's own directory; `input=sdl` is no path.
std::string relative_to(const std::string& file_name, std::string_view value) {
  return value == kSdlInput ? std::string(value) : beside(file_name, value);
}

std::string known_keys() {
  std::string out;
  for (const auto& row : settings_table()) {
    if (row.key.empty()) continue;
    out += (out.empty() ? "" : ", ") + std::string(row.key);
  }
  return out;
}

}  // namespace

std::string beside(const std::string& file_name, std::string_view path) {
  const std::filesystem::path p(path);
  if (p.is_absolute()) return std::string(path);
  return (std::filesystem::path(file_name).parent_path() / p).lexically_normal().string();
}

void parse_config(TextReader& in, Settings& settings) {
  const std::string& file_name = in.name();
  std::map<std::string, int> first_line;  // each key's line: a key given twice is an error, never "last wins"
  while (const auto next = in.next_line()) {
    const std::string_view line = *next;
    const int line_no = in.line_number();
    const auto text = trim(line);
    if (text.empty() || text.front() == '#') continue;
    const auto eq = text.find('=');
    if (eq == std::string_view::npos) {
      throw InputError(SourcePos{file_name, line_no, 1}, "expected key=value, got " + quote(text));
    }
    const auto key = to_lower(trim(text.substr(0, eq)));
    const auto value = trim(text.substr(eq + 1));
    if (value.empty()) throw InputError(SourcePos{file_name, line_no, 0}, quote(key) + " has no value");
    // Column of the value, for errors about it (1-based, in the raw line).
    const int value_col =
        static_cast<int>(line.find('=')) + 2 + static_cast<int>(text.substr(eq + 1).find_first_not_of(" \t"));
    const Setting* row = find_key(key);
    if (row == nullptr) {
      throw InputError(SourcePos{file_name, line_no, 1},
                       "unknown key " + quote(key) + " (known: " + known_keys() + ")");
    }
    if (const auto [first, fresh] = first_line.try_emplace(key, line_no); !fresh) {
      const int key_col = static_cast<int>(line.find_first_not_of(" \t")) + 1;
      throw InputError(SourcePos{file_name, line_no, key_col},
                       "key " + quote(key) + " given twice (first at line " + std::to_string(first->second) + ")");
    }
    const SourcePos pos{file_name, line_no, value_col};
    row->parse(row->file_relative ? relative_to(file_name, value) : std::string(value), pos, settings);
  }
}

void read_config_file(const std::string& path, Settings& settings, ConfigRead read) {
  auto in = read == ConfigRead::kReload ? TextReader::open_regular(path, kConfigLimits)
                                        : TextReader::open(path, kConfigLimits);
  parse_config(in, settings);
  settings.config_file = path;
  settings.config_stream = in.regular_file() ? std::string() : in.kind();
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
