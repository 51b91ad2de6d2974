#pragma once
/// Redraws a screen on the terminal a few times a second from its own thread,
/// so that a slow or paused terminal (Ctrl-S) can never hold up the frame
/// clock. It writes through a non-blocking descriptor of its own on the
/// terminal, with a time limit per screen, so that neither its thread nor
/// stop() ever waits on a stuck terminal for long; it draws only while the
/// process is in the terminal's foreground. While it runs, log lines are kept
/// and shown under the screen instead of scrolling through it.

#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "andros/base/stop.hpp"

namespace spdlog::sinks {
class sink;
template <typename Mutex>
class ringbuffer_sink;
}

namespace andros::view {

class StatusDisplay {
 public:
  using Compose = std::function<std::string()>;

  /// compose is called on the display thread; it must lock what it reads.
  StatusDisplay(Compose compose, int redraws_per_second);
  ~StatusDisplay();  ///< stops, draws the last screen, restores the log
  StatusDisplay(const StatusDisplay&) = delete;
  StatusDisplay& operator=(const StatusDisplay&) = delete;

  /// Starts the thread (after all other set-up); again after stop() to redraw from scratch.
  void start();
  /// Draws the last screen (bounded), gives the cursor back, restores the log.
  void stop();

 private:
  void run();
  void draw(bool final);
  [[nodiscard]] bool foreground() const;
  /// Writes text within timeout_ms; false if the terminal took not all of it.
  bool write_out(const std::string& text, int timeout_ms);

  Compose compose_;
  int period_ms_;
  int fd_ = -1;        ///< the terminal, opened anew (non-blocking) or stdout
  bool own_fd_ = false;
  bool broken_ = false;  ///< a write failed (terminal gone): nothing more is drawn
  std::shared_ptr<spdlog::sinks::ringbuffer_sink<std::mutex>> log_;
  std::vector<std::shared_ptr<spdlog::sinks::sink>> saved_sinks_;  ///< the log's sinks before start()
  std::optional<StopRequest> stop_;  ///< a new one for each start()
  std::thread thread_;
};

/// True when fd is a terminal and TERM is not "dumb".
bool is_interactive(int fd);

}  // namespace andros::view
