#pragma once
// Test doubles of the run loop's frame source. The loop's guards read the
// inputs a source's mapping names (run/drive_guard.hpp): a double's mapping
// names a deadman at most, said here once.

#include <optional>

#include "andros/run/bridge.hpp"

namespace andros::testing {

/// A frame source whose mapping names no stop button and no reset gesture:
/// nothing it reads ever stops, and so nothing ever resets (for the tests of
/// everything but the stop). Its deadman, if any, is the loop's own guard's.
class WithoutStops : public run::FrameSource {
 public:
  explicit WithoutStops(std::optional<input::InputKey> deadman = std::nullopt) {
    if (deadman) mapping_.deadman = mapping::InputUse{*deadman, {}};
  }
  [[nodiscard]] const mapping::Mapping& mapping() const override { return mapping_; }

 private:
  mapping::Mapping mapping_;
};

}  // namespace andros::testing
