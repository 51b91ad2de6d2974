#include "andros/run/replay.hpp"

#include <optional>

#include "andros/link/fault_link.hpp"
#include "andros/run/loop.hpp"

namespace andros::run {
namespace {

/// The script as the loop's input.
class PlayerInput final : public input::InputSource {
 public:
  explicit PlayerInput(input::ScriptPlayer& player) : player_(player) {}
  void pump(input::TickInput& input, std::int64_t now_ms) override { player_.advance_to(now_ms, input); }
  [[nodiscard]] bool finished(std::int64_t now_ms) const override { return player_.finished_at(now_ms); }
  [[nodiscard]] bool supervised() const override { return player_.supervised(); }

 private:
  input::ScriptPlayer& player_;
};

}  // namespace

std::int64_t replay(input::ScriptPlayer& player, mapping::Engine engine, const ReplayOptions& options,
                    const FrameSink& sink) {
  VirtualClock clock;
  PlayerInput input(player);
  std::string mapping_file = engine.mapping().file;
  const std::unique_ptr<FrameSource> frames = options.frames(std::make_unique<mapping::Engine>(std::move(engine)));
  link::SinkLink sink_link(
      [&options](std::int64_t now_ns, const protocol::Frame& frame) { options.wire(now_ns / kNsPerMs, frame); });
  LoopParts loop{.clock = clock,
                 .input = input,
                 .frames = *frames,
                 .link = options.link != nullptr ? *options.link : sink_link,
                 .options = {.rate_millihertz = options.rate_millihertz,
                             .neutral_tail_at_end = false,
                             .rules = {options.engine.weapons, options.engine.code}},
                 .control = {},
                 .observers = {}};

  // A reload is read at once (the clock waits for it) and applied after its neutral frames.
  std::optional<mapping::ValidMapping> loaded;
  std::string loaded_file;
  std::optional<ReloadOutcome> outcome;
  loop.control.begin_reload = [&](const std::string& file) {
    const std::string wanted = file.empty() ? mapping_file : file;
    try {
      loaded = options.load(wanted);
      loaded_file = wanted;
      outcome = ReloadOutcome{true, "", options.engine.weapons};
    } catch (const std::exception& e) {
      // Whatever the reading met (a bad file, one that cannot be read): the
      // old mapping stays and the replay goes on, as `run` does.
      outcome = ReloadOutcome{false, e.what()};
    }
  };
  loop.control.finish_reload = [&] {
    if (outcome && outcome->ok) {
      outcome->frames = options.frames(std::make_unique<mapping::Engine>(std::move(*loaded), options.engine));
      mapping_file = loaded_file;
      loaded.reset();
    }
    if (outcome) options.reloaded(clock.now().count() / kNsPerMs, *outcome);
    return std::exchange(outcome, std::nullopt);
  };

  std::int64_t delivered = 0;
  loop.observers = {options.observe, [&](const TickReport& r) {
                      if (r.delivered()) {
                        sink(r.t_ms, r.data);
                        ++delivered;
                      }
                    }};
  run_loop(loop);
  return delivered;
}

}  // namespace andros::run
