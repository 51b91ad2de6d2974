#include "andros/run/frame_gate.hpp"

#include <cstddef>

#include "andros/base/text.hpp"
#include "andros/protocol/signals.hpp"

namespace andros::run {
namespace {

using protocol::kSignals;
using protocol::SignalKind;

std::string named(std::size_t i) { return std::string(kSignals[i].name); }

/// Bits that may be 1 in a neutral frame: the selector-like ones only.
bool kept_in_neutral(const protocol::SignalInfo& sig) { return sig.kind == SignalKind::kSelector; }

}  // namespace

GateVerdict FrameGate::pass(const protocol::DataBytes& offered, bool enabled) {
  GateVerdict verdict{offered, fault(offered, enabled)};
  if (verdict.tripped()) {
    verdict.data = neutral_of(offered);
    ++trips_;
  }
  return verdict;
}

std::string FrameGate::fault(const protocol::DataBytes& data, bool enabled) const {
  if (const auto errors = protocol::validation_errors(data); !errors.empty()) return "invalid frame: " + errors.front();
  if (data[protocol::kCodeByte] != rules_.code) {
    return "byte 11 is 0x" + hex_byte(data[protocol::kCodeByte]) + ", the configured code is 0x" +
           hex_byte(rules_.code);
  }
  const auto s = protocol::read_signals(data);
  for (std::size_t i = 0; i < protocol::kSignalCount; ++i) {
    const auto partner = protocol::partner_of(static_cast<protocol::SignalId>(i));
    if (partner && *partner > i && s.values[i] != 0 && s.values[*partner] != 0) {
      return named(i) + " and " + named(*partner) + " both 1 (an opposing pair)";
    }
  }
  for (std::size_t i = 0; i < protocol::kSignalCount; ++i) {
    if (kSignals[i].kind != SignalKind::kWeapon || s.values[i] == 0) continue;
    if (!rules_.weapons) return named(i) + " = 1 with weapons not enabled for the run";
    if (!enabled) return named(i) + " = 1 while not enabled";
  }
  if (enabled) return {};
  for (std::size_t i = 0; i < protocol::kSignalCount; ++i) {
    const auto& sig = kSignals[i];
    if (sig.kind == SignalKind::kCentred && s.values[i] != protocol::kNeutralCentre) {
      return named(i) + " = " + std::to_string(s.values[i]) + " while not enabled (neutral is 128)";
    }
    if (sig.is_bit() && !kept_in_neutral(sig) && s.values[i] != 0) return named(i) + " = 1 while not enabled";
  }
  return {};
}

protocol::DataBytes FrameGate::neutral_of(const protocol::DataBytes& data) const {
  const auto s = protocol::read_signals(data);
  protocol::ControlState n;
  for (std::size_t i = 0; i < protocol::kSignalCount; ++i) {
    const auto& sig = kSignals[i];
    if (sig.kind == SignalKind::kCentred) n.values[i] = protocol::kNeutralCentre;
    else if (!sig.is_bit() || kept_in_neutral(sig)) n.values[i] = s.values[i];
  }
  // A selector pair both 1 (speed high and low) is neither.
  for (std::size_t i = 0; i < protocol::kSignalCount; ++i) {
    const auto partner = protocol::partner_of(static_cast<protocol::SignalId>(i));
    if (partner && s.values[i] != 0 && s.values[*partner] != 0) n.values[i] = 0;
  }
  return protocol::FrameBuilder(rules_.code).build(n);
}

}  // namespace andros::run
