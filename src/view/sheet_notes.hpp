#pragma once
// The cheat sheet's notes: what the panels cannot show (selectors' positions,
// knobs, speed levels, weapons, the supervisor, the stop and its reset).

#include <string>
#include <vector>

#include "andros/mapping/model.hpp"

namespace andros::view::sheet_detail {

std::vector<std::string> sheet_notes(const mapping::Mapping& m);

}  // namespace andros::view::sheet_detail
