#include "andros/input/input_state.hpp"

#include <algorithm>

#include "andros/base/text.hpp"

namespace andros::input {
namespace {

std::optional<int> parse_index(std::string_view text) {
  const auto value = to_integer(text);
  if (!value || *value < 0 || *value > kMaxJoystickIndex) return std::nullopt;
  return static_cast<int>(*value);
}

template <std::size_t N>
std::optional<std::uint16_t> find_name(const std::array<std::string_view, N>& names, std::string_view name) {
  for (std::size_t i = 0; i < N; ++i) {
    if (names[i] == name) return static_cast<std::uint16_t>(i);
  }
  return std::nullopt;
}

}  // namespace

std::optional<InputKey> parse_button_name(std::string_view name) {
  if (auto i = find_name(kPadButtonNames, name)) return InputKey{InputKind::kPadButton, *i};
  if (name.starts_with("hat")) {
    const auto rest = name.substr(3);
    const auto digits = rest.find_first_not_of("0123456789");
    if (digits == 0 || digits == std::string_view::npos) return std::nullopt;
    const auto hat = parse_index(rest.substr(0, digits));
    const auto dir = find_name(kHatDirectionNames, rest.substr(digits));
    if (!hat || !dir || *hat > kMaxHatIndex) return std::nullopt;
    return InputKey{InputKind::kHat, static_cast<std::uint16_t>(*hat * 4 + *dir)};
  }
  if (auto n = parse_index(name)) return InputKey{InputKind::kJoyButton, static_cast<std::uint16_t>(*n)};
  return std::nullopt;
}

std::optional<InputKey> parse_axis_name(std::string_view name) {
  if (auto i = find_name(kPadAxisNames, name)) return InputKey{InputKind::kPadAxis, *i};
  if (auto n = parse_index(name)) return InputKey{InputKind::kJoyAxis, static_cast<std::uint16_t>(*n)};
  return std::nullopt;
}

std::string input_name(InputKey key) {
  switch (key.kind) {
    case InputKind::kPadButton: return std::string(kPadButtonNames.at(key.index));
    case InputKind::kPadAxis: return std::string(kPadAxisNames.at(key.index));
    case InputKind::kJoyButton:
    case InputKind::kJoyAxis: return std::to_string(key.index);
    case InputKind::kHat:
      return "hat" + std::to_string(key.index / 4) + std::string(kHatDirectionNames.at(key.index % 4));
  }
  return "?";
}

void PadState::set_button(InputKey key, bool down, bool initial) {
  auto& b = buttons_[key];
  if (down && !b.down && !initial) ++b.presses;
  if (!down && b.down && !initial) ++b.releases;
  b.down = down;
}

void InputState::apply(const InputEvent& event) {
  (event.pad == Pad::kSupervisor ? supervisor_pad_ : operator_pad_).apply(event);
}

void TickInput::apply(const InputEvent& event) {
  if (keep_applied_) applied_.push_back(event);
  if (event.is_fault()) {
    faults_.push_back(event);
    return;
  }
  state_.apply(event);
}

void PadState::apply(const InputEvent& event) {
  using T = InputEvent::Type;
  if (event.type == T::kConnect) {
    // A new session: nothing carries over from the last one.
    connected_ = true;
    ++connection_;
    connect_t_ = event.t_ms;
    name_ = event.name;
    identity_ = PadIdentity{event.name, {}, {}, {}};
    // A script's or a recorder's identity fields that do not read leave the name alone.
    if (!parse_pad_fields(event.device, identity_)) identity_ = PadIdentity{event.name, {}, {}, {}};
    buttons_.clear();
    axes_.clear();
    spans_.clear();
    return;
  }
  if (event.type == T::kDisconnect) {
    connected_ = false;
    name_.clear();
    identity_ = {};
    buttons_.clear();
    axes_.clear();
    spans_.clear();
    return;
  }
  if (!connected_) return;  // a lost controller's stale events move nothing
  const bool initial = event.t_ms == connect_t_;
  switch (event.type) {
    case T::kButton: set_button(event.key, event.value != 0, initial); break;
    case T::kAxis: {
      const auto value = static_cast<std::int16_t>(event.value);
      const auto was = axis(event.key);
      axes_[event.key] = value;
      // The state the controller had when it appeared spans its value alone.
      if (initial) {
        spans_.erase(event.key);
        break;
      }
      auto& span = spans_.try_emplace(event.key, AxisSpan{was, was}).first->second;
      span = {std::min(span.low, value), std::max(span.high, value)};
      break;
    }
    case T::kHat:
      for (std::uint16_t dir = 0; dir < 4; ++dir) {
        set_button(InputKey{InputKind::kHat, static_cast<std::uint16_t>(event.key.index + dir)},
                   (event.value >> dir & 1) != 0, initial);
      }
      break;
    default: break;
  }
}

ButtonState PadState::button(InputKey key) const {
  const auto it = buttons_.find(key);
  return it == buttons_.end() ? ButtonState{} : it->second;
}

std::int16_t PadState::axis(InputKey key) const {
  const auto it = axes_.find(key);
  return it == axes_.end() ? std::int16_t{0} : it->second;
}

AxisSpan PadState::axis_span(InputKey key) const {
  const auto it = spans_.find(key);
  if (it != spans_.end()) return it->second;
  const auto now = axis(key);
  return {now, now};
}

int PadState::hat(int hat_index) const {
  int mask = 0;
  for (int dir = 0; dir < 4; ++dir) {
    if (button(InputKey{InputKind::kHat, static_cast<std::uint16_t>(hat_index * 4 + dir)}).down) {
      mask |= 1 << dir;
    }
  }
  return mask;
}

}  // namespace andros::input
