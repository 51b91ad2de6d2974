#include "merge.hpp"

#include <algorithm>

namespace andros::mapping {

Unbind read_unbind(const yaml::Reader& r, const YAML::Node& n) {
  r.expect_keys(n, {"unbind"}, "an unbind item");
  const auto name = r.text(n["unbind"], "unbind");
  if (!input::parse_button_name(name) && !input::parse_axis_name(name)) {
    r.fail(n["unbind"], "unknown input " + quote(name) + " (a button or axis name, as in a binding)");
  }
  return Unbind{name, r.pos(n["unbind"])};
}

bool unbind_matches(const Unbind& unbind, const Binding& binding) {
  const auto button = input::parse_button_name(unbind.name);
  const auto axis = input::parse_axis_name(unbind.name);
  return std::any_of(binding.inputs.begin(), binding.inputs.end(),
                     [&](const InputUse& u) { return u.key == button || u.key == axis; });
}

void merge_bindings(std::vector<Binding>& base, std::vector<Binding> over, const std::vector<Unbind>& unbinds) {
  for (const auto& unbind : unbinds) {
    if (std::erase_if(base, [&](const Binding& old) { return unbind_matches(unbind, old); }) == 0) {
      throw InputError(unbind.pos,
                       "'unbind: " + unbind.name + "': the file this one extends binds nothing to it in this layer");
    }
  }
  std::erase_if(base, [&](const Binding& old) {
    return std::any_of(over.begin(), over.end(), [&](const Binding& b) { return bindings_conflict(old, b); });
  });
  for (auto& b : over) base.push_back(std::move(b));
}

}  // namespace andros::mapping
