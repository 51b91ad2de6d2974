#pragma once
// A mapping file's bindings and layers (docs/mapping.md, Binding kinds,
// Layers), read over those of the file it extends (merge.hpp).

#include <vector>

#include "andros/base/error_list.hpp"
#include "andros/mapping/model.hpp"
#include "yaml_reader.hpp"

namespace andros::mapping {

/// An input the file names at node: for errors that point at it.
InputUse input_use(const yaml::Reader& r, const YAML::Node& node, input::InputKey key);

/// Reads `bindings:` (bindings and `unbind:` items) and merges it over base,
/// the extended file's. A bad item is added to errors and left out; reading
/// goes on with the next. A merge that fails throws InputError.
void read_bindings(const yaml::Reader& r, const YAML::Node& list, std::vector<Binding>& base, ErrorList& errors);

/// Reads `layers:` and merges each over base's layer of the same name (a new
/// one is added). A bad layer or binding is added to errors and left out.
void read_layers(const yaml::Reader& r, const YAML::Node& layers, std::vector<Layer>& base, ErrorList& errors);

}  // namespace andros::mapping
