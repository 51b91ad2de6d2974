// `andros-bridge monitor [PORT|FILE]`: the vehicle's side of the link.
#include <fcntl.h>
#include <poll.h>
#include <spdlog/spdlog.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "andros/base/clock.hpp"
#include "andros/base/error.hpp"
#include "andros/base/shutdown_request.hpp"
#include "andros/base/text.hpp"
#include "andros/base/unique_fd.hpp"
#include "andros/cli/command_line.hpp"
#include "andros/link/serial_link.hpp"
#include "andros/link/vehicle_view.hpp"
#include "andros/view/operator_screens.hpp"
#include "andros/view/terminal_display.hpp"
#include "commands.hpp"

namespace andros::cli {
namespace {

struct MonitorOptions {
  std::string source = "-";
  std::unique_ptr<CommandLine> settings;  ///< the settings table's flags
};

constexpr int kMonitorRedrawsPerSecond = 4;
constexpr std::int64_t kQuietNs = kNsPerSecond;  ///< no frame for this long: the stream stopped
/// After a stop, what has already arrived is still read, up to these bounds.
constexpr std::size_t kDrainBytes = std::size_t{256} * 1024;
constexpr std::int64_t kDrainNs = 200'000'000;

/// Off a terminal: one line when frames start or stop arriving or errors grow.
class MonitorLog {
 public:
  void update(const link::VehicleStatus& v, std::int64_t now_ns, std::int64_t last_frame_ns) {
    const bool flowing = v.stats.frames > 0 && now_ns - last_frame_ns < kQuietNs;
    const auto errors = v.stats.bad_checksum + v.stats.invalid;
    if (flowing != flowing_) {
      if (flowing) spdlog::info("frames arriving");
      else spdlog::warn("no frame for 1 s ({} so far)", v.stats.frames);
      flowing_ = flowing;
    }
    if (errors != errors_) {
      spdlog::warn("errors: {} bad checksum, {} invalid{}", v.stats.bad_checksum, v.stats.invalid,
                   v.last_errors.empty() ? "" : " (last: " + v.last_errors.front() + ")");
      errors_ = errors;
    }
  }

