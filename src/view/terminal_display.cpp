#include "andros/view/terminal_display.hpp"

#include <fcntl.h>
#include <pthread.h>
#include <spdlog/sinks/ringbuffer_sink.h>
#include <spdlog/spdlog.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>

#include "andros/base/clock.hpp"
#include "andros/base/write_fully.hpp"

namespace andros::view {
namespace {

constexpr int kFinalDrawMs = 300;      ///< the last screen's time limit: exit never waits longer on the terminal
constexpr std::size_t kLogLines = 64;  ///< kept for the screen: more than a tall terminal's spare rows
constexpr int kLogPriority = -1;       ///< below every block of a view

/// The log lines as the screen's last block: warnings yellow, errors red.
/// A line wider than the screen wraps, indented under its text: a log line
/// says why (a refused reload, a lost link), and its end is often the point.
std::vector<Line> log_lines(const std::vector<std::string>& formatted, std::size_t width) {
  constexpr std::size_t kIndent = 9;  // under the text, past "HH:MM:SS "
  std::vector<Line> out;
  for (auto text : formatted) {
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
    const auto level = text.find(' ') + 1;  // after "HH:MM:SS "
    const auto style = text.compare(level, 7, "warning") == 0 ? Style::kWarn
                       : text.compare(level, 5, "error") == 0 || text.compare(level, 8, "critical") == 0
                           ? Style::kAlert
                           : Style::kPlain;
    for (auto& part : wrap_text(text, width, kIndent)) out.emplace_back(std::move(part), style);
  }
  return out;
}

}  // namespace

TermSize terminal_size(int fd) {
  winsize ws{};
  if (::ioctl(fd, TIOCGWINSZ, &ws) != 0 || ws.ws_col == 0 || ws.ws_row == 0) return TermSize{};
  return TermSize{ws.ws_col, ws.ws_row};
}

bool is_interactive(int fd) {
  const char* term = std::getenv("TERM");
  return isatty(fd) != 0 && (term == nullptr || std::strcmp(term, "dumb") != 0);
}

TerminalDisplay::TerminalDisplay(Compose compose, int redraws_per_second)
    : compose_(std::move(compose)),
      period_ms_(1000 / redraws_per_second),
      log_(std::make_shared<spdlog::sinks::ringbuffer_sink_mt>(kLogLines)) {
  log_->set_pattern("%H:%M:%S %l: %v");
  // A description of the terminal of its own: O_NONBLOCK on stdout's would
  // reach the shell and every other process sharing it.
  const char* tty = ttyname(STDOUT_FILENO);
  if (tty != nullptr) fd_ = ::open(tty, O_WRONLY | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  own_fd_ = fd_ >= 0;
  if (!own_fd_) fd_ = STDOUT_FILENO;
  colour_ = isatty(fd_) != 0 && colour_wanted(std::getenv("NO_COLOR"), std::getenv("TERM"));
}

TerminalDisplay::~TerminalDisplay() {
  stop();
  if (own_fd_) ::close(fd_);
}

void TerminalDisplay::start() {
  if (thread_.joinable()) return;
  auto& sinks = spdlog::default_logger()->sinks();
  saved_sinks_ = sinks;
  sinks.assign({log_});
  stop_.emplace();
  if (foreground()) write_out("\x1b[2J\x1b[?25l", period_ms_);  // clear, and hide the cursor while redrawing
  thread_ = std::thread([this] { run(); });
  pthread_setname_np(thread_.native_handle(), "andros-screen");  // as top -H and the idle-cost benchmark name it
}

void TerminalDisplay::stop() {
  if (!thread_.joinable()) return;
  stop_->raise();
  thread_.join();
  draw(true);
  spdlog::default_logger()->sinks() = saved_sinks_;
}

// In the background (bg, or continued there) the terminal is the shell's. A
// terminal that is not the controlling one has no foreground to respect.
bool TerminalDisplay::foreground() const {
  const pid_t owner = tcgetpgrp(fd_);
  return owner < 0 || owner == getpgrp();
}

bool TerminalDisplay::write_out(const std::string& text, int timeout_ms) {
  if (broken_) return false;
  const int error = write_fully(fd_, text, timeout_ms);
  // Any failure but a slow terminal (EIO after a hang-up): the run goes on without a screen.
  if (error != 0 && error != ETIMEDOUT) broken_ = true;
  return error == 0;
}

void TerminalDisplay::run() {
  while (!stop_->requested()) {
    draw(false);
    stop_->sleep_until(monotonic_ns() + period_ms_ * kNsPerMs);
  }
}

void TerminalDisplay::draw(bool final) {
  if (!foreground()) return;
  auto size = terminal_size(fd_);
  // One column short of the edge: a line never leaves the cursor waiting to wrap.
  size.cols = std::max(size.cols - 1, 1);
  Screen screen = compose_(size);
  screen.tail(log_lines(log_->last_formatted(), static_cast<std::size_t>(size.cols)), kLogPriority);
  const std::string text = screen.render(size, colour_);
  // Each line is cleared to its end as it is drawn, so nothing stale shows;
  // the last one ends without a newline, which would scroll the top away.
  std::string out = "\x1b[H";
  out.reserve(text.size() + 256);
  for (std::size_t start = 0; start < text.size();) {
    const auto end = std::min(text.find('\n', start), text.size());
    out.append(text, start, end - start);
    if (end == text.size()) break;
    out += "\x1b[K";
    if (end + 1 < text.size()) out += '\n';
    start = end + 1;
  }
  // Clear what is left of the last, perhaps longer, screen.
  out += "\x1b[J";
  if (final) out += "\x1b[?25h\n";
  // A screen the terminal cannot take in time is cut short; the next one starts from the top.
  write_out(out, final ? kFinalDrawMs : period_ms_);
}

}  // namespace andros::view
