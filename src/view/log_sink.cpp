#include "andros/view/log_sink.hpp"

#include <pthread.h>
#include <spdlog/pattern_formatter.h>
#include <spdlog/spdlog.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <thread>

#include "andros/base/service_notify.hpp"
#include "andros/base/sink_text.hpp"
#include "andros/base/write_fully.hpp"
#include "andros/view/screen.hpp"
#include "andros/view/terminal_display.hpp"

namespace andros::view {

struct FdLogSink::Queue {
  int fd = -1;
  std::string name;
  std::size_t max_lines = 0;
  int note_fd = -1;
  int flush_wait_ms = 0;
  std::mutex mutex;
  std::condition_variable wake;  ///< the writer: lines to write, or stop
  std::condition_variable idle;  ///< flushers: the queue is written out
  std::deque<std::string> lines;
  std::uint64_t dropped = 0;
  std::uint64_t unreported = 0;  ///< dropped from a full queue since the writer last said so
  bool writing = false;
  bool failed = false;
  bool stopping = false;
  bool exited = false;
  std::thread thread;
};

namespace {

const char* level_colour(spdlog::level::level_enum level) {
  switch (level) {
    case spdlog::level::info: return "\x1b[32m";
    case spdlog::level::warn: return "\x1b[33m\x1b[1m";
    case spdlog::level::err: return "\x1b[31m\x1b[1m";
    case spdlog::level::critical: return "\x1b[1m\x1b[41m";
    default: return "\x1b[36m";
  }
}

/// sd-daemon(3)'s priority prefixes (syslog levels).
int syslog_priority(spdlog::level::level_enum level) {
  switch (level) {
    case spdlog::level::critical: return 2;
    case spdlog::level::err: return 3;
    case spdlog::level::warn: return 4;
    case spdlog::level::info: return 6;
    default: return 7;
  }
}

bool same_file(int a, int b) {
  struct stat sa {};
  struct stat sb {};
  return fstat(a, &sa) == 0 && fstat(b, &sb) == 0 && sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

}  // namespace

void FdLogSink::write_out(const std::shared_ptr<Queue>& q) {
  std::unique_lock lock(q->mutex);
  while (true) {
    q->wake.wait(lock, [&] { return q->stopping || !q->lines.empty(); });
    if (q->lines.empty()) break;
    std::string text;
    if (q->unreported > 0) {
      text = "(" + std::to_string(q->unreported) + " log lines dropped: " + q->name + " was not taking them)\n";
      q->unreported = 0;
    }
    while (!q->lines.empty()) {
      text += q->lines.front();
      q->lines.pop_front();
    }
    q->writing = true;
    lock.unlock();
    const int error = write_fully(q->fd, text);
    lock.lock();
    q->writing = false;
    if (error != 0) {
      q->failed = true;
      q->dropped += q->lines.size();
      q->lines.clear();
      if (q->note_fd >= 0) {
        const std::string note =
            "andros-bridge: log: " + q->name + ": " + std::strerror(error) + "; no more log lines go there\n";
        lock.unlock();
        write_fully(q->note_fd, note);
        lock.lock();
      }
    }
    q->idle.notify_all();
    if (q->failed) break;
  }
  q->exited = true;
  q->idle.notify_all();
}

FdLogSink::FdLogSink(int fd, Options options)
    : queue_(std::make_shared<Queue>()),
      colour_(options.colour),
      priority_prefix_(options.priority_prefix),
      formatter_(std::make_unique<spdlog::pattern_formatter>()) {
  queue_->fd = fd;
  queue_->name = std::move(options.name);
  queue_->max_lines = std::max<std::size_t>(options.max_lines, 1);
  queue_->note_fd = options.note_fd;
  queue_->flush_wait_ms = options.flush_wait_ms;
  // Started before the commands block their signals: it must never be the
  // thread a process signal (SIGTERM...) is delivered to, so it blocks them all from birth.
  sigset_t all;
  sigset_t old;
  sigfillset(&all);
  pthread_sigmask(SIG_SETMASK, &all, &old);
  queue_->thread = std::thread([q = queue_] { write_out(q); });
  pthread_setname_np(queue_->thread.native_handle(), "andros-log");
  pthread_sigmask(SIG_SETMASK, &old, nullptr);
}

FdLogSink::~FdLogSink() {
  flush_for(queue_->flush_wait_ms);
  std::unique_lock lock(queue_->mutex);
  queue_->stopping = true;
  queue_->wake.notify_all();
  queue_->idle.wait_for(lock, std::chrono::milliseconds(20), [this] { return queue_->exited; });
  const bool exited = queue_->exited;
  lock.unlock();
  // A writer stuck in write() on a paused terminal holds only the queue, which it shares.
  if (exited) queue_->thread.join();
  else queue_->thread.detach();
}

void FdLogSink::write_line(std::string_view line, int priority) { queue(terminal_line(line), priority); }

void FdLogSink::queue(std::string line, int priority) {
  if (priority_prefix_) line.insert(0, "<" + std::to_string(priority) + ">");
  line += '\n';
  const std::lock_guard lock(queue_->mutex);
  if (queue_->failed || queue_->exited) {
    ++queue_->dropped;
    return;
  }
  if (queue_->lines.size() >= queue_->max_lines) {
    queue_->lines.pop_front();
    ++queue_->dropped;
    ++queue_->unreported;
  }
  queue_->lines.push_back(std::move(line));
  queue_->wake.notify_one();
}

bool FdLogSink::flush_for(int timeout_ms) {
  std::unique_lock lock(queue_->mutex);
  return queue_->idle.wait_for(lock, std::chrono::milliseconds(timeout_ms),
                               [this] { return queue_->exited || (queue_->lines.empty() && !queue_->writing); });
}

bool FdLogSink::failed() const {
  const std::lock_guard lock(queue_->mutex);
  return queue_->failed;
}

std::uint64_t FdLogSink::dropped() const {
  const std::lock_guard lock(queue_->mutex);
  return queue_->dropped;
}

void FdLogSink::log(const spdlog::details::log_msg& msg) {
  // The message, not the line: the level's colour is the sink's own escape sequence.
  const std::string text = terminal_line(std::string_view(msg.payload.data(), msg.payload.size()));
  spdlog::details::log_msg escaped = msg;
  escaped.payload = spdlog::string_view_t(text.data(), text.size());
  spdlog::memory_buf_t buf;
  {
    const std::lock_guard lock(format_mutex_);
    formatter_->format(escaped, buf);
  }
  std::string line(buf.data(), buf.size());
  if (!line.empty() && line.back() == '\n') line.pop_back();
  if (colour_ && msg.color_range_end > msg.color_range_start && msg.color_range_end <= line.size()) {
    line.insert(msg.color_range_end, "\x1b[m");
    line.insert(msg.color_range_start, level_colour(msg.level));
  }
  queue(std::move(line), syslog_priority(msg.level));
}

void FdLogSink::flush() { flush_for(queue_->flush_wait_ms); }

void FdLogSink::set_pattern(const std::string& pattern) {
  set_formatter(std::make_unique<spdlog::pattern_formatter>(pattern));
}

void FdLogSink::set_formatter(std::unique_ptr<spdlog::formatter> formatter) {
  const std::lock_guard lock(format_mutex_);
  formatter_ = std::move(formatter);
}

std::shared_ptr<FdLogSink> install_stderr_log() {
  FdLogSink::Options options;
  options.colour = is_interactive(STDERR_FILENO) && colour_wanted(std::getenv("NO_COLOR"), std::getenv("TERM"));
  options.priority_prefix = is_journal_stream(STDERR_FILENO);
  if (isatty(STDOUT_FILENO) != 0 && !same_file(STDOUT_FILENO, STDERR_FILENO)) options.note_fd = STDOUT_FILENO;
  auto sink = std::make_shared<FdLogSink>(STDERR_FILENO, options);
  spdlog::set_default_logger(std::make_shared<spdlog::logger>("andros-bridge", sink));
  spdlog::set_pattern(options.priority_prefix ? "%v" : "%^%l%$: %v");
  return sink;
}

}  // namespace andros::view
