#include "andros/run/engine_frames.hpp"

#include "andros/mapping/engine.hpp"

namespace andros::run {
namespace {

class EngineFrames final : public FrameSource {
 public:
  explicit EngineFrames(mapping::Engine engine) : engine_(std::move(engine)) {}

  mapping::InputFacts facts(const input::InputState& input, std::int64_t now_ms, bool enabled) override {
    return engine_.facts(input, now_ms, enabled);
  }
  Step step(const input::InputState& input, std::int64_t now_ms, bool motion_allowed) override {
    auto data = engine_.step(input, now_ms, motion_allowed);
    return Step{data, engine_.status()};
  }
  [[nodiscard]] protocol::DataBytes neutral() const override { return engine_.neutral(); }
  void restart(const input::InputState& now) override { engine_.restart(now); }
  mapping::StopPresses take_stop(const input::InputState& input) override { return engine_.take_stop(input); }
  mapping::StoppedTick stopped(const input::InputState& input, std::int64_t now_ms) override {
    return engine_.stopped(input, now_ms);
  }
  void held_stops(const input::InputState& input, mapping::EngineStatus& status) const override {
    engine_.held_stops(input, status);
  }

 private:
  mapping::Engine engine_;
};

}  // namespace

std::unique_ptr<FrameSource> make_engine_frames(mapping::Engine engine) {
  return std::make_unique<EngineFrames>(std::move(engine));
}

}  // namespace andros::run
