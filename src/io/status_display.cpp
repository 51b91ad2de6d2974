#include "andros/io/status_display.hpp"

#include <spdlog/sinks/ringbuffer_sink.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace andros::io {

bool is_interactive(int fd) {
  const char* term = std::getenv("TERM");
  return isatty(fd) != 0 && (term == nullptr || std::strcmp(term, "dumb") != 0);
}

StatusDisplay::StatusDisplay(Compose compose, int redraws_per_second)
    : compose_(std::move(compose)),
      period_ms_(1000 / redraws_per_second),
      log_(std::make_shared<spdlog::sinks::ringbuffer_sink_mt>(6)) {
  log_->set_pattern("%H:%M:%S %l: %v");
}

StatusDisplay::~StatusDisplay() { stop(); }

void StatusDisplay::start() {
  auto& sinks = spdlog::default_logger()->sinks();
  saved_sinks_ = sinks;
  sinks.assign({log_});
  std::fputs("\x1b[2J\x1b[?25l", stdout);  // clear, and hide the cursor while redrawing
  thread_ = std::thread([this] { run(); });
}

void StatusDisplay::stop() {
  if (!thread_.joinable()) return;
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  thread_.join();
  draw(true);
  spdlog::default_logger()->sinks() = saved_sinks_;
}

void StatusDisplay::run() {
  std::unique_lock lock(mutex_);
  while (!stopping_) {
    lock.unlock();
    draw(false);
    lock.lock();
    wake_.wait_for(lock, std::chrono::milliseconds(period_ms_), [this] { return stopping_; });
  }
}

void StatusDisplay::draw(bool final) {
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
  std::fputs(out.c_str(), stdout);
  std::fflush(stdout);
}

}  // namespace andros::io
