#pragma once
// A broken property is a crash, so that libFuzzer keeps the input (and the
// replay test fails on it) in every build type, asserts or not.
#include <cstdlib>

namespace andros::fuzz {

inline void check(bool ok) {
  if (!ok) std::abort();
}

}  // namespace andros::fuzz
