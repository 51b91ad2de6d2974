// What the hands held (andros/view/held_inputs.hpp), read as the loop reads
// it: the plot's lanes and the export's input columns are this one reading.
#include "andros/view/held_inputs.hpp"

#include <algorithm>

#include "andros/mapping/axis.hpp"
#include "andros/run/deadman.hpp"

namespace andros::view {
namespace {

/// Every input of a chord held at once; an empty chord (none in the mapping) never is.
bool chord_held(const input::PadState& pad, const std::vector<mapping::InputUse>& chord) {
  return !chord.empty() &&
         std::all_of(chord.begin(), chord.end(), [&pad](const mapping::InputUse& use) { return held(pad, use); });
}

}  // namespace

HeldInputs& HeldInputs::operator|=(const HeldInputs& o) {
  operator_pad = operator_pad || o.operator_pad;
  supervisor_pad = supervisor_pad || o.supervisor_pad;
  deadman = deadman || o.deadman;
  operator_stop = operator_stop || o.operator_stop;
  operator_reset = operator_reset || o.operator_reset;
  supervisor_stop = supervisor_stop || o.supervisor_stop;
  supervisor_reset = supervisor_reset || o.supervisor_reset;
  consent = consent || o.consent;
  return *this;
}

bool held(const input::PadState& pad, const mapping::InputUse& use) {
  if (!pad.connected()) return false;
  if (use.key.is_button()) return pad.button(use.key).down;
  return mapping::normalise_axis(pad.axis(use.key)) >= mapping::kDefaultThreshold;
}

HeldInputs held_inputs(const input::InputState& input, const mapping::Mapping& m) {
  const auto& op = input.operator_pad();
  const auto& sup = input.supervisor();
  HeldInputs out;
  out.operator_pad = op.connected();
  out.supervisor_pad = sup.connected();
  out.deadman = run::Deadman(m).held(input);
  out.operator_stop = m.estop && held(op, *m.estop);
  out.operator_reset = chord_held(op, m.stop_reset);
  if (m.supervisor) {
    out.supervisor_stop = held(sup, m.supervisor->stop);
    out.supervisor_reset = chord_held(sup, m.supervisor->reset);
    out.consent = m.supervisor->weapons_consent && held(sup, *m.supervisor->weapons_consent);
  }
  return out;
}

}  // namespace andros::view
