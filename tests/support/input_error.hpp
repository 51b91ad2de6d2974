#pragma once
// The whole text of the InputError a piece of code throws, for tests that
// compare error messages as the user reads them.

#include <string>
#include <utility>

#include "andros/base/error.hpp"

namespace andros::testing {

/// What `action()` throws as an InputError ("FILE:LINE:COL: error: ..."), or
/// "no error" when it returns.
template <typename Action>
std::string input_error_text(Action&& action) {
  try {
    std::forward<Action>(action)();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace andros::testing
