#pragma once
// std::visit with one lambda per alternative.

namespace andros {

template <class... F>
struct Overload : F... {
  using F::operator()...;
};

}  // namespace andros
