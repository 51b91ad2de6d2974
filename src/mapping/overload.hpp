#pragma once
// std::visit with one lambda per alternative.

namespace andros::mapping {

template <class... F>
struct Overload : F... {
  using F::operator()...;
};

// Aggregate deduction is C++20, but clang 14 (the fuzzers' compiler) lacks it.
template <class... F>
Overload(F...) -> Overload<F...>;

}  // namespace andros::mapping
