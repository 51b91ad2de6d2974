#pragma once
// What a call says when it refuses its input.

#include <string>

#include "andros/base/error.hpp"

namespace andros::testing {

/// The message of the InputError call() throws, or "no error".
template <typename Call>
std::string input_error_of(const Call& call) {
  try {
    call();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace andros::testing
