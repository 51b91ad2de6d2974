#include "andros/view/inputs_view.hpp"

namespace andros::view {

std::vector<std::string> InputsBoard::update(const std::vector<input::InputEvent>& events,
                                             std::optional<input::DeviceLayout> layout) {
  std::vector<std::string> lines;
  lines.reserve(events.size());
  const std::lock_guard lock(mutex_);
  layout_ = std::move(layout);
  for (const auto& event : events) {
    state_.apply(event);
    lines.push_back(format_input_change(event, uses_, layout_));
  }
  return lines;
}

std::string InputsBoard::compose(TermSize size) const {
  const std::lock_guard lock(mutex_);
  return render_inputs_screen(state_, layout_, uses_, heading_, size);
}

}  // namespace andros::view
