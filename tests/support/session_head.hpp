#pragma once
// The first records of a small session the readers take (header, program,
// started, settings: 25 Hz, hd1's text), for tests that write sessions.

#include <string>
#include <vector>

#include "andros/record/session.hpp"

namespace andros::testing {

/// The payloads of a session's first four records, before any tick.
inline std::vector<std::string> session_head() {
  record::SessionSettings s;
  s.robot = "HD1";
  s.mapping_file = "/m/hd1.yaml";
  s.rate_millihertz = 25'000;
  s.sources = {{"/m/hd1.yaml", "robot: HD1\n"}};
  return {record::payload::header(), record::payload::program("9.9.9"),
          record::payload::started("2024-05-01T12:00:00+0200", 42, "bench"), record::payload::settings(s)};
}

}  // namespace andros::testing
