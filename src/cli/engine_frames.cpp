#include "engine_frames.hpp"

#include "andros/engine.hpp"
#include "andros/mapping_loader.hpp"

namespace andros::cli {
namespace {

class EngineFrames final : public io::FrameSource {
 public:
  explicit EngineFrames(Engine engine) : engine_(std::move(engine)) {}

  DataBytes step(const InputState& input, std::int64_t now_ms) override { return engine_.step(input, now_ms); }
  [[nodiscard]] DataBytes neutral() const override { return engine_.neutral(); }
  /// While enabled, the inputs the rest rule still holds back ("enabled; at rest
  /// first: lefty"), so that a stick pushed through the deadman press explains itself.
  [[nodiscard]] std::string enable_text() const override {
    const auto& status = engine_.status();
    std::string text(describe(status.enable));
    if (status.enable != EnableState::kEnabled || status.held_back.empty()) return text;
    text += "; at rest first:";
    for (const auto key : status.held_back) text += " " + input_name(key);
    return text;
  }
  [[nodiscard]] bool enabled() const override { return engine_.status().enable == EnableState::kEnabled; }
  [[nodiscard]] std::string layer() const override { return engine_.status().layer; }
  void restart() override { engine_.restart(); }

 private:
  Engine engine_;
};

}  // namespace

std::unique_ptr<io::FrameSource> make_engine_frames(const RunConfig& config) {
  Mapping mapping = config.mapping.empty() ? load_robot_mapping(config.robot) : load_mapping(config.mapping);
  return std::make_unique<EngineFrames>(
      Engine(std::move(mapping), EngineOptions{.weapons = config.weapons, .code = config.code}));
}

std::string mapping_file(const RunConfig& config) {
  return config.mapping.empty() ? find_robot_mapping(config.robot, mapping_search_path()).string() : config.mapping;
}

}  // namespace andros::cli
