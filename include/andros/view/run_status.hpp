#pragma once
// What `run` tells the operator: the board the run loop updates every tick,
// read by the terminal view's thread; off a terminal, one log line per change.

#include <mutex>
#include <string>

#include "andros/link/sim_vehicle.hpp"
#include "andros/run/bridge.hpp"
#include "andros/timing/frame_timing.hpp"
#include "andros/view/status_view.hpp"

namespace andros::view {

class RunStatusBoard {
 public:
  RunStatusBoard(RunStatus initial, const link::Link& link, const run::FrameSource& frames,
                 const link::SimVehicle* vehicle)
      : status_(std::move(initial)), link_(link), frames_(frames), vehicle_(vehicle) {}

  /// Called by the run loop after every tick (cheap: no formatting).
  void observe(const run::TickReport& report);
  /// The screen, for the display thread.
  [[nodiscard]] std::string compose() const;
  /// The last status (after the run, for the closing line).
  [[nodiscard]] RunStatus snapshot() const;

 private:
  void log_changes(const RunStatus& before, const RunStatus& after) const;

  mutable std::mutex mutex_;
  RunStatus status_;
  timing::FrameTiming timing_;
  const link::Link& link_;
  const run::FrameSource& frames_;
  const link::SimVehicle* vehicle_;
  bool first_tick_ = true;
};

}  // namespace andros::view
