#pragma once
/// `run --input FILE`: an event script played in real time through the same
/// path as a live controller. The whole script is checked when it is opened,
/// so that a bad line stops the run before the first frame, not mid-drive.

#include <memory>
#include <sstream>
#include <string>

#include "andros/input_source.hpp"
#include "andros/script_player.hpp"

namespace andros::io {

class ScriptInput final : public InputSource {
 public:
  /// Reads and checks the script; throws InputError at FILE:LINE:COL.
  explicit ScriptInput(const std::string& path);

  void pump(InputState& state, std::int64_t now_ms) override { player_->advance_to(now_ms, state); }
  [[nodiscard]] bool finished(std::int64_t now_ms) const override { return player_->finished_at(now_ms); }

 private:
  std::istringstream text_;
  std::unique_ptr<ScriptPlayer> player_;
};

}  // namespace andros::io
