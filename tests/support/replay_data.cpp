#include "support/replay_data.hpp"

#include "andros/base/text.hpp"

#include "andros/run/replay.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace andros::testing {

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open " + path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<ExpectedFrame> read_expected(const std::string& path, std::uint8_t code) {
  protocol::ControlState rest;
  rest[protocol::signal_id("drive")] = 128;
  rest[protocol::signal_id("pivot")] = 128;
  rest[protocol::signal_id("battery")] = 0xCC;
  rest[protocol::signal_id("code")] = code;
  std::vector<ExpectedFrame> frames;
  std::istringstream in(read_text(path));
  std::string raw;
  int line_no = 0;
  while (std::getline(in, raw)) {
    ++line_no;
    raw = raw.substr(0, raw.find('#'));
    std::istringstream words(raw);
    ExpectedFrame f{0, rest, line_no};
    if (!(words >> f.t)) continue;
    std::string word;
    while (words >> word) {
      if (word == "enabled") word = "safety=1 drive_brake=1";
      std::istringstream parts(word);
      std::string assignment;
      while (parts >> assignment) {
        const auto eq = assignment.find('=');
        const auto id = protocol::find_signal(assignment.substr(0, eq));
        if (eq == std::string::npos || !id)
          throw std::runtime_error(path + ":" + std::to_string(line_no) + ": bad " + assignment);
        f.state[*id] = static_cast<std::uint8_t>(
            parse_integer(assignment.substr(eq + 1), 0, 255, "value", SourcePos{path, line_no}));
      }
    }
    frames.push_back(f);
  }
  return frames;
}

std::string describe_difference(const protocol::ControlState& want, const protocol::ControlState& got) {
  std::string out;
  for (std::size_t i = 0; i < protocol::kSignalCount; ++i) {
    if (want.values[i] != got.values[i]) {
      if (!out.empty()) out += ", ";
      out += std::string(protocol::kSignals[i].name) + " expected " + std::to_string(want.values[i]) + " got " +
             std::to_string(got.values[i]);
    }
  }
  return out;
}

void expect_replay(mapping::ValidMapping mapping, bool weapons, std::int64_t rate_millihertz, const std::string& events,
                   const std::string& expected) {
  const std::uint8_t code = 0x01;
  const auto want = read_expected(expected, code);
  // The engine as the run has it, and computing every step afresh: the same frames.
  for (const bool reuse : {true, false}) {
    const mapping::EngineOptions options{.weapons = weapons, .code = code, .reuse_settled = reuse};
    mapping::Engine engine(mapping, options);
    TextReader in(read_text(events), events, kEventScriptLimits);
    input::ScriptPlayer player(in);
    std::vector<std::pair<std::int64_t, protocol::DataBytes>> got;
    run::replay(player, std::move(engine), run::ReplayOptions{.rate_millihertz = rate_millihertz, .engine = options},
                [&](std::int64_t t, const protocol::DataBytes& d) { got.emplace_back(t, d); });

    ASSERT_EQ(got.size(), want.size()) << "frame count of " << events << (reuse ? "" : " (every step computed)");
    for (std::size_t i = 0; i < want.size(); ++i) {
      EXPECT_EQ(got[i].first, want[i].t) << "frame " << i;
      EXPECT_TRUE(protocol::validation_errors(got[i].second).empty());
      const auto built = protocol::FrameBuilder(code).build(want[i].state);
      EXPECT_EQ(got[i].second, built) << expected << ":" << want[i].line << " t=" << want[i].t
                                      << (reuse ? "" : " (every step computed)") << ": "
                                      << describe_difference(protocol::read_signals(built),
                                                             protocol::read_signals(got[i].second));
    }
  }
}

}  // namespace andros::testing
