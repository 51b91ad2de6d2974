#pragma once
/// Every error of one input, reported together as a compiler reports them:
/// a mapping with three mistakes says all three at once, not one per try.

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "andros/base/error.hpp"

namespace andros {

/// Several errors of one input. pos() and message() are the first's; what()
/// is each one's `FILE:LINE:COL: error: WHAT`, one line each, in order.
class InputErrors : public InputError {
 public:
  explicit InputErrors(std::vector<InputError> errors)
      : InputError(errors.at(0).pos(), errors.at(0).message()), errors_(std::move(errors)) {
    for (const auto& e : errors_) text_ += (text_.empty() ? "" : "\n") + std::string(e.what());
  }
  [[nodiscard]] const std::vector<InputError>& errors() const { return errors_; }
  [[nodiscard]] const char* what() const noexcept override { return text_.c_str(); }

 private:
  std::vector<InputError> errors_;
  std::string text_;
};

/// Collects the errors of one input while reading goes on past each.
class ErrorList {
 public:
  /// Adds e (each of them, for an InputErrors), once: a second report of
  /// the same line and words is left out.
  void add(const InputError& e) {
    if (const auto* several = dynamic_cast<const InputErrors*>(&e)) {
      for (const auto& one : several->errors()) add(one);
      return;
    }
    for (const auto& seen : errors_) {
      if (std::string_view(seen.what()) == e.what()) return;
    }
    errors_.push_back(e);
  }
  /// Runs step; an InputError it throws is added, and reading goes on.
  template <typename Step>
  void attempt(Step&& step) {
    try {
      std::forward<Step>(step)();
    } catch (const InputError& e) {
      add(e);
    }
  }
  [[nodiscard]] bool empty() const { return errors_.empty(); }
  /// Throws what was collected: the one InputError, or InputErrors of all; nothing when none.
  void throw_if_any() const {
    if (errors_.size() == 1) throw errors_.front();
    if (!errors_.empty()) throw InputErrors(errors_);
  }

 private:
  std::vector<InputError> errors_;
};

}  // namespace andros
