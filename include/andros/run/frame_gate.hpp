#pragma once
/// The last gate before the wire: a second channel, written apart from the
/// mapping engine (the channel it checks), that holds every frame the loop
/// offers the link to the contract's safety rules (docs/safety-states.md,
/// "The frame gate"). It reads only the frame's bytes, the protocol's tables
/// (the signals, their kinds and partners, the validation table) and what the
/// run was started with (the code, whether weapons are enabled), and the
/// operating state's one answer: enabled or not. A frame that breaks a rule
/// is replaced by the gate's own neutral frame, and the loop stops (latched,
/// as a stop button does).

#include <cstdint>
#include <string>

#include "andros/protocol/frame.hpp"

namespace andros::run {

/// What the gate holds frames to: the run's settings, never the engine's.
/// No default: whoever builds a loop says what its frames must carry.
struct FrameRules {
  FrameRules(bool weapons_enabled, std::uint8_t code_byte) : weapons(weapons_enabled), code(code_byte) {}
  bool weapons;       ///< weapons enabled for the run (--weapons, weapons=enabled; a reload may change it)
  std::uint8_t code;  ///< byte 11, the configured dip-switch code
};

/// The gate's verdict on one frame: what goes to the link, and why it is not the frame offered.
struct GateVerdict {
  protocol::DataBytes data{};  ///< the frame to send: the one offered, or the gate's neutral one
  std::string fault;           ///< the first rule the offered frame broke; empty: it passed
  [[nodiscard]] bool tripped() const { return !fault.empty(); }
};

class FrameGate {
 public:
  explicit FrameGate(FrameRules rules) : rules_(rules) {}

  /// Checks the frame offered in a tick whose operating state is `enabled`
  /// (kEnabled) or not; counts a trip.
  GateVerdict pass(const protocol::DataBytes& offered, bool enabled);

  /// The first rule data breaks, or "": the validation table and byte 15,
  /// the code, no opposing pair both 1, no weapon bit unless weapons are
  /// enabled and so is the state; not enabled, the neutral frame (every bit
  /// 0 but the selector-like ones, drive and pivot at 128).
  [[nodiscard]] std::string fault(const protocol::DataBytes& data, bool enabled) const;

  /// The gate's neutral frame for data: its selectors (never both of a pair),
  /// levels and constant bytes kept, every other bit 0, drive and pivot at
  /// 128, the configured code and the validation table's bits.
  [[nodiscard]] protocol::DataBytes neutral_of(const protocol::DataBytes& data) const;

  /// A reload applied new settings: weapons may have been turned on or off.
  void set_weapons(bool weapons) { rules_.weapons = weapons; }
  [[nodiscard]] const FrameRules& rules() const { return rules_; }
  /// Frames replaced since the start.
  [[nodiscard]] std::int64_t trips() const { return trips_; }

 private:
  FrameRules rules_;
  std::int64_t trips_ = 0;
};

}  // namespace andros::run
