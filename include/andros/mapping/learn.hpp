#pragma once
/// The plan of `andros-bridge learn` (docs/mapping.md, Changing buttons with
/// learn): every input of a mapping in a fixed order, the change an operator
/// makes to each, the refusal of an input already used, and the extending
/// file that holds only what changed. No controller here: the inputs come in
/// as input::Gesture values.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "andros/input/gesture.hpp"
#include "andros/mapping/model.hpp"

namespace andros::mapping {

/// What a step takes.
enum class LearnAccepts : std::uint8_t {
  kButton,           ///< a button or hat direction
  kButtonOrTrigger,  ///< the deadman, a weapon's arming input
  kButtonOrAxis,     ///< a momentary signal: a button, or an axis pushed the way that sets it
  kAxis,             ///< an opposing pair or an analog byte: an axis, pushed the way the prompt names
};

/// One input of the mapping: the deadman, a layer's key, or one input of a
/// binding (a knob, a weapon and a selector with `prev` have two).
struct LearnStep {
  enum class Role : std::uint8_t { kDeadman, kLayerKey, kBinding };
  Role role = Role::kBinding;
  int layer = -1;           ///< -1: the base layer
  std::size_t binding = 0;  ///< the binding's index in its layer's list
  int slot = 0;             ///< which of its inputs: 0 the first, 1 the second (arm, decrease, prev)
};

struct LearnResult {
  enum class Kind : std::uint8_t { kChanged, kKept, kRefused };
  Kind kind = Kind::kKept;
  std::string message;  ///< "dpup -> paddle1", "kept dpup", or why the input is refused
};

class LearnPlan {
 public:
  /// base: a loaded, validated robot mapping (load_mapping, load_robot_mapping).
  explicit LearnPlan(Mapping base);

  /// The deadman, the base layer's bindings in order, then each layer's key and bindings.
  [[nodiscard]] const std::vector<LearnStep>& steps() const { return steps_; }
  /// "[5/52] base layer, front_art_up: press a button (Enter keeps dpup)".
  [[nodiscard]] std::string prompt(std::size_t step) const;
  [[nodiscard]] LearnAccepts accepts(std::size_t step) const;
  /// The step's input now, as the prompt shows it: "dpup", "lefty up".
  [[nodiscard]] std::string current(std::size_t step) const;
  /// The index of the first step of the next layer (steps().size() after the last).
  [[nodiscard]] std::size_t next_layer(std::size_t step) const;

  /// Gives the step this input. Refused (and nothing changes) when the step
  /// does not take that kind of input, when another binding of the same
  /// layer, the deadman or a layer key already uses it, or when the mapping
  /// would no longer pass validate(); kept when it is the step's input now.
  LearnResult assign(std::size_t step, const input::Gesture& gesture);

  [[nodiscard]] bool changed() const;
  [[nodiscard]] const Mapping& base() const { return base_; }
  [[nodiscard]] const Mapping& learned() const { return learned_; }

  /// The mapping file that extends `extends` (the base's path as the file
  /// will name it) with only what changed: the deadman, layer keys and the
  /// changed bindings, each with an `unbind:` for its old input when the
  /// new binding does not replace the old one by itself.
  [[nodiscard]] std::string extending_yaml(std::string_view extends) const;
  /// The same, extending another mapping than the base: `over`, the file
  /// `extends` names (learn writing over the file it learned from extends
  /// what that file extended). Bindings are compared as sets, so over's lists
  /// need not line up with the base's.
  [[nodiscard]] std::string extending_yaml(std::string_view extends, const Mapping& over) const;

  /// True when loaded (the written file, read back) has the learned inputs:
  /// the same deadman, layer keys, and bindings in every layer.
  [[nodiscard]] bool matches(const Mapping& loaded) const;

 private:
  Mapping base_;
  Mapping learned_;
  std::vector<LearnStep> steps_;
};

/// A binding as a list item of a mapping file, every line prefixed by indent.
std::string binding_yaml(const Binding& binding, std::string_view indent);

}  // namespace andros::mapping
