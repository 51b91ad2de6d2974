#pragma once
/// The live controller read for deliberate inputs (`andros-bridge learn`):
/// an SdlInput whose events go through a GestureDetector. Single-threaded,
/// like SdlInput.

#include <optional>
#include <string>

#include "andros/input/gesture.hpp"
#include "andros/input/sdl_input.hpp"

namespace andros::input {

class LiveGestures {
 public:
  /// Starts SDL as SdlInput does (InputError for a bad selection or mapping
  /// file, RuntimeError when SDL cannot start).
  explicit LiveGestures(const SdlInputOptions& options);

  /// Reads what the controller did since the last call, without blocking,
  /// and returns the first gesture in it. A gesture that completes in the
  /// same read as another is dropped: one deliberate input at a time.
  std::optional<Gesture> poll();

  /// From now on only pushes that start from rest count (call before each prompt).
  void reset() { detector_.reset(); }

  [[nodiscard]] bool connected() const { return state_.connected(); }
  /// Counts connects: a new value means the controller (re)appeared.
  [[nodiscard]] std::uint32_t connection() const { return state_.connection(); }
  [[nodiscard]] const std::string& name() const { return state_.name(); }
  /// "the first controller", "controller named 'xbox'"...
  [[nodiscard]] std::string selection() const { return input_.selection(); }

 private:
  SdlInput input_;
  GestureDetector detector_;
  InputState state_;
  std::int64_t reads_ = 0;
};

}  // namespace andros::input
