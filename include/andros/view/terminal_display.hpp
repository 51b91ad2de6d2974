#pragma once
/// Redraws a screen on the terminal a few times a second from its own thread,
/// so that a slow or paused terminal (Ctrl-S) can never hold up the frame
/// clock. It writes through a non-blocking descriptor of its own on the
/// terminal, with a time limit per screen, so that neither its thread nor
/// stop() ever waits on a stuck terminal for long; it draws only while the
/// process is in the terminal's foreground. Each screen is composed for the
/// terminal's size at that moment (a resize shows at the next redraw), never
/// more lines than it has; while it runs, the newest log lines fill the rows
/// the screen leaves, instead of scrolling through it. Colour only where
/// colour_wanted() says so.

#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "andros/base/shutdown_request.hpp"
#include "andros/view/screen.hpp"

namespace spdlog::sinks {
class sink;
template <typename Mutex>
class ringbuffer_sink;
}  // namespace spdlog::sinks

namespace andros::view {

class TerminalDisplay {
 public:
  using Compose = std::function<Screen(TermSize)>;

  /// compose is called on the display thread with the size to fill; it must
  /// lock what it reads.
  TerminalDisplay(Compose compose, int redraws_per_second);
  ~TerminalDisplay();  ///< stops, draws the last screen, restores the log
  TerminalDisplay(const TerminalDisplay&) = delete;
  TerminalDisplay& operator=(const TerminalDisplay&) = delete;

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
  int fd_ = -1;  ///< the terminal, opened anew (non-blocking) or stdout
  bool own_fd_ = false;
  bool colour_ = false;
  bool broken_ = false;  ///< a write failed (terminal gone): nothing more is drawn
  std::shared_ptr<spdlog::sinks::ringbuffer_sink<std::mutex>> log_;
  std::vector<std::shared_ptr<spdlog::sinks::sink>> saved_sinks_;  ///< the log's sinks before start()
  std::optional<ShutdownRequest> stop_;                            ///< a new one for each start()
  std::thread thread_;
};

/// True when fd is a terminal and TERM is not "dumb".
bool is_interactive(int fd);

/// The terminal's size (TIOCGWINSZ), or 80x24 when it does not say.
TermSize terminal_size(int fd);

}  // namespace andros::view
