#pragma once
/// The log's way out of the process. Lines are handed to a bounded queue and
/// written to a file descriptor (stderr) by a thread of their own, so that a
/// reader that stops reading (a full pipe, a terminal paused with Ctrl-S) or
/// goes away (`| head`, a hung-up ssh session) can never block the thread that
/// logs: the frame loop. A full queue drops its oldest line and counts it; a
/// descriptor whose write fails (EPIPE, EIO, ENOSPC...) is given up once, with
/// a note on another descriptor where there is one.

#include <spdlog/formatter.h>
#include <spdlog/sinks/sink.h>

#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>

namespace andros::view {

class FdLogSink final : public spdlog::sinks::sink {
 public:
  struct Options {
    std::string name = "standard error";  ///< what fd is, for the note
    std::size_t max_lines = 256;          ///< beyond this, the oldest queued line is dropped
    int note_fd = -1;                     ///< where to say that fd failed (-1: nowhere)
    bool colour = false;                  ///< ANSI colour on the level (fd is a terminal)
    int flush_wait_ms = 300;              ///< how long flush() and destruction wait for queued lines
    bool priority_prefix = false;         ///< `<N>` syslog priority before each line (fd is the journal)
  };

  /// Starts the writer thread. fd stays owned by the caller and must outlive the sink.
  FdLogSink(int fd, Options options);
  /// Waits at most flush_wait_ms for the queue; a writer still stuck in a
  /// write then is left to end with the process.
  ~FdLogSink() override;
  FdLogSink(const FdLogSink&) = delete;
  FdLogSink& operator=(const FdLogSink&) = delete;

  /// Queues one line, escaped as every log line is (terminal_line(),
  /// base/sink_text.hpp: a newline in it is shown as \n, never a second
  /// line; the newline is added; with priority_prefix, the `<priority>` too:
  /// 3, err, for the callers' own error lines). Never blocks on the fd.
  void write_line(std::string_view line, int priority = 3);
  /// Waits at most timeout_ms until every queued line is written (or given up).
  bool flush_for(int timeout_ms);
  /// True once a write to the fd failed: nothing more is written to it.
  [[nodiscard]] bool failed() const;
  /// Lines dropped from a full queue, or after the fd failed.
  [[nodiscard]] std::uint64_t dropped() const;

  /// spdlog's side: log() escapes the message (terminal_line()), formats and queues; flush() waits at most
  /// flush_wait_ms.
  void log(const spdlog::details::log_msg& msg) override;
  void flush() override;
  void set_pattern(const std::string& pattern) override;
  void set_formatter(std::unique_ptr<spdlog::formatter> formatter) override;

 private:
  struct Queue;
  static void write_out(const std::shared_ptr<Queue>& q);
  /// Queues a line already escaped.
  void queue(std::string line, int priority);

  std::shared_ptr<Queue> queue_;  ///< shared with the writer thread, which may outlive the sink
  bool colour_;
  bool priority_prefix_;
  std::mutex format_mutex_;
  std::unique_ptr<spdlog::formatter> formatter_;
};

/// Makes spdlog's default logger write `LEVEL: message` lines to stderr
/// through an FdLogSink (the note, if stderr fails, goes to stdout when that
/// is a terminal of its own). Call once, before any thread logs. When stderr
/// is the journal (a systemd service), lines are `<N>message` instead: the
/// journal takes the level from the prefix.
std::shared_ptr<FdLogSink> install_stderr_log();

}  // namespace andros::view
