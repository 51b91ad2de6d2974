#pragma once
/// The signal catalogue: every signal of the switchbox frame under the
/// canonical names of the protocol reference, in one table. The encoder, the
/// decoder, the mapping loader, the JSON output and the docs all derive from it.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

namespace andros::protocol {

inline constexpr std::size_t kDataBytes = 16;

/// How a signal behaves, which decides what the safety layer does with it.
enum class SignalKind : std::uint8_t {
  kMotion,     ///< a switch that moves something: 0 in the neutral frame
  kSelector,   ///< a selector-like switch (speed, video): kept in the neutral frame
  kWeapon,     ///< 0 unless weapons are enabled, armed and the deadman held
  kInterlock,  ///< `safety` and `drive_brake`: owned by the safety layer, never bound
  kCentred,    ///< `drive` and `pivot`: a whole byte, at centre in the neutral frame
  kLevel,      ///< `arm_speed` and `light`: a whole byte, kept in the neutral frame
  kConstant,   ///< `code`, `byte12`, `battery`: whole bytes fixed for the run
};

inline constexpr std::int8_t kWholeByte = -1;
/// The largest value of a whole byte: `drive` and `pivot` at full, a level,
/// a constant.
inline constexpr int kWholeByteMax = 255;

/// `drive` and `pivot` in every neutral frame. The protocol's, not a
/// mapping's: no `center:` trim reaches a frame sent while not enabled.
inline constexpr std::uint8_t kNeutralCentre = 128;

struct SignalInfo {
  std::string_view name;
  std::uint8_t byte;
  std::int8_t bit;  ///< 0..7, or kWholeByte for an analog or constant byte
  SignalKind kind;
  std::string_view partner;  ///< the opposing signal, empty when there is none
  std::string_view label;    ///< the ICD's own wording

