#pragma once
// A mapping file's own keys (docs/mapping.md, File layout): all but
// `extends`, `bindings` and `layers`, which the loader reads itself.

#include "andros/base/error_list.hpp"
#include "andros/mapping/model.hpp"
#include "yaml_reader.hpp"

namespace andros::mapping {

/// Reads robot, center, constants, deadman, deadman_panic, estop,
/// stop_reset_hold, enable_timeout, supervisor, brake, scale and feedback
/// from root into m, over what the extended file set. Each key on its own: an
/// error in one is added to errors and the others are still read.
void read_file_keys(const yaml::Reader& r, const YAML::Node& root, Mapping& m, ErrorList& errors);

}  // namespace andros::mapping
