#pragma once
/// What each signal does, in the operator's words (docs/robots.md's): the
/// one table the cheat sheet, `learn`'s prompts and the status screen say
/// instead of the protocol's names (`zoom_down` is "zoom out", `fiber_takeup`
/// "reel in tether"). Signal names stay in YAML, errors and the frame's own views.

#include <array>
#include <string_view>

#include "andros/protocol/signals.hpp"

namespace andros::protocol {

struct SignalWords {
  std::string_view signal;
  std::string_view words;  ///< what it does: "zoom out"; for an analog byte, what it is: "drive"
  /// For an analog byte, the way it grows (drive and pivot away from centre):
  /// "forward", "right"; empty for a switch.
  std::string_view more;
  std::string_view less;  ///< the other way: "back", "left"
};

/// Every signal once, in frame order.
inline constexpr std::array kSignalWords = {
    SignalWords{"tool_on", "tool on", "", ""},
    SignalWords{"safety", "enabled (deadman held)", "", ""},
    SignalWords{"drive_brake", "brake released", "", ""},
    SignalWords{"speed_high", "vehicle speed high", "", ""},
    SignalWords{"front_art_up", "front articulators up", "", ""},
    SignalWords{"front_art_down", "front articulators down", "", ""},
    SignalWords{"rear_art_up", "rear articulators up", "", ""},
    SignalWords{"rear_art_down", "rear articulators down", "", ""},
    SignalWords{"pt_left", "pan left", "", ""},
    SignalWords{"pt_right", "pan right", "", ""},
    SignalWords{"pt_up", "tilt up", "", ""},
    SignalWords{"pt_down", "tilt down", "", ""},
    SignalWords{"focus_down", "focus down", "", ""},
    SignalWords{"focus_up", "focus up", "", ""},
    SignalWords{"iris_up", "iris open", "", ""},
    SignalWords{"iris_down", "iris close", "", ""},
    SignalWords{"zoom_down", "zoom out", "", ""},
    SignalWords{"zoom_up", "zoom in", "", ""},
    SignalWords{"inset_4", "inset 4", "", ""},
    SignalWords{"inset_3", "inset 3", "", ""},
    SignalWords{"fiber_unwind", "pay out tether", "", ""},
    SignalWords{"fiber_takeup", "reel in tether", "", ""},
    SignalWords{"weapon_1", "weapon 1", "", ""},
    SignalWords{"weapon_2", "weapon 2", "", ""},
    SignalWords{"weapon_3", "weapon 3", "", ""},
    SignalWords{"shotgun", "shotgun", "", ""},
    SignalWords{"laser", "laser", "", ""},
    SignalWords{"shoulder_cw", "shoulder down", "", ""},
    SignalWords{"shoulder_ccw", "shoulder up", "", ""},
    SignalWords{"torso_left", "turn torso left", "", ""},
    SignalWords{"torso_right", "turn torso right", "", ""},
    SignalWords{"wrist_cw", "wrist CW", "", ""},
    SignalWords{"wrist_ccw", "wrist CCW", "", ""},
    SignalWords{"gripper_rot_ccw", "rotate gripper CCW", "", ""},
    SignalWords{"gripper_rot_cw", "rotate gripper CW", "", ""},
    SignalWords{"gripper_open", "open gripper", "", ""},
    SignalWords{"gripper_close", "close gripper", "", ""},
    SignalWords{"elbow_cw", "elbow down", "", ""},
    SignalWords{"elbow_ccw", "elbow up", "", ""},
    SignalWords{"pivot", "pivot", "right", "left"},
    SignalWords{"drive", "drive", "forward", "back"},
    SignalWords{"arm_speed", "arm speed", "faster", "slower"},
    SignalWords{"light", "light", "brighter", "dimmer"},
    SignalWords{"pt_extend_up", "camera mast up", "", ""},
    SignalWords{"pt_extend_down", "camera mast down", "", ""},
    SignalWords{"wrist_extend_left", "wrist extend left", "", ""},
    SignalWords{"wrist_extend_right", "wrist extend right", "", ""},
    SignalWords{"graphics_down", "on-screen graphics down", "", ""},
    SignalWords{"graphics_up", "on-screen graphics up", "", ""},
    SignalWords{"weapon_4", "weapon 4", "", ""},
    SignalWords{"enable_key", "weapons enable key", "", ""},
    SignalWords{"code", "switchbox code", "", ""},
    SignalWords{"byte12", "byte 12", "", ""},
    SignalWords{"inset_video_1", "inset video 1", "", ""},
    SignalWords{"inset_video_2", "inset video 2", "", ""},
    SignalWords{"main_video_2", "main video 2", "", ""},
    SignalWords{"main_video_3", "main video 3", "", ""},
    SignalWords{"main_video_4", "main video 4", "", ""},
    SignalWords{"speed_low", "vehicle speed low", "", ""},
    SignalWords{"weapon_5", "weapon 5", "", ""},
    SignalWords{"weapon_6", "weapon 6", "", ""},
    SignalWords{"battery", "battery", "", ""},
};
static_assert(kSignalWords.size() == kSignalCount, "one entry per signal of kSignals");

/// The words of a signal (kSignalWords is in kSignals' order: checked at compile time).
constexpr const SignalWords& words(SignalId id) { return kSignalWords[id]; }

/// A rotary switch of the switchbox made of selector-like bits, and what its
/// position with none of them set means: the video selectors' first camera,
/// the middle speed. What the operator reads where the frame shows no bit.
struct SelectorWords {
  std::string_view name;                  ///< "vehicle speed"
  std::array<std::string_view, 4> bits;   ///< its signals ("" pads the list)
  std::array<std::string_view, 4> words;  ///< each bit's position: "low", "high"
  std::string_view none;                  ///< no bit set: "medium"
};

inline constexpr std::array kSelectorWords = {
    SelectorWords{"vehicle speed", {"speed_low", "speed_high", "", ""}, {"low", "high", "", ""}, "medium"},
    SelectorWords{"main video", {"main_video_2", "main_video_3", "main_video_4", ""}, {"2", "3", "4", ""}, "1"},
    SelectorWords{"inset", {"inset_video_1", "inset_video_2", "inset_3", "inset_4"}, {"1", "2", "3", "4"}, "off"},
};

namespace detail {
constexpr bool words_in_signal_order() {
  for (std::size_t i = 0; i < kSignalCount; ++i) {
    if (kSignalWords[i].signal != kSignals[i].name) return false;
  }
  return true;
}
}  // namespace detail
static_assert(detail::words_in_signal_order(), "kSignalWords must list the signals in kSignals' order");

}  // namespace andros::protocol
