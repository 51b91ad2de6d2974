#pragma once
// How the cheat sheet words a mapping (docs/sheets.md): an input's label,
// the way an axis is pushed, a signal's words, the mapping's figures.

#include <string>

#include "andros/input/input_state.hpp"
#include "andros/mapping/model.hpp"
#include "andros/protocol/signals.hpp"

namespace andros::view::sheet_detail {

/// An input as the operator finds it on the pad: "LB", "left stick up/down", "hat 0 up".
std::string label(input::InputKey key);

bool is_trigger(input::InputKey key);

/// The way an axis is pushed to read as `positive` after invert: "up", "right", "squeezed".
std::string direction(input::InputKey axis, bool invert, bool positive);

/// What a signal does, in the operator's words (protocol/words.hpp): "zoom out".
std::string signal_words(protocol::SignalId id);

/// A mapping's own name (a selector's) as words: "main_video" reads "main video".
std::string spoken(std::string text);

/// A number of the mapping as it is written there: 0.1, 0.35.
std::string figure(double value);

/// A fraction as a percentage to three significant figures: "25%", "12.5%".
std::string exact_percent(double fraction);

/// A threshold other than the default: "past 35%" ("" for the default).
std::string past(double threshold);

/// How the deadman is held, when it is not a plain button: "past half way;
/// off past 90% until fully released".
std::string deadman_detail(const mapping::Mapping& m);

}  // namespace andros::view::sheet_detail
