#pragma once
// How an extending file's list of bindings applies to the list it extends
// (docs/mapping.md, extends): shared by the loader and by `learn`, which
// writes such files.

#include <string>
#include <vector>

#include "andros/mapping/model.hpp"
#include "yaml_reader.hpp"

namespace andros::mapping {

/// A list item `- unbind: NAME`: drops the extended file's bindings read by
/// that input. A number names both the joystick button and the joystick axis.
struct Unbind {
  std::string name;
  SourcePos pos;
};

/// Reads a `- unbind: NAME` list item.
Unbind read_unbind(const yaml::Reader& r, const YAML::Node& item);

/// True when the binding is read by the input unbind names (its `arm` does not count).
bool unbind_matches(const Unbind& unbind, const Binding& binding);

/// Applies the unbind items to base (each must drop something), then each
/// of over's bindings replaces the base bindings it conflicts with and is added.
void merge_bindings(std::vector<Binding>& base, std::vector<Binding> over, const std::vector<Unbind>& unbinds);

}  // namespace andros::mapping
