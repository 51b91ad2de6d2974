#include "andros/protocol/signals.hpp"

namespace andros::protocol {

std::string_view to_string(SignalKind kind) {
  switch (kind) {
    case SignalKind::kMotion: return "motion";
    case SignalKind::kSelector: return "selector";
    case SignalKind::kWeapon: return "weapon";
    case SignalKind::kInterlock: return "interlock";
    case SignalKind::kCentred: return "centred";
    case SignalKind::kLevel: return "level";
    case SignalKind::kConstant: return "constant";
  }
  return "?";
}

// The table must be in frame order and must not place two signals on one bit
// or on a fixed bit; checked once, at compile time.
static_assert(
    [] {
      for (std::size_t i = 0; i < kSignals.size(); ++i) {
        const auto& s = kSignals[i];
        if (s.byte >= kDataBytes || s.byte == kTrailerByte) return false;
        if (s.is_bit() && is_fixed_bit(s.byte, static_cast<std::uint8_t>(s.bit))) return false;
        if (i > 0) {
          const auto& p = kSignals[i - 1];
          if (p.byte > s.byte) return false;
          if (p.byte == s.byte && (!p.is_bit() || !s.is_bit() || p.bit >= s.bit)) return false;
        }
        if (!s.partner.empty()) {
          const auto other = find_signal(s.partner);
          if (!other || kSignals[*other].partner != s.name) return false;
        }
      }
      return true;
    }(),
    "kSignals must be in frame order, avoid fixed bits, and pair partners both ways");

}  // namespace andros::protocol
