#include "andros/run/replay.hpp"

namespace andros::run {

std::int64_t replay(input::ScriptPlayer& player, mapping::Engine& engine, const timing::FrameClock& clock, const FrameSink& sink) {
  input::InputState input;
  for (std::int64_t k = 0;; ++k) {
    const auto t = clock.time_of(k);
    player.advance_to(t, input);
    sink(t, engine.step(input, t));
    if (player.finished_at(t)) return k + 1;
  }
}

}  // namespace andros::run
