#pragma once
// The mapping engine as the run loop's frame source, and a frame source a
// reload swaps.

#include <memory>

#include "andros/mapping/engine.hpp"
#include "andros/run/bridge.hpp"

namespace andros::run {

/// The engine as a frame source for the run loop.
std::unique_ptr<FrameSource> make_engine_frames(mapping::Engine engine);

/// The run loop's frame source, whose engine a reload replaces. Everything
/// is called on the loop's thread. (Not final: the tests wrap an engine in it
/// to inject faults, tests/support/faulty_frames.hpp.)
class ReloadableFrames : public FrameSource {
 public:
  explicit ReloadableFrames(std::unique_ptr<FrameSource> inner) : inner_(std::move(inner)) {}
  void replace(std::unique_ptr<FrameSource> inner) { inner_ = std::move(inner); }

  [[nodiscard]] const mapping::Mapping& mapping() const override { return inner_->mapping(); }
  Step step(const input::InputState& input, std::int64_t now_ms, bool motion_allowed) override {
    return inner_->step(input, now_ms, motion_allowed);
  }
  [[nodiscard]] protocol::DataBytes neutral() const override { return inner_->neutral(); }
  void rebase(const input::InputState& now) override { inner_->rebase(now); }

 private:
  std::unique_ptr<FrameSource> inner_;
};

}  // namespace andros::run
