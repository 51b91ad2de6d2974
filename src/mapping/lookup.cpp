#include <cstdlib>

#include "andros/base/text.hpp"
#include "andros/base/version.hpp"
#include "andros/mapping/loader.hpp"
#include "andros/protocol/robots.hpp"

namespace andros::mapping {

namespace fs = std::filesystem;

std::vector<fs::path> mapping_search_path() {
  std::vector<fs::path> dirs;
  const char* xdg = std::getenv("XDG_CONFIG_HOME");
  const char* home = std::getenv("HOME");
  if (xdg != nullptr && *xdg != '\0') {
    dirs.emplace_back(fs::path(xdg) / "andros-bridge" / "mappings");
  } else if (home != nullptr && *home != '\0') {
    dirs.emplace_back(fs::path(home) / ".config" / "andros-bridge" / "mappings");
  }
  std::error_code ec;
  if (*kSourceMappingsDir != '\0' && fs::is_directory(kSourceMappingsDir, ec)) dirs.emplace_back(kSourceMappingsDir);
  // Beside the binary: an installed tree unpacked somewhere else (dpkg-deb -x) finds its own.
  const auto exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const auto beside = (exe.parent_path() / kMappingsFromBinDir).lexically_normal();
    if (beside != fs::path(kInstalledMappingsDir) && fs::is_directory(beside, ec)) dirs.push_back(beside);
  }
  dirs.emplace_back(kInstalledMappingsDir);
  return dirs;
}

fs::path find_robot_mapping(std::string_view robot, const std::vector<fs::path>& search_path) {
  const auto canonical = protocol::canonical_robot(robot);
  if (!canonical) {
    throw InputError(SourcePos{"--robot"},
                     "unknown robot " + quote(robot) + " (expected " + protocol::robot_list() + ")");
  }
  const std::string file = to_lower(*canonical) + ".yaml";
  std::string looked;
  for (const auto& dir : search_path) {
    std::error_code ec;
    if (fs::is_regular_file(dir / file, ec)) return dir / file;
    // A folder that cannot be looked into (a HOME the user may not read) is passed over, and said if nothing is found.
    looked += (looked.empty() ? "" : ", ") + dir.string() + (ec ? " (" + ec.message() + ")" : "");
  }
  throw InputError(SourcePos{"--robot"},
                   "no mapping " + file + " for robot " + *canonical + " (looked in " + looked + ")");
}

ValidMapping load_robot_mapping(std::string_view robot) {
  const auto path = find_robot_mapping(robot, mapping_search_path());
  auto mapping = load_mapping(path);
  const auto canonical = protocol::canonical_robot(robot);
  if (mapping->robot != canonical) {
    throw InputError(mapping->robot_pos,
                     "this file is for robot " + mapping->robot.value_or("?") + ", not " + *canonical);
  }
  return mapping;
}

ValidMapping load_chosen_mapping(const std::string& file, std::string_view robot) {
  return file.empty() ? load_robot_mapping(robot) : load_mapping(file);
}

}  // namespace andros::mapping
