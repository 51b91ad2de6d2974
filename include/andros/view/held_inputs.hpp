#pragma once
/// What the hands held, read from the controllers' state with the mapping in
/// effect: the facts the plot's lanes draw and the export's input columns
/// give (docs/recording.md). The deadman is held by its own rule; any other
/// input when its button is down or its axis is past the mapping's default
/// threshold, on a controller that is connected; a chord when every input of
/// it is held at once.

#include <vector>

#include "andros/input/input_state.hpp"
#include "andros/mapping/model.hpp"

namespace andros::view {

/// At one moment; an input the mapping has none of is never held.
struct HeldInputs {
  bool operator_pad = false;      ///< the operator's controller connected
  bool supervisor_pad = false;    ///< the supervisor's controller connected
  bool deadman = false;           ///< the operator's deadman
  bool operator_stop = false;     ///< the operator's stop button (`estop`)
  bool operator_reset = false;    ///< every input of the operator's `stop_reset`, on the operator's controller
  bool supervisor_stop = false;   ///< the supervisor's `stop`
  bool supervisor_reset = false;  ///< every input of the supervisor's `reset`
  bool consent = false;           ///< the supervisor's `weapons_consent`

  /// Each held here or in other: held at either moment.
  HeldInputs& operator|=(const HeldInputs& other);
};

/// One input held on pad.
bool held(const input::PadState& pad, const mapping::InputUse& use);

/// What is held now, read with mapping.
HeldInputs held_inputs(const input::InputState& input, const mapping::Mapping& mapping);

}  // namespace andros::view
