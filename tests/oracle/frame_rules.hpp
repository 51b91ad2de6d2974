#pragma once
// The fault simulation oracle's rules on one frame by itself
// (safety_oracle.hpp): what every frame must be whatever the state, and what
// counts as motion (anything a neutral frame may not carry).

#include <cstdint>
#include <optional>
#include <string>

#include "andros/protocol/frame.hpp"

namespace andros::test {

/// Drive and pivot in every neutral frame: the protocol's centre, whatever a mapping says.
inline constexpr std::uint8_t kNeutralCentre = 128;

/// Every frame: the validation table, the code, and no opposing pair both 1. Empty, or the rule broken.
inline std::string frame_errors(const protocol::DataBytes& data, const protocol::ControlState& s, std::uint8_t code) {
  // [rule: valid]
  if (const auto errors = protocol::validation_errors(data); !errors.empty()) return "invalid frame: " + errors.front();
  // [rule: code]
  if (data[protocol::kCodeByte] != code) return "byte 11 is not the code";
  // [rule: pairs]
  for (std::size_t i = 0; i < protocol::kSignalCount; ++i) {
    const auto partner = protocol::partner_of(static_cast<protocol::SignalId>(i));
    if (partner && *partner > i && s.values[i] != 0 && s.values[*partner] != 0) {
      return std::string(protocol::kSignals[i].name) + " and " + std::string(protocol::kSignals[*partner].name) +
             " both 1 (an opposing pair)";
    }
  }
  return {};
}

/// Weapon bits: only with --weapons, while enabled (why: empty, or why the
/// frame must be neutral), with an arming input held and, where the mapping
/// in force asks for it, the supervisor's consent held (consent). Counts them.
// [rule: weapons]
template <typename Armed>
std::string weapon_errors(const protocol::ControlState& s, bool weapons, const std::string& why, const Armed& armed,
                          bool consent, std::int64_t& count) {
  for (std::size_t i = 0; i < protocol::kSignalCount; ++i) {
    const auto& sig = protocol::kSignals[i];
    if (sig.kind != protocol::SignalKind::kWeapon || s.values[i] == 0) continue;
    ++count;
    if (!weapons) return std::string(sig.name) + " = 1 without --weapons";
    if (!why.empty()) return std::string(sig.name) + " = 1 while " + why;
    if (!armed(static_cast<protocol::SignalId>(i))) return std::string(sig.name) + " = 1 without its arming input held";
    // [rule: consent]
    if (!consent) return std::string(sig.name) + " = 1 without the supervisor's weapons consent held";
  }
  return {};
}

/// Motion: drive or pivot off the protocol's centre, or any bit that is not
/// selector-like (safety and drive_brake included).
inline std::optional<std::string> motion(const protocol::ControlState& s) {
  for (std::size_t i = 0; i < protocol::kSignalCount; ++i) {
    const auto& sig = protocol::kSignals[i];
    if (sig.kind == protocol::SignalKind::kCentred && s.values[i] != kNeutralCentre) {
      return std::string(sig.name) + " = " + std::to_string(s.values[i]);
    }
    if (sig.is_bit() && sig.kind != protocol::SignalKind::kSelector && s.values[i] != 0) {
      return std::string(sig.name) + " = 1";
    }
  }
  return std::nullopt;
}

}  // namespace andros::test
