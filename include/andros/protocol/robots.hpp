#pragma once
/// The Andros robot types the switchbox drives.

#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace andros::protocol {

inline constexpr std::array<std::string_view, 7> kRobotTypes = {"F6A",     "VA1", "WOLVERINE", "HD1",
                                                                "PROWLER", "RAV", "RONS"};
inline constexpr std::string_view kDefaultRobot = "HD1";

/// A robot type under the vehicle's own name (docs/robots.md): what an
/// operator reads on the vehicle is accepted wherever a type is.
struct RobotAlias {
  std::string_view alias;
  std::string_view type;
};
inline constexpr std::array<RobotAlias, 2> kRobotAliases = {{{"V-A1", "VA1"}, {"HD-1", "HD1"}}};

/// The canonical (upper-case) name of a robot type, matched case-insensitively,
/// by its type or its vehicle's name (kRobotAliases: `HD-1` is HD1).
std::optional<std::string> canonical_robot(std::string_view name);

/// "F6A, VA1, ..." for error messages.
std::string robot_list();

}  // namespace andros::protocol
