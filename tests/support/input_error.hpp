#pragma once
// What the "bad input" tests check: the whole text of the InputError a piece of
// code throws, or that it names FILE:LINE:COL.

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
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

/// Expects run() to throw an InputError at a file of this name, line and
/// column, whose message holds `message`; `input` is shown if it is accepted.
inline void expect_input_error(const std::function<void()>& run, const std::filesystem::path& file, int line,
                               int column, const std::string& message, const std::string& input) {
  try {
    run();
    ADD_FAILURE() << "accepted:\n" << input;
  } catch (const InputError& e) {
    EXPECT_EQ(std::filesystem::path(e.pos().file).filename(), file);
    EXPECT_EQ(e.pos().line, line) << e.what();
    EXPECT_EQ(e.pos().column, column) << e.what();
    EXPECT_NE(e.message().find(message), std::string::npos) << e.what();
  }
}

}  // namespace andros::testing
