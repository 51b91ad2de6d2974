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

/// The canonical (upper-case) name of a robot type, matched case-insensitively.
std::optional<std::string> canonical_robot(std::string_view name);

/// "F6A, VA1, ..." for error messages.
std::string robot_list();

}  // namespace andros::protocol
