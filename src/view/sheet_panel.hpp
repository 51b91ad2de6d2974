#pragma once
// One panel of the cheat sheet: a layer's entries, one per input.

#include <vector>

#include "andros/mapping/model.hpp"
#include "andros/view/sheet.hpp"

namespace andros::view::sheet_detail {

/// The entries of layer (-1: the base layer): the deadman, the stop, the
/// layer and speed keys, then its bindings and the base's it keeps (marked
/// inherited); the inputs the pad drawing shows first, in its order.
std::vector<SheetEntry> panel_entries(const mapping::Mapping& m, int layer);

}  // namespace andros::view::sheet_detail
