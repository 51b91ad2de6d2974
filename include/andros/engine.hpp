#pragma once
/// The mapping engine: a pure function of (input snapshot, its own previous
/// state, tick time) to the frame's data bytes. No SDL, no clock reads, no I/O.
/// The safety rules of contract section 5 are applied after the bindings, in
/// one place, so that no mapping can bypass them.

#include <cstdint>
#include <string>

#include "andros/frame.hpp"
#include "andros/input.hpp"
#include "andros/mapping.hpp"

namespace andros {

struct EngineOptions {
  bool weapons = false;       ///< --weapons / weapons=enabled
  std::uint8_t code = 0x01;   ///< byte 11, the dip-switch code
};

/// Why the engine is (not) enabled, for the operator's status view and logs.
enum class EnableState : std::uint8_t {
  kEnabled,
  kNoController,     ///< no controller connected
  kDeadmanReleased,  ///< the deadman is not held
  kDeadmanNotFresh,  ///< held since connect or start-up: release and press again
};

std::string_view describe(EnableState state);

struct EngineStatus {
  EnableState enable = EnableState::kNoController;
  std::string layer;  ///< the active layer's name ("" for the base layer)
};

class Engine {
 public:
  Engine(Mapping mapping, EngineOptions options);

  /// One tick at time now_ms (ms since start, non-decreasing): the data bytes
  /// of the frame to send. Always a frame that passes validation.
  DataBytes step(const InputState& input, std::int64_t now_ms);

  /// The neutral frame for the current analog/selector state (shutdown, link
  /// loss): every motion and weapon bit 0, drive and pivot at centre.
  [[nodiscard]] DataBytes neutral() const;

  [[nodiscard]] const EngineStatus& status() const;
  [[nodiscard]] const Mapping& mapping() const;

 private:
  // Implementation state lives in the mapping engine (issue 3).
};

}  // namespace andros
