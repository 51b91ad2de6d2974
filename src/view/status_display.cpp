#include "andros/view/status_display.hpp"

#include <fcntl.h>
#include <spdlog/sinks/ringbuffer_sink.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

#include "andros/base/clock.hpp"
#include "andros/base/write_fully.hpp"

namespace andros::view {
namespace {

constexpr int kFinalDrawMs = 300;  ///< the last screen's time limit: exit never waits longer on the terminal

}  // namespace

bool is_interactive(int fd) {
  const char* term = std::getenv("TERM");
  return isatty(fd) != 0 && (term == nullptr || std::strcmp(term, "dumb") != 0);
}

StatusDisplay::StatusDisplay(Compose compose, int redraws_per_second)
    : compose_(std::move(compose)),
      period_ms_(1000 / redraws_per_second),
      log_(std::make_shared<spdlog::sinks::ringbuffer_sink_mt>(6)) {
  log_->set_pattern("%H:%M:%S %l: %v");
  // A description of the terminal of its own: O_NONBLOCK on stdout's would
  // reach the shell and every other process sharing it.
  const char* tty = ttyname(STDOUT_FILENO);
  if (tty != nullptr) fd_ = ::open(tty, O_WRONLY | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  own_fd_ = fd_ >= 0;
  if (!own_fd_) fd_ = STDOUT_FILENO;
}

StatusDisplay::~StatusDisplay() {
  stop();
  if (own_fd_) ::close(fd_);
}

void StatusDisplay::start() {
  if (thread_.joinable()) return;
  auto& sinks = spdlog::default_logger()->sinks();
  saved_sinks_ = sinks;
  sinks.assign({log_});
  stop_.emplace();
  if (foreground()) write_out("\x1b[2J\x1b[?25l", period_ms_);  // clear, and hide the cursor while redrawing
  thread_ = std::thread([this] { run(); });
}

void StatusDisplay::stop() {
  if (!thread_.joinable()) return;
  stop_->raise();
  thread_.join();
  draw(true);
  spdlog::default_logger()->sinks() = saved_sinks_;
}

// In the background (bg, or continued there) the terminal is the shell's. A
// terminal that is not the controlling one has no foreground to respect.
bool StatusDisplay::foreground() const {
  const pid_t owner = tcgetpgrp(fd_);
  return owner < 0 || owner == getpgrp();
}

bool StatusDisplay::write_out(const std::string& text, int timeout_ms) {
  if (broken_) return false;
  const int error = write_fully(fd_, text, timeout_ms);
  // Any failure but a slow terminal (EIO after a hang-up): the run goes on without a screen.
  if (error != 0 && error != ETIMEDOUT) broken_ = true;
  return error == 0;
}

void StatusDisplay::run() {
  while (!stop_->requested()) {
    draw(false);
    stop_->sleep_until(monotonic_ns() + period_ms_ * kNsPerMs);
  }
}

void StatusDisplay::draw(bool final) {
  if (!foreground()) return;
  std::string screen = "\x1b[H" + compose_();
  screen += "\nlog:\n";
  for (const auto& line : log_->last_formatted()) screen += "  " + line;
  // Clear what is left of the last, perhaps longer, screen.
  screen += "\x1b[J";
  if (final) screen += "\x1b[?25h";
  // Each line is cleared to its end as it is drawn, so nothing stale shows.
  std::string out;
  out.reserve(screen.size() + 256);
  for (const char c : screen) {
    if (c == '\n') out += "\x1b[K";
    out += c;
  }
  // A screen the terminal cannot take in time is cut short; the next one starts from the top.
  write_out(out, final ? kFinalDrawMs : period_ms_);
}

}  // namespace andros::view
