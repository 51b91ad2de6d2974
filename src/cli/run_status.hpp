#pragma once
// What `run` tells the operator: the board the run loop updates every tick,
// read by the terminal view's thread; off a terminal, one log line per change.

#include <mutex>
#include <string>

#include "andros/io/bridge.hpp"
#include "andros/io/frame_timing.hpp"
#include "andros/io/sim_vehicle.hpp"
#include "andros/io/status_view.hpp"

namespace andros::cli {

class RunStatusBoard {
 public:
  RunStatusBoard(io::RunStatus initial, const io::Link& link, const io::FrameSource& frames,
                 const io::SimVehicle* vehicle)
      : status_(std::move(initial)), link_(link), frames_(frames), vehicle_(vehicle) {}

  /// Called by the run loop after every tick (cheap: no formatting).
  void observe(const io::TickReport& report);
  /// The screen, for the display thread.
  [[nodiscard]] std::string compose() const;
  /// After a reload: the robot (or mapping file) the view names.
  void set_robot(std::string robot);
  /// The last status (after the run, for the closing line).
  [[nodiscard]] io::RunStatus snapshot() const;

 private:
  void log_changes(const io::RunStatus& before, const io::RunStatus& after) const;

  mutable std::mutex mutex_;
  io::RunStatus status_;
  io::FrameTiming timing_;
  const io::Link& link_;
  const io::FrameSource& frames_;
  const io::SimVehicle* vehicle_;
  bool first_tick_ = true;
};

}  // namespace andros::cli
