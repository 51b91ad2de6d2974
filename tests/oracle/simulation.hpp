#pragma once
// One script of the fault simulation through replay (the run loop on a
// virtual clock) and the oracle: what the property test
// (tests/run/test_fault_simulation.cpp) does for each seed and the fuzz
// target (fuzz/fuzz_simulation.cpp) for each input.

#include <cstdint>
#include <cstdio>
#include <exception>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "andros/base/error.hpp"
#include "andros/base/text.hpp"
#include "andros/base/text_file.hpp"
#include "andros/input/events.hpp"
#include "andros/input/script_player.hpp"
#include "andros/mapping/loader.hpp"
#include "andros/run/replay.hpp"
#include "oracle/safety_oracle.hpp"
#include "oracle/wire_frame.hpp"
#include "support/faulty_frames.hpp"

namespace andros::test {

/// Mapping files, each loaded once, as replay's `reload FILE` and the oracle ask for them.
class MappingCache {
 public:
  /// The mapping in file; throws InputError for one that does not load (each time).
  const mapping::ValidMapping& load(const std::string& file) {
    auto it = loaded_.find(file);
    if (it == loaded_.end()) {
      try {
        it = loaded_.emplace(file, Loaded{mapping::load_mapping(file), {}}).first;
      } catch (const InputError& e) {
        it = loaded_.emplace(file, Loaded{std::nullopt, e.what()}).first;
      }
    }
    if (!it->second.mapping) throw InputError(it->second.error);
    return *it->second.mapping;
  }
  /// The same, as the oracle asks: nullptr for a file that does not load.
  const mapping::Mapping* find(const std::string& file) {
    try {
      return &*load(file);
    } catch (const InputError&) {
      return nullptr;
    }
  }

