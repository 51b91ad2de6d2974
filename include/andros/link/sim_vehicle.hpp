#pragma once
/// `--port sim`: a pseudo-terminal pair with a simulated vehicle on the far
/// end. The bridge opens the near end by its path like any serial device, so
/// the real serial code runs; the vehicle decodes what arrives, and the
/// operator sees what a real vehicle would decode.

#include <mutex>
#include <string>
#include <thread>

#include "andros/base/shutdown_request.hpp"
#include "andros/base/unique_fd.hpp"
#include "andros/link/vehicle_view.hpp"

namespace andros::link {

class SimVehicle {
 public:
  /// Opens the pair (set-up: throws RuntimeError when no pty can be had).
  /// expected_code: frames with another byte 11 count as invalid.
  explicit SimVehicle(std::uint8_t expected_code);
  ~SimVehicle();
  SimVehicle(const SimVehicle&) = delete;
  SimVehicle& operator=(const SimVehicle&) = delete;

  /// The near end's path, for a SerialLink.
  [[nodiscard]] const std::string& port_path() const { return path_; }

  /// Hands every frame the vehicle decodes to observer, on the vehicle's
  /// thread, as it arrives (before start()).
  void observe_frames(VehicleView::FrameObserver observer) { view_.observe_frames(std::move(observer)); }
  /// Starts the vehicle's reading thread (after all other set-up).
  void start();
  /// Reads what is still in flight, then stops the thread (the destructor does too).
  void stop();
  [[nodiscard]] VehicleStatus status() const;

 private:
  void run();
  /// Reads and decodes what is ready on the master; false at end of input.
  bool read_ready();

  UniqueFd master_;
  UniqueFd slave_;        ///< held open so the master never sees a hang-up between bridge reopens
  ShutdownRequest stop_;  ///< raised by stop(): the thread takes in the last frames and ends
  std::string path_;
  mutable std::mutex mutex_;
  VehicleView view_;
  std::thread thread_;
};

}  // namespace andros::link
