#include "andros/run/engine_frames.hpp"

#include "andros/mapping/engine.hpp"

namespace andros::run {
namespace {

class EngineFrames final : public FrameSource {
 public:
  explicit EngineFrames(mapping::Engine engine) : engine_(std::move(engine)) {}

  [[nodiscard]] const mapping::Mapping& mapping() const override { return engine_.mapping(); }
  Step step(const input::InputState& input, std::int64_t now_ms, bool motion_allowed) override {
    auto data = engine_.step(input, now_ms, motion_allowed);
    return Step{data, engine_.status()};
  }
  [[nodiscard]] protocol::DataBytes neutral() const override { return engine_.neutral(); }
  void rebase(const input::InputState& now) override { engine_.restart(now); }

 private:
  mapping::Engine engine_;
};

}  // namespace

std::unique_ptr<FrameSource> make_engine_frames(mapping::Engine engine) {
  return std::make_unique<EngineFrames>(std::move(engine));
}

}  // namespace andros::run