  [[nodiscard]] constexpr bool is_bit() const { return bit != kWholeByte; }
};

// The one table. Order is frame order (byte, then bit).
inline constexpr auto kSignals = [] {
  using K = SignalKind;
  return std::array{
      SignalInfo{"tool_on", 0, 0, K::kMotion, "", "Tool On"},
      SignalInfo{"safety", 0, 1, K::kInterlock, "", "Safety: 1 to drive, 0 is safe"},
      SignalInfo{"drive_brake", 0, 2, K::kInterlock, "", "Drive Brake: 1 to drive, 0 is stopped"},
      SignalInfo{"speed_high", 0, 3, K::kSelector, "speed_low", "Speed high"},
      SignalInfo{"front_art_up", 0, 4, K::kMotion, "front_art_down", "Front Art. Up"},
      SignalInfo{"front_art_down", 0, 5, K::kMotion, "front_art_up", "Front Art. Down"},
      SignalInfo{"rear_art_up", 0, 6, K::kMotion, "rear_art_down", "Rear Art. Up"},
      SignalInfo{"rear_art_down", 0, 7, K::kMotion, "rear_art_up", "Rear Art. Down"},
      SignalInfo{"pt_left", 1, 0, K::kMotion, "pt_right", "P/T Left"},
      SignalInfo{"pt_right", 1, 1, K::kMotion, "pt_left", "P/T Right"},
      SignalInfo{"pt_up", 1, 2, K::kMotion, "pt_down", "P/T Up"},
      SignalInfo{"pt_down", 1, 3, K::kMotion, "pt_up", "P/T Down"},
      SignalInfo{"focus_down", 1, 4, K::kMotion, "focus_up", "Focus down"},
      SignalInfo{"focus_up", 1, 5, K::kMotion, "focus_down", "Focus up"},
      SignalInfo{"iris_up", 1, 6, K::kMotion, "iris_down", "Iris up"},
      SignalInfo{"iris_down", 1, 7, K::kMotion, "iris_up", "Iris down"},
      SignalInfo{"zoom_down", 2, 0, K::kMotion, "zoom_up", "zoom down"},
      SignalInfo{"zoom_up", 2, 1, K::kMotion, "zoom_down", "zoom up"},
      SignalInfo{"inset_4", 2, 2, K::kSelector, "", "Inset 4"},
      SignalInfo{"inset_3", 2, 5, K::kSelector, "", "Inset 3"},
      SignalInfo{"fiber_unwind", 2, 6, K::kMotion, "fiber_takeup", "fiber unwind"},
      SignalInfo{"fiber_takeup", 2, 7, K::kMotion, "fiber_unwind", "fiber takeup"},
      SignalInfo{"weapon_1", 3, 0, K::kWeapon, "", "Weapon 1"},
      SignalInfo{"weapon_2", 3, 1, K::kWeapon, "", "Weapon 2"},
      SignalInfo{"weapon_3", 3, 2, K::kWeapon, "", "Weapon 3"},
      SignalInfo{"shotgun", 3, 3, K::kWeapon, "", "Shotgun"},
      SignalInfo{"laser", 3, 7, K::kWeapon, "", "Laser"},
      SignalInfo{"shoulder_cw", 4, 0, K::kMotion, "shoulder_ccw", "Shoulder CW"},
      SignalInfo{"shoulder_ccw", 4, 1, K::kMotion, "shoulder_cw", "Shoulder CCW"},
      SignalInfo{"torso_left", 4, 2, K::kMotion, "torso_right", "Torso left"},
      SignalInfo{"torso_right", 4, 3, K::kMotion, "torso_left", "Torso right"},
      SignalInfo{"wrist_cw", 4, 4, K::kMotion, "wrist_ccw", "Wrist CW"},
      SignalInfo{"wrist_ccw", 4, 5, K::kMotion, "wrist_cw", "Wrist CCW"},
      SignalInfo{"gripper_rot_ccw", 4, 6, K::kMotion, "gripper_rot_cw", "Gripper rot. CCW"},
      SignalInfo{"gripper_rot_cw", 4, 7, K::kMotion, "gripper_rot_ccw", "Gripper rot. CW"},
      SignalInfo{"gripper_open", 5, 0, K::kMotion, "gripper_close", "Gripper open"},
      SignalInfo{"gripper_close", 5, 1, K::kMotion, "gripper_open", "Gripper close"},
      SignalInfo{"elbow_cw", 5, 2, K::kMotion, "elbow_ccw", "Elbow CW"},
      SignalInfo{"elbow_ccw", 5, 3, K::kMotion, "elbow_cw", "Elbow CCW"},
      SignalInfo{"pivot", 6, kWholeByte, K::kCentred, "", "Calculated pivot analog value"},
      SignalInfo{"drive", 7, kWholeByte, K::kCentred, "", "Calculated drive analog value"},
      SignalInfo{"arm_speed", 8, kWholeByte, K::kLevel, "", "Arm speed analog input"},
      SignalInfo{"light", 9, kWholeByte, K::kLevel, "", "Light analog input"},
      SignalInfo{"pt_extend_up", 10, 0, K::kMotion, "pt_extend_down", "P/T extend up"},
      SignalInfo{"pt_extend_down", 10, 1, K::kMotion, "pt_extend_up", "P/T extend down"},
      SignalInfo{"wrist_extend_left", 10, 2, K::kMotion, "wrist_extend_right", "Wrist extend left"},
      SignalInfo{"wrist_extend_right", 10, 3, K::kMotion, "wrist_extend_left", "Wrist extend right"},
      SignalInfo{"graphics_down", 10, 4, K::kMotion, "graphics_up", "Graphics down"},
      SignalInfo{"graphics_up", 10, 5, K::kMotion, "graphics_down", "Graphics up"},
      SignalInfo{"weapon_4", 10, 6, K::kWeapon, "", "Weapon 4"},
      SignalInfo{"enable_key", 10, 7, K::kWeapon, "", "Enable key"},
      SignalInfo{"code", 11, kWholeByte, K::kConstant, "", "dipswitch code"},
      SignalInfo{"byte12", 12, kWholeByte, K::kConstant, "", "listed as logic 0"},
      SignalInfo{"inset_video_1", 13, 0, K::kSelector, "", "Inset video 1"},
      SignalInfo{"inset_video_2", 13, 1, K::kSelector, "", "Inset video 2"},
      SignalInfo{"main_video_2", 13, 2, K::kSelector, "", "Main video 2"},
      SignalInfo{"main_video_3", 13, 3, K::kSelector, "", "Main video 3"},
      SignalInfo{"main_video_4", 13, 4, K::kSelector, "", "Main video 4"},
      SignalInfo{"speed_low", 13, 5, K::kSelector, "speed_high", "Speed low"},
      SignalInfo{"weapon_5", 13, 6, K::kWeapon, "", "Weapon 5"},
      SignalInfo{"weapon_6", 13, 7, K::kWeapon, "", "Weapon 6"},
      SignalInfo{"battery", 14, kWholeByte, K::kConstant, "", "Battery voltage analog input"},
  };
}();

inline constexpr std::size_t kSignalCount = kSignals.size();

/// Index of a signal in kSignals.
using SignalId = std::uint8_t;

/// The signal with this canonical name, or nullopt.
constexpr std::optional<SignalId> find_signal(std::string_view name) {
  for (std::size_t i = 0; i < kSignals.size(); ++i) {
    if (kSignals[i].name == name) return static_cast<SignalId>(i);
  }
  return std::nullopt;
}

/// Compile-time lookup for the few signals code names directly
/// (`signal_id("safety")`); a misspelt name fails to compile.
consteval SignalId signal_id(std::string_view name) {
  const auto id = find_signal(name);
  if (!id) throw "unknown signal name";  // not a constant expression: compile error
  return *id;
}

constexpr const SignalInfo& info(SignalId id) { return kSignals[id]; }

/// Each signal's opposing partner, looked up by name once, at compile time:
/// apply_safety() asks for every signal's in every frame.
inline constexpr auto kPartners = [] {
  std::array<std::optional<SignalId>, kSignalCount> partners{};
  for (std::size_t i = 0; i < kSignalCount; ++i) {
    if (!kSignals[i].partner.empty()) partners[i] = find_signal(kSignals[i].partner);
  }
  return partners;
}();

/// The opposing partner of a signal, if it has one.
constexpr std::optional<SignalId> partner_of(SignalId id) { return kPartners[id]; }

/// A bit the protocol fixes (the validation table); never a mapping target.
struct FixedBit {
  std::uint8_t byte;
  std::uint8_t bit;
  std::uint8_t value;
};

inline constexpr std::array kFixedBits = {
    FixedBit{2, 3, 1}, FixedBit{2, 4, 1}, FixedBit{3, 4, 0}, FixedBit{3, 5, 1}, FixedBit{3, 6, 0},
    FixedBit{5, 4, 1}, FixedBit{5, 5, 0}, FixedBit{5, 6, 0}, FixedBit{5, 7, 1},
};

inline constexpr std::uint8_t kCodeByte = 11;
inline constexpr std::uint8_t kTrailerByte = 15;
inline constexpr std::uint8_t kTrailerValue = 0x02;

/// True when (byte, bit) is one of the validation table's fixed bits.
constexpr bool is_fixed_bit(std::uint8_t byte, std::uint8_t bit) {
  for (const auto& f : kFixedBits) {
    if (f.byte == byte && f.bit == bit) return true;
  }
  return false;
}

std::string_view to_string(SignalKind kind);

}  // namespace andros::protocol
