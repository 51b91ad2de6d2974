#pragma once
// `systemctl reload` (SIGHUP) for `run`: the frame source whose settings a
// reload swaps, and which settings a reload may change at all.

#include <memory>
#include <string>

#include "andros/config.hpp"
#include "andros/io/bridge.hpp"

namespace andros::cli {

/// The run loop's frame source, whose engine a reload replaces. Everything
/// is called on the loop's thread.
class ReloadableFrames final : public io::FrameSource {
 public:
  explicit ReloadableFrames(std::unique_ptr<io::FrameSource> inner) : inner_(std::move(inner)) {}
  void replace(std::unique_ptr<io::FrameSource> inner) { inner_ = std::move(inner); }

  DataBytes step(const InputState& input, std::int64_t now_ms) override { return inner_->step(input, now_ms); }
  [[nodiscard]] DataBytes neutral() const override { return inner_->neutral(); }
  [[nodiscard]] std::string enable_text() const override { return inner_->enable_text(); }
  [[nodiscard]] bool enabled() const override { return inner_->enabled(); }
  [[nodiscard]] std::string layer() const override { return inner_->layer(); }
  void restart() override { inner_->restart(); }

 private:
  std::unique_ptr<io::FrameSource> inner_;
};

/// A reload changes the mapping (robot, mapping) and weapons. The port, baud,
/// code, rate and input are the link's and the clock's: changing them needs a
/// restart. Returns what changed among those ("" for nothing), for the refusal.
std::string needs_restart(const RunConfig& running, const RunConfig& fresh);

}  // namespace andros::cli
