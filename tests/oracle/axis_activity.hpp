#pragma once
// The enable timeout's noise band as the fault simulation's oracle
// (script_reading.hpp) reads it, from docs/mapping.md ("Enable timeout"): an
// axis has changed once it "moved more than 1024 of its ±32768 from where it
// was at the last change, so that a pad's noise does not count and a hand
// does". The loop reads the pad at its ticks, so "where it was" is taken both
// ways and either counts: from the last event that was a change, and from the
// last tick that saw one (a move made and undone between two ticks is a change
// to the first way only; the oracle is permissive: a timeout it asks for is
// one both readings owe).

#include <cstdlib>
#include <map>

#include "andros/input/events.hpp"

namespace andros::test {

/// docs/mapping.md: a move of more than this (of -32768..32767) is a change; noise within it is not.
inline constexpr int kNoiseBand = 1024;

// [rule: timeout-band]
class AxisActivity {
 public:
  /// An event set key to value: whether that is a change (beyond the band from the last one).
  bool moved(input::InputKey key, int value) { return beyond(by_event_, key, value); }

  /// A pad connected or lost: every axis back at rest (0), by the events' reckoning.
  void at_rest() {
    for (auto& [key, from] : by_event_) {
      if (std::abs(from) > kNoiseBand) from = 0;
    }
  }

  /// At a tick, the axes as they are (one not there is at rest): whether any
  /// moved beyond the band since the last tick that saw a change.
  bool seen_at_tick(const std::map<input::InputKey, int>& axes) {
    bool changed = false;
    for (const auto& [key, value] : axes) changed = beyond(by_tick_, key, value) || changed;
    for (auto& [key, from] : by_tick_) {
      if (!axes.contains(key) && std::abs(from) > kNoiseBand) {
        from = 0;
        changed = true;
      }
    }
    return changed;
  }

 private:
  // An axis never moved is at rest (0).
  static bool beyond(std::map<input::InputKey, int>& from, input::InputKey key, int value) {
    const auto it = from.try_emplace(key, 0).first;
    if (std::abs(value - it->second) <= kNoiseBand) return false;
    it->second = value;
    return true;
  }

  std::map<input::InputKey, int> by_event_;
  std::map<input::InputKey, int> by_tick_;
};

}  // namespace andros::test
