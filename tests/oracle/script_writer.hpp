#pragma once
// What the fault simulation's generator (fault_script.hpp) writes a script
// with: the events so far, the time, what the script last set (the operator's
// controller there, the deadman held, a supervisor's controller in the
// script), and how time moves on between events.

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "andros/input/events.hpp"

namespace andros::test {

template <typename Choices>
struct ScriptWriter {
  using T = input::InputEvent::Type;

  ScriptWriter(Choices& choices, input::InputKey deadman_key) : pick(choices), deadman(deadman_key) {}

  Choices& pick;
  input::InputKey deadman;  ///< the operator's deadman button (LB)
  std::vector<input::InputEvent> events;
  std::int64_t t = 0;
  bool connected = true;
  bool held = false;        ///< the deadman, as the script last set it
  bool supervised = false;  ///< a supervisor's controller in this script

  void add(T type, input::InputKey key = {}, int value = 0, std::string name = {}) {
    input::InputEvent e;
    e.t_ms = t;
    e.type = type;
    e.key = key;
    e.value = value;
    e.name = std::move(name);
    events.push_back(std::move(e));
    if (type == T::kButton && key == deadman) held = value != 0;
    if (type == T::kConnect || type == T::kDisconnect) {
      connected = type == T::kConnect;
      held = false;
    }
  }
  /// An event on the supervisor's controller.
  void supervisor(T type, input::InputKey key = {}, int value = 0, std::string name = {}) {
    add(type, key, value, std::move(name));
    events.back().pad = input::Pad::kSupervisor;
  }
  // Time moves on: often not at all (events at one instant), to a frame's
  // time exactly, just past it, within a frame, or a long while.
  void wait() {
    switch (pick.below(10)) {
      case 0:
      case 1:
      case 2: break;
      case 3: t = (t / 40 + 1) * 40; break;
      case 4: t += 1; break;
      case 9: t += 100 + pick.below(700); break;
      default: t += pick.below(60); break;
    }
  }
  // A second event of a pair (link down/up, suspend/resume): within the same
  // frame, within a stop's or suspend's neutral frames, or later.
  void pair_gap() {
    switch (pick.below(4)) {
      case 0: t += pick.below(40); break;
      case 1: t += 40 + pick.below(100); break;
      default: t += 150 + pick.below(800); break;
    }
  }
  /// Just after the next frame's time, within `within` ms of it.
  void next_tick(int within) { t = (t / 40 + 1) * 40 + 1 + pick.below(static_cast<std::uint32_t>(within)); }
};

}  // namespace andros::test
