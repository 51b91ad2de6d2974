#include "andros/io/shutdown_signals.hpp"

namespace andros::io {

bool ShutdownSignals::requested() {
  if (received_ == 0) received_ = signals_.take();
  return received_ != 0;
}

}  // namespace andros::io
