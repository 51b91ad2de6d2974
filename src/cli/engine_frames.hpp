#pragma once
// The mapping engine as the run loop's frame source.

#include <memory>
#include <string>

#include "andros/config.hpp"
#include "andros/io/bridge.hpp"

namespace andros::cli {

/// Loads the mapping the config names (a file, or the robot's shipped one)
/// and wraps an engine for it. Throws InputError for a bad mapping.
std::unique_ptr<io::FrameSource> make_engine_frames(const RunConfig& config);

/// The mapping file the config names, for the log: the file given, or the
/// robot's on the search path.
std::string mapping_file(const RunConfig& config);

}  // namespace andros::cli
