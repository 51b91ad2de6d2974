#pragma once
// validate()'s checks of bindings (docs/mapping.md, Binding kinds, Layers):
// what each binding may drive, and what the bindings of one layer may share.

#include <optional>
#include <string>
#include <vector>

#include "andros/base/error_list.hpp"
#include "andros/mapping/model.hpp"

namespace andros::mapping {

/// One binding's rule: its target's kind, its ranges, a weapon's arming
/// input. reserved: the deadman and the layer keys; file: the file checked
/// (an error in a clash is reported in it). Throws InputError.
void check_rule(const Binding& b, const std::optional<InputUse>& deadman, const std::vector<InputUse>& reserved,
                const std::string& file);

/// Within one list of bindings: every input once, every analog byte once,
/// no reserved input bound.
void check_list(const std::vector<Binding>& list, const std::vector<InputUse>& reserved, const std::string& file,
                ErrorList& errors);

/// A weapon's arming input may not also fire something else in layer (-1: the base).
void check_arms(const Mapping& m, int layer, ErrorList& errors);

/// A signal is toggled or momentary, not both.
void check_toggles(const Mapping& m, ErrorList& errors);

}  // namespace andros::mapping
