#pragma once
// The engine `run` drives, made from the settings: at start and again on
// `systemctl reload` (SIGHUP, docs/running.md), which swaps it between
// neutral frames.

#include <memory>
#include <string>

#include "andros/cli/settings.hpp"
#include "andros/mapping/feedback.hpp"
#include "andros/run/bridge.hpp"
#include "andros/run/engine_frames.hpp"

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

using run::ReloadableFrames;

/// A reload changes the mapping (robot, mapping) and weapons. The port, baud,
/// code, rate and input are the link's and the clock's: changing them needs a
/// restart. Returns what changed among those ("" for nothing), for the refusal.
std::string needs_restart(const Settings& running, const Settings& fresh);

}  // namespace andros::cli
