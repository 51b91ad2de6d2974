#include "andros/base/shutdown_signals.hpp"

namespace andros {

bool ShutdownSignals::requested() {
  if (received_ == 0) received_ = signals_.take();
  return received_ != 0;
}

}  // namespace andros
