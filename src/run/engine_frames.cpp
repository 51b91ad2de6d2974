#include "andros/run/engine_frames.hpp"

#include "andros/mapping/engine.hpp"

namespace andros::run {
namespace {

class EngineFrames final : public FrameSource {
 public:
  explicit EngineFrames(mapping::Engine engine) : engine_(std::move(engine)) {}

  protocol::DataBytes step(const input::InputState& input, std::int64_t now_ms) override { return engine_.step(input, now_ms); }
  [[nodiscard]] protocol::DataBytes neutral() const override { return engine_.neutral(); }
  /// While enabled, the inputs the rest rule still holds back ("enabled; at rest
  /// first: lefty"), so that a stick pushed through the deadman press explains itself.
  [[nodiscard]] std::string enable_text() const override {
    const auto& status = engine_.status();
    std::string text(describe(status.enable));
    if (status.enable != mapping::EnableState::kEnabled || status.held_back.empty()) return text;
    text += "; at rest first:";
    for (const auto key : status.held_back) text += " " + input::input_name(key);
    return text;
  }
  [[nodiscard]] bool enabled() const override { return engine_.status().enable == mapping::EnableState::kEnabled; }
  [[nodiscard]] std::string layer() const override { return engine_.status().layer; }
  void restart() override { engine_.restart(); }

 private:
  mapping::Engine engine_;
};

}  // namespace

std::unique_ptr<FrameSource> make_engine_frames(mapping::Engine engine) {
  return std::make_unique<EngineFrames>(std::move(engine));
}

}  // namespace andros::run
