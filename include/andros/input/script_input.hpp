#pragma once
/// `run --input FILE`: an event script played in real time through the same
/// path as a live controller. The whole script is read into memory and
/// checked when it is opened, so that a bad line stops the run before the
/// first frame, not mid-drive, and a file changed during the run changes nothing.

#include <memory>
#include <string>

#include "andros/base/text_file.hpp"
#include "andros/input/input_source.hpp"
#include "andros/input/script_player.hpp"

namespace andros::input {

class ScriptInput final : public InputSource {
 public:
  /// Reads and checks the script; throws InputError at FILE:LINE:COL, or
  /// ReadStopped when stop says so while it waits for input (a FIFO, a pipe).
  explicit ScriptInput(const std::string& path, const StopCheck& stop = {});
  ScriptInput(const ScriptInput&) = delete;  // the player holds on to text_
  ScriptInput& operator=(const ScriptInput&) = delete;

  void pump(TickInput& input, std::int64_t now_ms) override { player_->advance_to(now_ms, input); }
  [[nodiscard]] bool finished(std::int64_t now_ms) const override { return player_->finished_at(now_ms); }
  [[nodiscard]] bool supervised() const override { return player_->supervised(); }

 private:
  TextReader text_;
  std::unique_ptr<ScriptPlayer> player_;
};

}  // namespace andros::input
