#include "replay_data.hpp"

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
  ControlState rest;
  rest[signal_id("drive")] = 128;
  rest[signal_id("pivot")] = 128;
  rest[signal_id("battery")] = 0xCC;
  rest[signal_id("code")] = code;
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
        const auto id = find_signal(assignment.substr(0, eq));
        if (eq == std::string::npos || !id) throw std::runtime_error(path + ":" + std::to_string(line_no) + ": bad " + assignment);
        f.state[*id] = static_cast<std::uint8_t>(std::stoi(assignment.substr(eq + 1)));
      }
    }
    frames.push_back(f);
  }
  return frames;
}

std::string describe_difference(const ControlState& want, const ControlState& got) {
  std::string out;
  for (std::size_t i = 0; i < kSignalCount; ++i) {
    if (want.values[i] != got.values[i]) {
      if (!out.empty()) out += ", ";
      out += std::string(kSignals[i].name) + " expected " + std::to_string(want.values[i]) + " got " +
             std::to_string(got.values[i]);
    }
  }
  return out;
}

}  // namespace andros::testing
