// Table-driven replay: every tests/data/replay/NAME.events against its
// hand-derived NAME.expected (see replay_data.hpp for the format).
#include <gtest/gtest.h>

#include <string>

#include "andros/mapping/loader.hpp"
#include "andros/run/replay.hpp"
#include "support/replay_data.hpp"

namespace andros::run {
namespace {

struct Case {
  const char* name;
  std::string mapping;  // under tests/data/mappings/, or an absolute path
  bool weapons = false;
  std::int64_t rate_millihertz = timing::kDefaultRateMillihertz;
};

const std::string kData = ANDROS_TEST_DATA_DIR;

void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

class ReplayData : public ::testing::TestWithParam<Case> {};

TEST_P(ReplayData, FramesMatchTheHandDerivedOnes) {
  const auto& c = GetParam();
  const std::string base = kData + "/replay/" + c.name;
  const auto mapping = c.mapping.starts_with('/') ? c.mapping : kData + "/mappings/" + c.mapping;
  testing::expect_replay(mapping::load_mapping(mapping), c.weapons, c.rate_millihertz, base + ".events",
                         base + ".expected");
}

INSTANTIATE_TEST_SUITE_P(
    Catalogue, ReplayData,
    ::testing::Values(
        Case{"momentary", "core.yaml"}, Case{"toggle", "core.yaml"}, Case{"opposing_axis_pair", "core.yaml"},
        Case{"drive_deadzone", "core.yaml"}, Case{"pivot_deadzone_expo", "core.yaml"},
        Case{"trigger_analog", "core.yaml"}, Case{"knob_ramp", "core.yaml"}, Case{"deadman_release", "core.yaml"},
        Case{"fresh_press_after_connect", "core.yaml"}, Case{"stuck_deadman_at_connect", "core.yaml"},
        Case{"controller_loss_mid_drive", "core.yaml"}, Case{"reconnect", "core.yaml"},
        Case{"toggle_cleared_by_loss", "core.yaml"}, Case{"short_tap_between_frames", "core.yaml"},
        Case{"opposing_buttons", "core.yaml"}, Case{"presses_while_disabled_ignored", "core.yaml"},
        Case{"weapons_off", "core.yaml"}, Case{"weapons_on_without_arming", "core.yaml", true},
        Case{"weapons_on_armed", "core.yaml", true}, Case{"selector_cycling", "layers.yaml"},
        Case{"layers", "layers.yaml"}, Case{"joystick", "joystick.yaml"}, Case{"rate_24hz", "core.yaml", false, 24'000},
        // No motion from a change of meaning; one toggle state per signal.
        Case{"layer_release_stick_held", ANDROS_MAPPINGS_DIR "/hd1.yaml"},
        Case{"layer_entered_stick_held", "layers.yaml"}, Case{"toggle_layer_stick_held", "rest.yaml"},
        Case{"deadman_pressed_stick_deflected", "core.yaml"}, Case{"trigger_held_across_layer", "rest.yaml"},
        Case{"button_held_across_layer", "rest.yaml"}, Case{"toggle_held_across_layer", "rest.yaml"},
        Case{"two_toggles_one_signal", "rest.yaml"},
        // Neutral is the protocol's: a center trim moves only the enabled rest.
        Case{"center_trim", "trim.yaml"},
        // Speed levels: exact scaling, a held stick held back at a change, the level's life.
        Case{"speed_levels", "speed.yaml"},
        // The supervisor's controller: its loss, its absence at the start, its weapons consent.
        Case{"supervisor_loss", "core.yaml"}, Case{"supervisor_late", "core.yaml"},
        Case{"supervisor_consent", "supervisor.yaml", true},
        // Every change between two frames counts: a deadman let go and pressed again, a panic squeeze.
        Case{"deadman_blip_within_tick", "core.yaml"}, Case{"panic_within_tick", "safety.yaml"},
        // A stop is reset by the book: on the pad that stopped (or the supervisor's), deliberately.
        Case{"stop_reset_by_the_book", "stops.yaml"}, Case{"supervisor_stop_not_reset_by_the_operator", "stops.yaml"},
        // Issue 33: a stop button held is never a reset; nothing moves while it is held.
        Case{"supervisor_stop_held_never_drives", "issue33.yaml"}, Case{"another_pad_cannot_reset", "stops.yaml"},
        // A stop outlives its own tick; a panic ends only with a full release.
        Case{"stop_tapped_within_a_tick", ANDROS_MAPPINGS_DIR "/hd1.yaml"},
        Case{"stop_tapped_as_the_supervisor_returns", ANDROS_MAPPINGS_DIR "/hd1.yaml"},
        Case{"panic_back_to_the_middle", "safety.yaml"},
        // Enabled after a rebase is a change of meaning, whatever the engine stepped meanwhile.
        Case{"link_back_stick_pushed", "core.yaml"}),
    [](const auto& param_info) { return std::string(param_info.param.name); });

}  // namespace
}  // namespace andros::run
