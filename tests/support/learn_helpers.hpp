#pragma once
// What the mapping and learn tests share: inputs by name, a plan's step by
// its prompt, and whether a list of bindings reads an input.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "andros/mapping/learn.hpp"

namespace andros::test {

inline input::Gesture button(const char* name) { return {*input::parse_button_name(name), false}; }
inline input::Gesture axis(const char* name, bool negative) { return {*input::parse_axis_name(name), negative}; }

/// The step whose prompt names this layer and target ("base layer, drive"),
/// before the operator's words in brackets, if any ("(zoom out)").
inline std::size_t step_of(const mapping::LearnPlan& plan, const std::string& where) {
  for (std::size_t i = 0; i < plan.steps().size(); ++i) {
    const auto prompt = plan.prompt(i);
    const auto at = prompt.find("] " + where);
    if (at == std::string::npos) continue;
    const auto after = prompt.substr(at + 2 + where.size(), 2);
    if (after.starts_with(":") || after == " (") return i;
  }
  ADD_FAILURE() << "no step " << where;
  return 0;
}

/// True when a binding of the list is triggered by the input of that name.
inline bool reads(const std::vector<mapping::Binding>& list, const char* name) {
  return std::any_of(list.begin(), list.end(), [&](const mapping::Binding& b) {
    return std::any_of(b.inputs.begin(), b.inputs.end(),
                       [&](const mapping::InputUse& u) { return input::input_name(u.key) == name; });
  });
}

}  // namespace andros::test
