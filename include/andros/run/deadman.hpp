#pragma once
/// The deadman, as facts: whether it is held, and whether the press that
/// holds it is fresh (made after the session began, after the last release,
/// a panic or a timeout). It decides nothing about the frame: the engine
/// reads its DeadmanState. Every change between two frames counts: a button
/// released and pressed again since the last read (its `releases` count), or
/// a trigger let go below its press point (its span), is a release at this
/// read, and the press after it is fresh; a trigger squeezed past
/// `deadman_panic` since the last read is a panic, even if it is back now.

#include <cstdint>
#include <optional>

#include "andros/input/input_state.hpp"
#include "andros/mapping/engine_status.hpp"
#include "andros/mapping/model.hpp"

namespace andros::run {

class Deadman {
 public:
  explicit Deadman(const mapping::Mapping& mapping);

  /// A new controller session (at_start_up: or the start, or a restart:
  /// every press so far is history).
  void start(const input::InputState& input, bool at_start_up);
  /// Once per computed step: the deadman's state, taking the releases seen.
  [[nodiscard]] mapping::DeadmanState read(const input::InputState& input);
  /// The enable timeout ran out: not enabled until released and pressed again.
  void time_out(const input::InputState& input);
  /// Held now (a controller there, the button down or the trigger past its press point).
  [[nodiscard]] bool held(const input::InputState& input) const;
  /// Stopped (no read): held now, or pressed since the last call (a
  /// trigger: squeezed to its press point since the tick began).
  [[nodiscard]] bool touched(const input::InputState& input);

  bool operator==(const Deadman&) const = default;

 private:
  /// Squeezed past the panic point: true while latched off.
  [[nodiscard]] bool panic(const input::InputState& input);
  /// Let go since the last read, though held now.
  [[nodiscard]] bool let_go_between(const input::InputState& input) const;

  std::optional<input::InputKey> key_;
  std::optional<double> panic_;
  std::uint32_t base_ = 0;             ///< presses that are not fresh
  std::uint32_t releases_seen_ = 0;    ///< a button deadman's releases already read
  std::uint32_t presses_seen_ = 0;     ///< its presses already seen (read(), touched())
  std::uint32_t connection_seen_ = 0;  ///< the controller session presses_seen_ counts in
  bool released_seen_ = false;         ///< a trigger deadman was seen released this session
  bool held_at_read_ = false;          ///< held at the last read (a trigger let go since is a release)
  bool panic_latched_ = false;         ///< squeezed past the panic point, not yet fully released
  bool timed_out_ = false;             ///< the enable timeout ran out, the deadman not yet released
};

}  // namespace andros::run
