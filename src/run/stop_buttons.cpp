#include "andros/run/stop_buttons.hpp"

#include <algorithm>
#include <utility>

namespace andros::run {
namespace {

std::vector<input::InputKey> keys_of(const std::vector<mapping::InputUse>& uses) {
  std::vector<input::InputKey> keys;
  keys.reserve(uses.size());
  for (const auto& u : uses) keys.push_back(u.key);
  return keys;
}

}  // namespace

StopButtons::StopButtons(const mapping::Mapping& mapping) : hold_ms_(mapping.stop_reset_hold_ms) {
  if (mapping.estop) operator_.key = mapping.estop->key;
  operator_reset_.keys = keys_of(mapping.stop_reset);
  if (mapping.supervisor) {
    supervisor_.key = mapping.supervisor->stop.key;
    supervisor_reset_.keys = keys_of(mapping.supervisor->reset);
  }
  operator_gesture_ = gesture_text(operator_reset_.keys);
  supervisor_gesture_ = gesture_text(supervisor_reset_.keys);
}

void StopButtons::start(const input::InputState& input, bool at_start_up) {
  const auto& pad = input.operator_pad();
  operator_.connection = pad.connection();
  operator_.presses = at_start_up && operator_.key ? pad.button(*operator_.key).presses : 0;
  end(pad, operator_reset_);
}

void StopButtons::forget(const input::InputState& input) {
  for (auto [pad, b] : {std::pair{&input.operator_pad(), &operator_}, std::pair{&input.supervisor(), &supervisor_}}) {
    b->connection = pad->connection();
    b->presses = b->key ? pad->button(*b->key).presses : 0;
  }
  end(input.operator_pad(), operator_reset_);
  end(input.supervisor(), supervisor_reset_);
}

bool StopButtons::pressed(const input::PadState& pad, Button& b) {
  if (!b.key || !pad.connected()) return false;
  // Presses are counted per controller session: a new one counts from its connect.
  if (pad.connection() != b.connection) b = Button{b.key, pad.connection(), 0};
  const auto now = pad.button(*b.key).presses;
  const bool fresh = now > b.presses;
  b.presses = now;
  return fresh;
}

bool StopButtons::down(const input::PadState& pad, const Button& b) {
  return b.key && pad.connected() && pad.button(*b.key).down;
}

bool StopButtons::take(const input::PadState& pad, Button& b) {
  // Pressed (even a tap between two ticks), or held: a stop, whenever.
  const bool fresh = pressed(pad, b);
  return fresh || down(pad, b);
}

mapping::StopPresses StopButtons::take(const input::InputState& input) {
  // Both are taken: neither press may wait for a later read.
  const bool by_operator = take(input.operator_pad(), operator_);
  const bool by_supervisor = take(input.supervisor(), supervisor_);
  end(input.operator_pad(), operator_reset_);
  end(input.supervisor(), supervisor_reset_);
  return {by_operator, by_supervisor};
}

void StopButtons::end(const input::PadState& pad, Reset& r) {
  r.connection = pad.connection();
  r.releases.clear();
  bool made = !r.keys.empty();
  for (const auto key : r.keys) {
    const auto now = pad.button(key);
    r.releases.push_back(now.releases);
    made = made && now.down;
  }
  r.open = !made;  // made now, or held on: let go and made again
  r.hold_since.reset();
}

bool StopButtons::tick(const input::PadState& pad, Reset& r, bool blocked, std::int64_t now_ms) const {
  if (r.keys.empty()) return false;
  if (!pad.connected() || pad.connection() != r.connection) {
    // Another controller session: a gesture held at its connect is not made afresh.
    end(pad, r);
    return false;
  }
  bool made = true;
  bool let_go = false;
  for (std::size_t i = 0; i < r.keys.size(); ++i) {
    const auto now = pad.button(r.keys[i]);
    made = made && now.down;
    let_go = let_go || now.releases > r.releases[i];
    r.releases[i] = now.releases;
  }
  if (blocked) {
    // A stop pressed or held, or the deadman touched: the hold ends, and a gesture still made is made again.
    r.open = !made;
    r.hold_since.reset();
    return false;
  }
  // Let go (even let go and made again between two ticks): the hold ends, and a making now is afresh.
  if (!made || let_go) {
    r.open = true;
    r.hold_since.reset();
  }
  if (!made || !r.open) return false;
  if (!r.hold_since) r.hold_since = now_ms;
  if (now_ms - *r.hold_since < hold_ms_) return false;
  r.hold_since.reset();
  r.open = false;
  return true;
}

StoppedTick StopButtons::stopped(const input::InputState& input, bool deadman_touched, std::int64_t now_ms) {
  StoppedTick out;
  const auto& op = input.operator_pad();
  const auto& sup = input.supervisor();
  out.pressed.by_operator = pressed(op, operator_);
  out.pressed.by_supervisor = pressed(sup, supervisor_);
  // While any stop button on any pad is pressed or held, no reset goes on.
  const bool blocked = out.pressed.any() || down(op, operator_) || down(sup, supervisor_) || deadman_touched;
  if (tick(op, operator_reset_, blocked, now_ms)) out.reset = input::Pad::kOperator;
  if (tick(sup, supervisor_reset_, blocked, now_ms))
    out.reset = input::Pad::kSupervisor;  // the supervisor's, when both
  for (const auto& [pad, r] :
       {std::pair{input::Pad::kOperator, &operator_reset_}, std::pair{input::Pad::kSupervisor, &supervisor_reset_}}) {
    if (!r->hold_since) continue;
    const std::int64_t held = now_ms - *r->hold_since;
    if (!out.hold || held > out.hold->held_ms) out.hold = mapping::ResetHold{pad, held, hold_ms_};
  }
  return out;
}

std::string gesture_text(const std::vector<input::InputKey>& keys) {
  std::string out;
  for (const auto key : keys) out += (out.empty() ? "" : "+") + input::input_name(key);
  return out;
}

void StopButtons::held(const input::InputState& input, mapping::EngineStatus& status) const {
  status.operator_reset = operator_gesture_;
  status.supervisor_reset = supervisor_gesture_;
  status.reset_hold_ms = hold_ms_;
  status.reset_hold.reset();  // a stopped tick's (StoppedTick::hold)
  status.supervisor_stop = down(input.supervisor(), supervisor_);
  status.stop_held = status.supervisor_stop || down(input.operator_pad(), operator_);
}

}  // namespace andros::run
