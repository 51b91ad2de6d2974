#pragma once
// The engine `run` drives, made from the settings: at start and again on
// `systemctl reload` (SIGHUP, docs/running.md), which swaps it between
// neutral frames.

#include <memory>
#include <string>

#include "andros/cli/settings.hpp"
#include "andros/mapping/feedback.hpp"
#include "andros/run/bridge.hpp"

namespace andros::cli {

/// What the settings' mapping gives the run: the frame source and what the
/// view and the rumble need from the mapping.
struct EngineSetup {
  std::unique_ptr<run::FrameSource> frames;
  std::string robot;         ///< its robot type (the settings' when the mapping names none)
  std::string mapping_file;  ///< the file loaded
  int center = 128;          ///< drive and pivot's rest value (for the gauges)
  mapping::FeedbackTable feedback;
};

/// Loads the mapping the settings name and builds its engine. Throws
/// InputError for a bad mapping.
EngineSetup load_engine(const Settings& settings);

/// The run loop's frame source, whose engine a reload replaces. Everything
/// is called on the loop's thread.
class ReloadableFrames final : public run::FrameSource {
 public:
  explicit ReloadableFrames(std::unique_ptr<run::FrameSource> inner) : inner_(std::move(inner)) {}
  void replace(std::unique_ptr<run::FrameSource> inner) { inner_ = std::move(inner); }

  run::Step step(const input::InputState& input, std::int64_t now_ms) override { return inner_->step(input, now_ms); }
  [[nodiscard]] protocol::DataBytes neutral() const override { return inner_->neutral(); }
  void restart() override { inner_->restart(); }

 private:
  std::unique_ptr<run::FrameSource> inner_;
};

/// A reload changes the mapping (robot, mapping) and weapons. The port, baud,
/// code, rate and input are the link's and the clock's: changing them needs a
/// restart. Returns what changed among those ("" for nothing), for the refusal.
std::string needs_restart(const Settings& running, const Settings& fresh);

}  // namespace andros::cli
