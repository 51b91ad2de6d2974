#include "andros/input/script_player.hpp"

namespace andros::input {

ScriptPlayer::ScriptPlayer(TextReader& text)
    : reader_(text), supervised_(text.can_rewind() && text.line_number() == 0 && addresses_supervisor(text)) {}

void ScriptPlayer::advance_to(std::int64_t t_ms, TickInput& input) {
  while (!exhausted_) {
    if (!pending_) {
      pending_ = reader_.next();
      if (!pending_) {
        exhausted_ = true;
        break;
      }
      last_t_ = pending_->t_ms;
      if (pending_->type == InputEvent::Type::kEnd) {
        exhausted_ = true;  // nothing may follow an end
        pending_.reset();
        break;
      }
    }
    if (pending_->t_ms > t_ms) break;
    input.apply(*pending_);
    pending_.reset();
  }
}

bool ScriptPlayer::finished_at(std::int64_t t_ms) const { return exhausted_ && t_ms >= last_t_; }

}  // namespace andros::input
