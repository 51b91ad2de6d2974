#pragma once
// The deadman between two ticks, as the fault simulation's oracle
// (safety_oracle.hpp) reads it: every change between two ticks counts. A
// deadman every possible mapping has, held at the last tick and let go since
// (even if pressed again since), makes this tick's frame neutral (and a press
// after it is fresh, which the oracle reads apart). A reset hold needs the
// deadman of the mapping in force released: not held now, not pressed since
// the last tick, and (a trigger, whose travel the loop reads since the tick
// began) not held at the last tick. And any deadman let go since the last
// tick (held at it or not: the loop counts a button's releases) may put off
// enabling to the next tick, from which the enable timeout then runs.

#include <cstdint>
#include <set>
#include <utility>

#include "andros/input/events.hpp"
#include "andros/mapping/model.hpp"

namespace andros::test {

// [rule: between-ticks]
class DeadmanTicks {
 public:
  /// A new session of the operator's pad: what the old one did is gone.
  void new_session() {
    // Nor is a trigger held at the last tick still held: the loop reads the new session's travel from its connect.
    pressed_ = let_go_since_ = released_since_ = was_down_ = false;
    down_at_tick_.clear();
  }

  /// A deadman (of any possible mapping) crossed its press point at an
  /// event the loop sees (not stamped with the connect's time).
  void moved(input::InputKey key, bool now, const mapping::Mapping& in_force,
             const std::set<input::InputKey>& common_deadmen) {
    if (now && in_force.deadman && key == in_force.deadman->key) pressed_ = true;
    if (!now && common_deadmen.contains(key) && down_at_tick_.contains(key)) let_go_since_ = true;
    if (!now) released_since_ = true;
  }

  /// The deadman of the mapping in force touched since the last tick: held now (down_now), pressed since, or a
  /// trigger held at the last tick.
  [[nodiscard]] bool touched(const mapping::Mapping& in_force, bool down_now) const {
    if (!in_force.deadman) return false;
    return down_now || pressed_ || (!in_force.deadman->key.is_button() && was_down_);
  }

  /// At the end of a tick's stop reading: down_now, the mapping in force's
  /// deadman held; held, the common deadmen held now.
  void at_tick(bool down_now, std::set<input::InputKey> held) {
    pressed_ = false;
    was_down_ = down_now;
    down_at_tick_ = std::move(held);
    let_go_this_tick_ = std::exchange(let_go_since_, false);
    maybe_let_go_this_tick_ = std::exchange(released_since_, false);
  }

  /// A deadman let go since the last tick: this tick's frame is neutral.
  [[nodiscard]] bool let_go_this_tick() const { return let_go_this_tick_; }
  /// Any deadman let go since the last tick: the loop may enable only at the next one.
  [[nodiscard]] bool maybe_let_go_this_tick() const { return maybe_let_go_this_tick_; }

 private:
  bool pressed_ = false;                    ///< the mapping in force's deadman, since the last tick
  bool was_down_ = false;                   ///< and held at the last tick
  std::set<input::InputKey> down_at_tick_;  ///< the common deadmen held at the last tick
  bool let_go_since_ = false;               ///< a common deadman let go since the last tick
  bool let_go_this_tick_ = false;           ///< and so at this tick
  bool released_since_ = false;             ///< any deadman let go since the last tick
  bool maybe_let_go_this_tick_ = false;     ///< and so at this tick
};

}  // namespace andros::test
