#pragma once
/// `andros-bridge inputs`: what the controller itself reports, as a live
/// screen on a terminal and one line per change off one. Pure formatting.

#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "andros/input/device_layout.hpp"
#include "andros/input/input_state.hpp"
#include "andros/mapping/model.hpp"
#include "andros/view/screen.hpp"

namespace andros::view {

/// How a mapping reads one axis: where it counts as at rest.
struct AxisUse {
  enum class Rest : std::uint8_t { kDeadzone, kThreshold, kBand } rest = Rest::kDeadzone;  /// band: a pair, both sides
  double limit = 0.0;   ///< the deadzone (inside it: at rest), or the threshold (from it: pressed)
  bool invert = false;  ///< a threshold of an inverted axis counts on the negative side
  std::string signal;   ///< what it drives ("drive", "pt_left/pt_right", "deadman"); "" without a mapping
  std::string layer;    ///< the layer of that binding, "" for the base layer
};
using AxisUses = std::map<input::InputKey, AxisUse>;

/// Each axis the mapping reads, by the first binding that reads it (the base
/// layer's first, then each layer's in order); the deadman and arming
/// triggers count at half way. An axis it does not read is left out:
/// axis_use() gives it the mapping default, deadzone 0.
AxisUses axis_uses(const mapping::Mapping& mapping);
AxisUse axis_use(const AxisUses& uses, input::InputKey axis);

/// One change as a line (no newline): "520 button a #0 down",
/// "560 axis lefty #1 -18112 -0.553 deadzone 0.10 drive: moves",
/// "600 hat 0 up+left", "0 connect Pad (game controller, GUID ...)".
std::string format_input_change(const input::InputEvent& event, const AxisUses& uses,
                                const std::optional<input::DeviceLayout>& layout);

/// An 80x24 terminal less the column the display leaves free (the cursor never wraps).
inline constexpr TermSize kInputsSize{79, 24};

/// The live screen for a terminal of this size (the columns it may fill): every button, axis, trigger
/// and hat of the device (a pad's hats its SDL mapping leaves out too), by
/// name and number, each axis with its raw value, its value from -1 to 1,
/// a bar as wide as the screen allows, whether the mapping would act on it
/// and its deadzone. Narrow or short, it reflows (fewer button columns, no
/// blank lines) before anything is cut.
std::string render_inputs_screen(const input::InputState& state, const std::optional<input::DeviceLayout>& layout,
                                 const AxisUses& uses, const std::string& heading, TermSize size = kInputsSize);

/// The tester's state between polls: the poll loop feeds it, the display
/// thread reads the screen from it.
class InputsBoard {
 public:
  InputsBoard(AxisUses uses, std::string heading) : uses_(std::move(uses)), heading_(std::move(heading)) {}

  /// One poll's events, and the device as it is after them: the state
  /// moves on, and each event becomes a line (format_input_change).
  std::vector<std::string> update(const std::vector<input::InputEvent>& events,
                                  std::optional<input::DeviceLayout> layout);
  /// The screen now (render_inputs_screen); safe from another thread.
  [[nodiscard]] std::string compose(TermSize size = kInputsSize) const;

 private:
  mutable std::mutex mutex_;
  AxisUses uses_;
  std::string heading_;
  input::InputState state_;
  std::optional<input::DeviceLayout> layout_;
};

}  // namespace andros::view
