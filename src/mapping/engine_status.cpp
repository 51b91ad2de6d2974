#include "andros/mapping/engine_status.hpp"

namespace andros::mapping {

std::string_view describe(DeadmanState state) {
  switch (state) {
    case DeadmanState::kFreshHold: return "enabled";
    case DeadmanState::kNoPad: return "no controller";
    case DeadmanState::kReleased: return "deadman released";
    case DeadmanState::kHeldNotFresh: return "deadman held since connect or start-up: release and press it again";
    case DeadmanState::kPastPanic:
      return "deadman squeezed past its panic point: release the trigger fully, then press it again";
    case DeadmanState::kTimedOut: return "enable timeout (no input changed): release the deadman and press it again";
  }
  return "?";
}

}  // namespace andros::mapping