 private:
  struct Loaded {
    std::optional<mapping::ValidMapping> mapping;
    std::string error;
  };
  std::map<std::string, Loaded> loaded_;
};

inline std::string script_text(const std::vector<input::InputEvent>& script) {
  std::string text;
  for (const auto& e : script) text += input::format_event(e) + "\n";
  return text;
}

/// The loop's state at a frame it sent, against the oracle's stop latch
/// (which reads the reset holds exactly as the loop must): a stop latched and
/// not reset is "stopped" (unless a suspend, a reload or the shutdown
/// outranks it), and "stopped" is a stop latched and not reset, so that a
/// reset made late, or never, breaks a rule as one made early does.
// [rule: loop-says-stop]
inline std::string stop_said(run::OpState state, bool latched) {
  using S = run::OpState;
  if (state == S::kSuspended || state == S::kReloading || state == S::kShuttingDown) return {};
  if (latched == (state == S::kStopped)) return {};
  return "the loop said \"" + std::string(run::to_string(state)) + "\" where the stop is " +
         (latched ? "latched, not reset" : "reset (or none was latched)");
}

struct SimulationOutcome {
  std::string violation;  ///< empty: every frame kept the rules
  OracleCoverage coverage;
};

/// `--code`'s text for code as an operator may write it (two digits, either
/// case, or 0x and one or two), chosen by code itself.
inline std::string code_text(std::uint8_t code) {
  char text[8];
  switch (code % 3) {
    case 0: std::snprintf(text, sizeof text, "%02X", code); break;
    case 1: std::snprintf(text, sizeof text, "%02x", code); break;
    default: std::snprintf(text, sizeof text, "0x%X", code); break;
  }
  return text;
}

/// An engine at fault from a tick on (tests/support/faulty_frames.hpp): frames the frame gate must refuse.
struct InjectedFault {
  EngineFault fault;
  std::int64_t from_ms = 0;
};

/// Replays script (as its text: what `andros-bridge replay` would read)
/// through mapping_file, with `--code` given as text, and checks every frame
/// the link took, read off its bytes on the wire, and the end. With an
/// injected fault, the engine is at fault from its time on: every frame is
/// checked up to the gate's first trip (none before that time), which ends
/// the checks (the loop is stopped by the gate from there, which the oracle
/// does not follow).
inline SimulationOutcome simulate(
    MappingCache& mappings, const std::string& mapping_file, const std::vector<input::InputEvent>& script, bool weapons,
    std::uint8_t code, const run::Bridge::Observer& observe = [](const run::TickReport&) {},
    std::optional<InjectedFault> injected = std::nullopt) {
  const std::string text = script_text(script);
  TextReader in(text, "simulation.events", kEventScriptLimits);
  input::ScriptPlayer player(in);
  const mapping::ValidMapping& valid = mappings.load(mapping_file);
  SafetyOracle oracle(
      *valid, script, [&mappings](const std::string& f) { return mappings.find(f); },
      SafetyOracle::Options{.weapons = weapons, .code = code});
  // The code as `replay --code` reads it; the oracle holds the frames to the byte meant.
  run::ReplayOptions options{.engine = {weapons, parse_code(code_text(code), SourcePos{"--code"})}};
  options.load = [&mappings](const std::string& file) { return mappings.load(file); };
  if (injected) {
    options.frames = [injected](std::unique_ptr<run::FrameSource> engine) -> std::unique_ptr<run::FrameSource> {
      return std::make_unique<FaultyFrames>(std::move(engine), injected->fault, injected->from_ms);
    };
  }
  // [rule: gate] The frame gate is in the loop replay runs: a trip here is a false alarm (or an engine fault the oracle
  // missed).
  std::int64_t gated = 0;
  std::string gate_fault;
  // [rule: loop-says-enabled] And what the loop says is what it sent: a frame the link took carries safety = 1 exactly
  // when the state after its tick is "enabled" (the screen, the pad's light and the status read that state).
  std::string said;
  run::OpState state = run::OpState::kNoLink;  ///< the loop's, at the frame it just sent
  // [rule: gate-refuses] An engine at fault: the gate refuses its frames (each rule it holds frames to, the
  // oracle's rules check on the wire until its first trip).
  std::optional<std::int64_t> tripped;  ///< the injected fault's first trip
  options.observe = [&](const run::TickReport& r) {
    observe(r);
    if (tripped) return;
    state = r.state;
    if (r.sent) ++gated;
    if (!r.gate_fault.empty() && injected && r.t_ms >= injected->from_ms) {
      tripped = r.t_ms;
      return;
    }
    if (!r.gate_fault.empty() && gate_fault.empty())
      gate_fault = "the frame gate tripped at t=" + std::to_string(r.t_ms) + ": " + r.gate_fault;
    const bool safety = protocol::read_signals(r.data)[protocol::signal_id("safety")] != 0;
    if (r.delivered() && safety != r.enabled() && said.empty()) {
      said = "the loop said \"" + std::string(run::to_string(r.state)) + "\" at t=" + std::to_string(r.t_ms) +
             " with safety = " + (safety ? "1" : "0") + " in the frame it sent";
    }
  };
  // What the vehicle receives: the bytes on the wire, read here (wire_frame.hpp), not the data bytes the loop had.
  std::optional<std::pair<std::int64_t, protocol::Frame>> on_wire;
  options.wire = [&on_wire](std::int64_t t, const protocol::Frame& frame) { on_wire.emplace(t, frame); };
  SimulationOutcome out;
  try {
    run::replay(player, mapping::Engine(valid, options.engine), options,
                [&](std::int64_t t, const protocol::DataBytes&) {
                  if (!out.violation.empty() || (tripped && t > *tripped)) return;
                  protocol::DataBytes data{};
                  std::string v = !on_wire || on_wire->first != t ? "a frame delivered with no bytes on the wire"
                                                                  : read_wire_frame(on_wire->second, data);
                  on_wire.reset();
                  if (v.empty()) v = oracle.frame(t, data);
                  if (v.empty() && !tripped) v = stop_said(state, oracle.stop_latched());
                  if (!v.empty()) out.violation = "frame at t=" + std::to_string(t) + ": " + v;
                });
  } catch (const std::exception& e) {
    out.violation = std::string("replay threw: ") + e.what();
  }
  if (out.violation.empty()) out.violation = gate_fault;
  if (out.violation.empty()) out.violation = said;
  if (out.violation.empty() && !tripped) out.violation = oracle.finish();
  out.coverage = oracle.coverage();
  out.coverage.gated = gated;
  out.coverage.gate_refused = tripped ? 1 : 0;
  return out;
}

}  // namespace andros::test
