#include "andros/input/gesture.hpp"

#include <cstdlib>
#include <utility>

namespace andros::input {

std::optional<Gesture> GestureDetector::feed(const InputEvent& e) {
  using T = InputEvent::Type;
  if (e.type == T::kConnect || e.type == T::kDisconnect) {
    connect_t_ = e.type == T::kConnect ? e.t_ms : -1;
    buttons_.clear();
    hats_.clear();
    axes_.clear();
    return std::nullopt;
  }
  const bool initial = e.t_ms == connect_t_;
  if (e.type == T::kButton) {
    const bool was_down = std::exchange(buttons_[e.key], e.value != 0);
    if (e.value != 0 && !was_down && !initial) return Gesture{e.key, false};
    return std::nullopt;
  }
  if (e.type == T::kHat) {
    const int hat = e.key.index / 4;
    const int pressed = e.value & ~std::exchange(hats_[hat], e.value);
    if (initial || pressed == 0) return std::nullopt;
    for (int dir = 0; dir < 4; ++dir) {
      if ((pressed & (1 << dir)) != 0) {
        return Gesture{InputKey{InputKind::kHat, static_cast<std::uint16_t>(hat * 4 + dir)}, false};
      }
    }
    return std::nullopt;
  }
  if (e.type != T::kAxis) return std::nullopt;
  auto& axis = axes_[e.key];
  axis.value = e.value;
  const int magnitude = std::abs(e.value);
  if (initial) {
    axis.ready = magnitude <= kGestureRest;
    return std::nullopt;
  }
  if (magnitude <= kGestureRest) {
    const int peak = std::exchange(axis.peak, 0);
    axis.ready = true;
    if (peak == 0) return std::nullopt;
    reset();  // one push, one gesture: a diagonal's other axis does not follow
    return Gesture{e.key, peak < 0};
  }
  if (axis.ready && magnitude >= kGesturePushed && magnitude > std::abs(axis.peak)) axis.peak = e.value;
  return std::nullopt;
}

void GestureDetector::reset() {
  for (auto& [key, axis] : axes_) {
    axis.peak = 0;
    axis.ready = std::abs(axis.value) <= kGestureRest;
  }
}

}  // namespace andros::input
