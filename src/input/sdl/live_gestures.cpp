#include "andros/input/live_gestures.hpp"

namespace andros::input {

LiveGestures::LiveGestures(const SdlInputOptions& options) : input_(options) {}

std::optional<Gesture> LiveGestures::poll() {
  std::optional<Gesture> first;
  // Each read its own stamp: events of a later read are never taken for the
  // state at connect, however soon it follows.
  for (const auto& event : input_.poll(++reads_)) {
    state_.apply(event);
    const auto gesture = detector_.feed(event);
    if (!first) first = gesture;
  }
  return first;
}

}  // namespace andros::input
