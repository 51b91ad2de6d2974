#include "andros/mapping/engine_status.hpp"

namespace andros::mapping {

std::string_view describe(EnableState state) {
  switch (state) {
    case EnableState::kEnabled: return "enabled";
    case EnableState::kNoController: return "no controller";
    case EnableState::kDeadmanReleased: return "deadman released";
    case EnableState::kDeadmanNotFresh: return "deadman held since connect or start-up: release and press it again";
    case EnableState::kPanic:
      return "deadman squeezed past its panic point: release the trigger fully, then press it again";
    case EnableState::kTimedOut: return "enable timeout (no input changed): release the deadman and press it again";
  }
  return "?";
}

}  // namespace andros::mapping
