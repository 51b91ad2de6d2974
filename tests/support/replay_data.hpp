#pragma once
// Reading the hand-written expected-frame files of tests/data/replay/.
//
// One line per frame: `T sig=value sig=value ...`, listing only the signals
// that differ from the mapping's rest state (every bit 0, drive/pivot at 128,
// byte12 0x00, battery 0xCC, code 0x01, arm_speed/light 0). The word
// `enabled` stands for `safety=1 drive_brake=1`. `#` starts a comment.

#include <cstdint>
#include <string>
#include <vector>

#include "andros/mapping/model.hpp"
#include "andros/protocol/frame.hpp"

namespace andros::testing {

struct ExpectedFrame {
  std::int64_t t = 0;
  protocol::ControlState state;
  int line = 0;
};

std::vector<ExpectedFrame> read_expected(const std::string& path, std::uint8_t code);

/// "drive 128 -> 255, safety 0 -> 1" for the signals that differ.
std::string describe_difference(const protocol::ControlState& want, const protocol::ControlState& got);

std::string read_text(const std::string& path);

/// Replays `events` through the mapping and EXPECTs every frame to match
/// `expected` exactly (and to pass validation).
void expect_replay(mapping::ValidMapping mapping, bool weapons, std::int64_t rate_millihertz, const std::string& events,
                   const std::string& expected);

}  // namespace andros::testing
