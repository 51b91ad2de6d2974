#pragma once
/// Redraws a screen on the terminal a few times a second from its own thread,
/// so that a slow or paused terminal (Ctrl-S) can never hold up the frame
/// clock. While it runs, log lines are kept and shown under the screen
/// instead of scrolling through it.

#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace spdlog::sinks {
class sink;
template <typename Mutex>
class ringbuffer_sink;
}

namespace andros::io {

class StatusDisplay {
 public:
  using Compose = std::function<std::string()>;

  /// compose is called on the display thread; it must lock what it reads.
  StatusDisplay(Compose compose, int redraws_per_second);
  ~StatusDisplay();  ///< stops, draws the last screen, restores the log
  StatusDisplay(const StatusDisplay&) = delete;
  StatusDisplay& operator=(const StatusDisplay&) = delete;

  /// Starts the thread (after all other set-up).
  void start();
  void stop();

 private:
  void run();
  void draw(bool final);

  Compose compose_;
  int period_ms_;
  std::shared_ptr<spdlog::sinks::ringbuffer_sink<std::mutex>> log_;
  std::vector<std::shared_ptr<spdlog::sinks::sink>> saved_sinks_;  ///< the log's sinks before start()
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::thread thread_;
};

/// True when fd is a terminal and TERM is not "dumb".
bool is_interactive(int fd);

}  // namespace andros::io
