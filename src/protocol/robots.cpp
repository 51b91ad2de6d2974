#include "andros/protocol/robots.hpp"

#include <cctype>

namespace andros::protocol {

std::optional<std::string> canonical_robot(std::string_view name) {
  std::string upper(name);
  for (auto& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  for (const auto robot : kRobotTypes) {
    if (robot == upper) return upper;
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
