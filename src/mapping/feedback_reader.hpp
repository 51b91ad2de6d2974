#pragma once
// A mapping's `feedback:` section (docs/mapping.md, Rumble and light).

#include "andros/mapping/feedback.hpp"
#include "yaml_reader.hpp"

namespace andros::mapping {

/// Applies `feedback: off` or a map of events to table (which holds the
/// base file's table, or the defaults). Errors at the node's FILE:LINE:COL.
void read_feedback(const yaml::Reader& r, const YAML::Node& node, FeedbackTable& table);

}  // namespace andros::mapping
