#include "andros/mapping/stop_buttons.hpp"

#include <utility>

namespace andros::mapping {

StopButtons::StopButtons(const Mapping& mapping) : hold_ms_(mapping.stop_reset_hold_ms) {
  if (mapping.estop) operator_.key = mapping.estop->key;
  if (mapping.supervisor) supervisor_.key = mapping.supervisor->stop.key;
}

void StopButtons::start(const input::InputState& input, bool at_start_up) {
  const auto& pad = input.operator_pad();
  const auto now = operator_.key ? pad.button(*operator_.key) : input::ButtonState{};
  if (pad.connection() != operator_.connection) operator_.held_from_reset = false;
  operator_.connection = pad.connection();
  operator_.presses = at_start_up ? now.presses : 0;
  operator_.releases = at_start_up ? now.releases : 0;
  operator_.hold_since.reset();
}

void StopButtons::forget(const input::InputState& input) {
  for (auto [pad, b] : {std::pair{&input.operator_pad(), &operator_}, std::pair{&input.supervisor(), &supervisor_}}) {
    const auto now = b->key ? pad->button(*b->key) : input::ButtonState{};
    *b = Button{b->key, pad->connection(), now.presses, now.releases, std::nullopt, false};
  }
}

bool StopButtons::take(const input::PadState& pad, Button& b) {
  b.hold_since.reset();
  if (!b.key || !pad.connected()) return false;
  // Presses are counted per controller session: a new one counts from its connect.
  if (pad.connection() != b.connection) b = Button{b.key, pad.connection(), 0, 0, std::nullopt, false};
  const auto now = pad.button(*b.key);
  // Held on from the reset that ended the last stop: not a stop until let go.
  if (!now.down || now.releases > b.releases) b.held_from_reset = false;
  const bool stop = (now.down && !b.held_from_reset) || now.presses > b.presses;
  b.presses = now.presses;
  b.releases = now.releases;
  return stop;
}

StopPresses StopButtons::take(const input::InputState& input) {
  // Both are taken: neither press may wait for a later read.
  const bool by_operator = take(input.operator_pad(), operator_);
  const bool by_supervisor = take(input.supervisor(), supervisor_);
  return {by_operator, by_supervisor};
}

bool StopButtons::tick(const input::PadState& pad, Button& b, bool deadman_touched, std::int64_t now_ms,
                       bool& pressed) const {
  pressed = false;
  if (!b.key || !pad.connected()) {
    b.hold_since.reset();
    return false;
  }
  if (pad.connection() != b.connection) b = Button{b.key, pad.connection(), 0, 0, std::nullopt, false};
  const auto now = pad.button(*b.key);
  pressed = now.presses > b.presses;
  const bool let_go = now.releases > b.releases || !now.down;
  b.presses = now.presses;
  b.releases = now.releases;
  // Let go (even between two ticks), or the deadman touched: no hold goes on.
  if (let_go || deadman_touched) b.hold_since.reset();
  // Pressed since the last tick (so released after the stop) and held, the deadman released: a hold begins.
  if (pressed && now.down && !deadman_touched) b.hold_since = now_ms;
  if (!b.hold_since || now_ms - *b.hold_since < hold_ms_) return false;
  b.hold_since.reset();
  b.held_from_reset = true;
  return true;
}

StoppedTick StopButtons::stopped(const input::InputState& input, bool deadman_touched, std::int64_t now_ms) {
  StoppedTick out;
  // The operator's deadman is on the operator's pad; the supervisor's reset needs it released too.
  if (tick(input.operator_pad(), operator_, deadman_touched, now_ms, out.pressed.by_operator)) {
    out.reset = input::Pad::kOperator;
  }
  if (tick(input.supervisor(), supervisor_, deadman_touched, now_ms, out.pressed.by_supervisor)) {
    out.reset = input::Pad::kSupervisor;  // the supervisor's, when both complete at once
  }
  return out;
}

void StopButtons::held(const input::InputState& input, EngineStatus& status) const {
  status.supervisor_stop = supervisor_.key && input.supervisor().button(*supervisor_.key).down;
  status.stop_held =
      status.supervisor_stop || (operator_.key && input.connected() && input.button(*operator_.key).down);
}

}  // namespace andros::mapping