 private:
  bool flowing_ = false;
  std::uint64_t errors_ = 0;
};

int monitor_file(const std::string& path, link::VehicleView& view) {
  UniqueFd fd(::open(path.c_str(), O_RDONLY | O_CLOEXEC));
  if (!fd) throw InputError(SourcePos{path}, std::string("cannot open: ") + std::strerror(errno));
  std::uint8_t buf[64 * 1024];
  long n = 0;
  while ((n = ::read(fd.get(), buf, sizeof buf)) > 0) {
    view.push(std::span<const std::uint8_t>(buf, static_cast<std::size_t>(n)), 0);
  }
  if (n < 0) throw RuntimeError(path + ": read error: " + std::strerror(errno));
  view.finish();
  std::fputs(view::render_monitor_screen(path, view.status(0), false, view::TermSize{}).text().c_str(), stdout);
  return kExitOk;
}

/// Decodes fd live until a signal or its end. is_port: fd is a serial port,
/// whose end means it was unplugged (exit 1); a pipe's end is just the end.
int monitor_stream(const std::string& name, int fd, bool is_port, link::VehicleView& view) {
  ShutdownRequest stop(kShutdownSignals);  // before the display's thread starts
  std::mutex mutex;
  const bool interactive = view::is_interactive(STDOUT_FILENO);
  std::optional<view::TerminalDisplay> display;
  if (interactive) {
    display.emplace(
        [&](view::TermSize size) {
          const auto now = monotonic_ns();
          const std::lock_guard lock(mutex);
          return view::render_monitor_screen(name, view.status(now), true, size);
        },
        kMonitorRedrawsPerSecond);
    display->start();
  }
  MonitorLog log;
  std::int64_t last_frame_ns = 0;
  std::uint8_t buf[4096];
  bool ended = false;
  bool failed = false;
  while (!stop.requested() && !ended) {
    const bool ready = stop.wait_readable(fd, monotonic_ns() + kNsPerSecond / kMonitorRedrawsPerSecond);
    const auto now = monotonic_ns();
    if (ready) {
      const long n = ::read(fd, buf, sizeof buf);
      if (n > 0) {
        const std::lock_guard lock(mutex);
        const auto before = view.stats().frames;
        view.push(std::span<const std::uint8_t>(buf, static_cast<std::size_t>(n)), now);
        if (view.stats().frames != before) last_frame_ns = now;
      } else if (n == 0 || (errno != EAGAIN && errno != EINTR)) {
        // The end of a pipe or capture is the end; a serial port that ends was unplugged.
        failed = n < 0 || is_port;
        if (failed) spdlog::error("{}: {}", name, n < 0 ? std::strerror(errno) : "hung up");
        ended = true;
      }
    }
    if (!interactive) {
      const std::lock_guard lock(mutex);
      log.update(view.status(now), now, last_frame_ns);
    }
  }
  {
    // Stopped by a signal: what has already arrived still counts, but a
    // source that never runs dry (/dev/zero) must not hold the stop up.
    const std::lock_guard lock(mutex);
    pollfd p{fd, POLLIN, 0};
    long n = 0;
    std::size_t taken = 0;
    const auto deadline = monotonic_ns() + kDrainNs;
    while (!ended && taken < kDrainBytes && monotonic_ns() < deadline && poll(&p, 1, 0) == 1 &&
           (n = ::read(fd, buf, sizeof buf)) > 0) {
      view.push(std::span<const std::uint8_t>(buf, static_cast<std::size_t>(n)), monotonic_ns());
      taken += static_cast<std::size_t>(n);
    }
    view.finish();
  }
  if (display) {
    display->stop();  // draws the last screen, taking the lock itself
  } else {
    const auto screen = view::render_monitor_screen(name, view.status(monotonic_ns()), true, view::TermSize{});
    std::fputs(screen.text().c_str(), stdout);
  }
  return failed ? kExitRuntime : kExitOk;
}

int run_monitor(const MonitorOptions& opt) {
  const Settings settings = resolve_settings(*opt.settings);
  const int baud = settings.baud;
  link::VehicleView view(settings.expected_code);

  if (opt.source == "-") return monitor_stream("standard input", STDIN_FILENO, false, view);
  struct stat st {};
  if (::stat(opt.source.c_str(), &st) != 0) {
    throw InputError(SourcePos{opt.source}, std::string("cannot open: ") + std::strerror(errno));
  }
  if (S_ISDIR(st.st_mode)) {
    throw InputError(SourcePos{opt.source}, "is a directory, not a port or a capture file");
  }
  if (S_ISREG(st.st_mode)) return monitor_file(opt.source, view);
  UniqueFd fd(::open(opt.source.c_str(), O_RDONLY | O_NOCTTY | O_NONBLOCK | O_CLOEXEC));
  if (!fd) throw RuntimeError(opt.source + ": cannot open: " + std::strerror(errno));
  const bool is_port = isatty(fd.get()) != 0;
  if (is_port && !link::configure_raw_8n1(fd.get(), baud)) {
    throw RuntimeError(opt.source + ": cannot set 8N1: " + std::strerror(errno));
  }
  return monitor_stream(opt.source, fd.get(), is_port, view);
}

}  // namespace

void add_monitor_command(CLI::App& app, int& exit_code) {
  auto opt = std::make_shared<MonitorOptions>();
  auto* cmd =
      app.add_subcommand("monitor",
                         "The vehicle's view: decode the frames arriving on a serial port (or in a capture file,\n"
                         "or on standard input) and show them live, with rate, period jitter and error counts.\n"
                         "A capture file is decoded to its end and summarised. Stops on Ctrl-C.");
  cmd->add_option("PORT|FILE", opt->source, "serial port, capture file, or - for standard input")->default_str("-");
  opt->settings = std::make_unique<CommandLine>(*cmd, kMonitor);
  cmd->callback([opt, &exit_code] { exit_code = run_monitor(*opt); });
}

}  // namespace andros::cli
