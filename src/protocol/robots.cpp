#include "andros/protocol/robots.hpp"

#include "andros/base/text.hpp"

namespace andros::protocol {

std::optional<std::string> canonical_robot(std::string_view name) {
  const std::string upper = to_upper(name);
  for (const auto robot : kRobotTypes) {
    if (robot == upper) return upper;
  }
  for (const auto& [alias, type] : kRobotAliases) {
    if (alias == upper) return std::string(type);
  }
  return std::nullopt;
}

std::string robot_list() {
  std::string out;
  for (const auto robot : kRobotTypes) {
    if (!out.empty()) out += ", ";
    out += robot;
  }
  return out;
}

}  // namespace andros::protocol
