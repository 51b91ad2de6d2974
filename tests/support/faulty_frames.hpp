#pragma once
// A frame source that is wrong on purpose: the mapping engine with one fault
// injected into its frames, for the frame gate's mutation test
// (tests/run/test_frame_gate.cpp) and the fault simulation's engine at fault
// (tests/oracle/simulation.hpp, through replay's ReplayOptions::frames, which
// `andros-bridge replay` leaves as it is). The seam is this wrapper, in the
// tests: the production code has no switch for it.

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <utility>

#include "andros/run/bridge.hpp"

namespace andros::test {

enum class EngineFault : std::uint8_t {
  kStaleNeutral,          ///< the neutral frame is the last step's (a stop's frames carry the motion)
  kDriveInNeutral,        ///< drive off centre in the neutral frame
  kPivotInNeutral,        ///< pivot off centre in the neutral frame
  kSafetyInNeutral,       ///< an interlock bit (`safety`) in the neutral frame
  kMotionBitInNeutral,    ///< a motion bit (`pt_left`) in the neutral frame
  kWeaponInNeutral,       ///< a weapon bit in the neutral frame, weapons enabled for the run
  kWeaponWithoutWeapons,  ///< a weapon bit while driving, weapons not enabled for the run
  kOpposingPair,          ///< front articulation up and down both 1 while driving
  kSpeedPair,             ///< speed high and low both 1 while driving
  kWrongCode,             ///< byte 11 not the configured code
  kWrongTrailer,          ///< byte 15 not 0x02
  kFixedBit,              ///< a bit of the validation table flipped
};

struct FaultKind {
  EngineFault fault;
  const char* name;
  bool weapons;  ///< the run's weapons setting the fault is injected under
};

inline constexpr std::array kFaultKinds = {
    FaultKind{EngineFault::kStaleNeutral, "motion while not enabled (a stale neutral frame)", false},
    FaultKind{EngineFault::kDriveInNeutral, "drive off centre in neutral", false},
    FaultKind{EngineFault::kPivotInNeutral, "pivot off centre in neutral", false},
    FaultKind{EngineFault::kSafetyInNeutral, "safety bit while not enabled", false},
    FaultKind{EngineFault::kMotionBitInNeutral, "a motion bit while not enabled", false},
    FaultKind{EngineFault::kWeaponInNeutral, "a weapon bit while not enabled", true},
    FaultKind{EngineFault::kWeaponWithoutWeapons, "a weapon bit without weapons enabled", false},
    FaultKind{EngineFault::kOpposingPair, "both of an opposing pair", false},
    FaultKind{EngineFault::kSpeedPair, "both speed selectors", false},
    FaultKind{EngineFault::kWrongCode, "a wrong code byte", false},
    FaultKind{EngineFault::kWrongTrailer, "a wrong byte 15", false},
    FaultKind{EngineFault::kFixedBit, "a fixed bit wrong", false},
};

/// The engine, its frames and neutral frame with the fault (from_ms on: the
/// first tick the loop asks the engine about at or after it); the rest passed on as it is.
class FaultyFrames final : public run::FrameSource {
 public:
  FaultyFrames(std::unique_ptr<run::FrameSource> inner, EngineFault fault, std::int64_t from_ms = 0)
      : inner_(std::move(inner)), fault_(fault), from_ms_(from_ms), on_(from_ms <= 0) {}

  [[nodiscard]] const mapping::Mapping& mapping() const override { return inner_->mapping(); }
  void rebase(const input::InputState& now) override { inner_->rebase(now); }

  run::Step step(const input::InputState& input, std::int64_t now_ms, bool motion_allowed) override {
    on_ = on_ || now_ms >= from_ms_;
    run::Step s = inner_->step(input, now_ms, motion_allowed);
    if (!on_) return s;
    if (fault_ == EngineFault::kStaleNeutral) {
      // The frames while not enabled are the last driving one's.
      if (motion_allowed) last_ = s.data;
      else if (last_) s.data = *last_;
      return s;
    }
    // A frame with motion allowed gets the driving faults; one without (sent as the neutral frame), the neutral ones.
    if (in_neutral() != motion_allowed) inject(s.data);
    return s;
  }
  [[nodiscard]] protocol::DataBytes neutral() const override {
    if (!on_) return inner_->neutral();
    if (fault_ == EngineFault::kStaleNeutral && last_) return *last_;
    protocol::DataBytes n = inner_->neutral();
    if (in_neutral()) inject(n);
    return n;
  }

 private:
  [[nodiscard]] bool in_neutral() const {
    switch (fault_) {
      case EngineFault::kStaleNeutral:
      case EngineFault::kDriveInNeutral:
      case EngineFault::kPivotInNeutral:
      case EngineFault::kSafetyInNeutral:
      case EngineFault::kMotionBitInNeutral:
      case EngineFault::kWeaponInNeutral: return true;
      default: return false;
    }
  }
  static void set(protocol::DataBytes& d, protocol::SignalId id, bool on) {
    const auto& sig = protocol::info(id);
    const auto mask = static_cast<std::uint8_t>(1U << sig.bit);
    d[sig.byte] = static_cast<std::uint8_t>(on ? (d[sig.byte] | mask) : (d[sig.byte] & ~mask));
  }
  void inject(protocol::DataBytes& d) const {
    using protocol::signal_id;
    switch (fault_) {
      case EngineFault::kStaleNeutral: break;
      case EngineFault::kDriveInNeutral: d[protocol::info(signal_id("drive")).byte] = 140; break;
      case EngineFault::kPivotInNeutral: d[protocol::info(signal_id("pivot")).byte] = 90; break;
      case EngineFault::kSafetyInNeutral: set(d, signal_id("safety"), true); break;
      case EngineFault::kMotionBitInNeutral: set(d, signal_id("pt_left"), true); break;
      case EngineFault::kWeaponInNeutral: set(d, signal_id("weapon_1"), true); break;
      case EngineFault::kWeaponWithoutWeapons: set(d, signal_id("weapon_3"), true); break;
      case EngineFault::kOpposingPair:
        set(d, signal_id("front_art_up"), true);
        set(d, signal_id("front_art_down"), true);
        break;
      case EngineFault::kSpeedPair:
        set(d, signal_id("speed_high"), true);
        set(d, signal_id("speed_low"), true);
        break;
      case EngineFault::kWrongCode:
        d[protocol::kCodeByte] = static_cast<std::uint8_t>(d[protocol::kCodeByte] + 1);
        break;
      case EngineFault::kWrongTrailer: d[protocol::kTrailerByte] = 0x03; break;
      case EngineFault::kFixedBit: d[2] = static_cast<std::uint8_t>(d[2] ^ 0x08U); break;  // byte 2 bit 3 must be 1
    }
  }

  std::unique_ptr<run::FrameSource> inner_;
  EngineFault fault_;
  std::int64_t from_ms_;
  bool on_;
  std::optional<protocol::DataBytes> last_;
};

}  // namespace andros::test
