// libFuzzer target: the fault simulation (tests/run/test_fault_simulation.cpp)
// with the fuzzer's bytes in place of a seed. The same generator
// (tests/oracle/fault_script.hpp) turns the bytes into an event script with
// faults (the controller lost, link flaps and take-overs, reloads of good,
// bad and missing mappings, suspend and resume, a stop); replay runs it
// through the run loop on a virtual clock over a shipped mapping, and the
// same oracle (tests/oracle/safety_oracle.hpp), which reads only the script
// and the frame bytes, checks every delivered frame. A broken rule prints the
// script, then crashes.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "andros/base/version.hpp"
#include "andros/mapping/loader.hpp"
#include "andros/protocol/robots.hpp"
#include "fuzz_check.hpp"
#include "oracle/fault_script.hpp"
#include "oracle/random.hpp"
#include "oracle/simulation.hpp"

namespace {

using namespace andros;

struct Shelf {
  test::MappingCache mappings;
  std::vector<std::string> shipped;
  test::ReloadTargets targets;
};

Shelf& shelf() {
  static Shelf s = [] {
    Shelf out;
    const std::filesystem::path dir(kSourceMappingsDir);
    for (const auto robot : protocol::kRobotTypes) {
      const std::string file = mapping::find_robot_mapping(robot, {dir}).string();
      out.mappings.load(file);
      out.shipped.push_back(file);
      out.targets.good.push_back(file);
    }
    out.targets.bad.push_back((dir / "common.yaml").string());  // a base: no robot, refused
    out.targets.bad.push_back((dir / "missing.yaml").string());
    return out;
  }();
  return s;
}

}  // namespace

// Byte 0 picks the mapping, byte 1 weapons and the code; the rest are the generator's choices.
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  Shelf& s = shelf();
  const std::string& mapping_file = s.shipped[data[0] % s.shipped.size()];
  const bool weapons = (data[1] & 1) != 0;
  const std::uint8_t code = data[1];
  test::ByteChoices pick(data + 2, size - 2);
  const auto script = test::fault_script(pick, s.targets);
  const auto out = test::simulate(s.mappings, mapping_file, script, weapons, code);
  if (!out.violation.empty()) {
    std::fprintf(stderr, "%s%s, code %02X: %s\nthe script:\n%s", mapping_file.c_str(), weapons ? ", --weapons" : "",
                 code, out.violation.c_str(), test::script_text(script).c_str());
  }
  fuzz::check(out.violation.empty());
  return 0;
}
