// `andros-bridge run`: the bridge itself. Reads top to bottom: options ->
// config -> checks -> set-up (signals first, before any thread) -> run ->
// shut down.
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "andros/config.hpp"
#include "andros/error.hpp"
#include "andros/io/bridge.hpp"
#include "andros/io/job_control.hpp"
#include "andros/io/serial_link.hpp"
#include "andros/io/shutdown_signals.hpp"
#include "andros/io/sim_vehicle.hpp"
#include "andros/io/status_display.hpp"
#include "andros/io/tcp_link.hpp"
#include "andros/parse.hpp"
#include "andros/robots.hpp"
#include "commands.hpp"
#include "engine_frames.hpp"
#include "run_input.hpp"
#include "run_reload.hpp"
#include "run_service.hpp"
#include "run_status.hpp"
#include "sdl_options.hpp"

namespace andros::cli {
namespace {

constexpr int kRedrawsPerSecond = 5;

struct RunOptions {
  std::string config;
  std::string robot;
  std::string mapping;
  std::string port;
  std::string baud;
  std::string code;
  std::string rate;
  std::string input;
  bool weapons = false;
  SdlInputOptions sdl;  ///< --controller, --controller-db
  CLI::App* cmd = nullptr;
};

std::string find_default_config() {
  for (const auto& path : default_config_paths()) {
    if (std::filesystem::exists(path)) return path;
  }
  return {};
}

/// Defaults, then the config file, then the flags given.
RunConfig resolve_config(const RunOptions& opt) {
  RunConfig config;
  const std::string file = opt.config.empty() ? find_default_config() : opt.config;
  if (!file.empty()) {
    read_config_file(file, config);
    spdlog::info("config: {}", file);
  }
  const auto given = [&](const char* flag) { return opt.cmd->count(flag) > 0; };
  if (given("--robot")) {
    const auto robot = canonical_robot(opt.robot);
    if (!robot) {
      throw InputError(SourcePos{"--robot"}, "unknown robot " + quote(opt.robot) + " (one of " + robot_list() + ")");
    }
    config.robot = *robot;
    config.mapping.clear();  // a robot on the command line beats a mapping from the file
  }
  if (given("--mapping")) config.mapping = opt.mapping;
  if (given("--port")) {
    config.port = opt.port;
    config.port_pos = SourcePos{"--port"};
  }
  if (given("--baud")) config.baud = parse_baud(opt.baud, SourcePos{"--baud"});
  if (given("--code")) config.code = parse_code(opt.code, SourcePos{"--code"});
  if (given("--rate")) {
    config.rate = opt.rate;
    config.rate_pos = SourcePos{"--rate"};
  }
  if (given("--weapons")) config.weapons = true;
  if (given("--input")) config.input = opt.input;
  if (config.port.empty()) {
    throw InputError(SourcePos{"--port"}, "the port is empty (a device path, sim or tcp:HOST:PORT)");
  }
  return config;
}

std::unique_ptr<io::Link> make_link(const RunConfig& config, const io::SimVehicle* sim) {
  if (sim != nullptr) return std::make_unique<io::SerialLink>(sim->port_path(), config.baud);
  if (config.port.starts_with("tcp:")) return std::make_unique<io::TcpLink>(io::parse_tcp_spec(config.port, config.port_pos));
  io::check_serial_port(config.port, config.port_pos);
  return std::make_unique<io::SerialLink>(config.port, config.baud);
}

io::Request poll_requests(io::ShutdownSignals& signals, io::JobControlSignals& job) {
  if (signals.requested()) return io::Request::kStop;
  if (signals.reload_requested()) return io::Request::kReload;
  switch (job.poll()) {
    case io::JobControlSignals::Event::kStopAsked: return io::Request::kSuspend;
    case io::JobControlSignals::Event::kContinued:
      // Stopped by a SIGSTOP the loop could not answer: no neutral frames went first.
      spdlog::info("continued (SIGCONT): not enabled until the deadman is pressed again");
      return io::Request::kResumed;
    case io::JobControlSignals::Event::kNone: break;
  }
  return io::Request::kNone;
}

/// The error line for neutral frames that did not reach the link.
std::string failed_neutral_frames(const io::ShutdownReport& shut, const std::string& link) {
  const std::string what =
      shut.neutral_sent < shut.neutral_wanted
          ? "only " + std::to_string(shut.neutral_sent) + " of " + std::to_string(shut.neutral_wanted) +
                " neutral frames could be handed to the link"
          : std::string("the neutral frames were not seen to reach the far end before the link closed");
  return what + " (" + link + "): the vehicle may still be acting on the last command it got";
}

/// Ctrl-Z, after the neutral frames: the terminal back to the shell, the log
/// out, then stop until continued (fg, bg, SIGCONT), and redraw.
void suspend_process(io::JobControlSignals& job, std::optional<io::StatusDisplay>& display,
                     const io::ShutdownReport& neutral, const std::string& link) {
  if (display) display->stop();
  if (neutral.ok()) {
    spdlog::info("suspended (SIG{}): neutral frames sent, link closed", sigabbrev_np(job.stop_signal()));
  } else {
    spdlog::error("suspended (SIG{}): {}", sigabbrev_np(job.stop_signal()), failed_neutral_frames(neutral, link));
  }
  spdlog::default_logger()->flush();  // bounded
  job.stop_process();
  spdlog::info("resumed: not enabled until the deadman is pressed again");
  if (display) display->start();
}

/// SIGHUP: the configuration and mapping read again, on the loop's thread
/// between the reload's neutral frames and a fresh start. A bad file keeps
/// the old settings, and says why.
void reload_settings(const RunOptions& opt, RunConfig& config, ReloadableFrames& frames, RunStatusBoard& board,
                     ServiceReporter& service) {
  service.reloading();
  try {
    RunConfig fresh = resolve_config(opt);
    if (auto why = needs_restart(config, fresh); !why.empty()) throw std::runtime_error(why);
    frames.replace(make_engine_frames(fresh));
    config = std::move(fresh);
    board.set_robot(config.mapping.empty() ? config.robot : config.mapping);
    spdlog::info("reloaded (SIGHUP): mapping {}{}; not enabled until the deadman is pressed again",
                 mapping_file(config), config.weapons ? ", WEAPONS ENABLED" : "");
    service.reloaded("");
  } catch (const std::exception& e) {
    spdlog::error("reload (SIGHUP) failed, the old settings stay: {}", e.what());
    service.reloaded(std::string("reload failed: ") + e.what());
  }
}

int run_bridge(const RunOptions& opt) {
  RunConfig config = resolve_config(opt);
  const std::int64_t rate_mhz = rate_millihertz(config);  // refuses a rate the link cannot carry

  // A reader that went away (`2>&1 | head`, a hung-up ssh session) is a
  // write error, never a signal that ends the run between two frames. (The
  // data commands keep the default: `frame decode | head` just ends.)
  std::signal(SIGPIPE, SIG_IGN);
  // Blocked before anything starts a thread (SDL does), so that every thread inherits the mask.
  io::ShutdownSignals signals;
  io::JobControlSignals job;
  ReloadableFrames frames(make_engine_frames(config));
  std::unique_ptr<InputSource> input;
  try {
    input = make_input_source(config.input, opt.sdl, [&signals] { return signals.requested(); });
  } catch (const ReadStopped&) {
    // Nothing has been sent: there is no frame to neutralise, and the stop was asked for.
    spdlog::info("stopped (SIG{}) while reading the input, before the first frame",
                 sigabbrev_np(signals.signal_number()));
    return kExitOk;
  }
  std::unique_ptr<io::SimVehicle> sim;
  if (config.port == kSimPort) sim = std::make_unique<io::SimVehicle>(config.code);
  const auto link = make_link(config, sim.get());

  io::RunStatus initial;
  initial.robot = config.mapping.empty() ? config.robot : config.mapping;
  initial.code = config.code;
  initial.rate_hz = static_cast<double>(rate_mhz) / 1000.0;
  initial.input = config.input == "sdl" ? "controller" : config.input;
  initial.link_name = sim ? "sim vehicle on " + link->name() : link->name();
  RunStatusBoard board(initial, *link, frames, sim.get());
  std::optional<io::StatusDisplay> display;
  if (io::is_interactive(STDOUT_FILENO)) display.emplace([&board] { return board.compose(); }, kRedrawsPerSecond);

  if (sim) sim->start();
  if (display) display->start();
  spdlog::info("streaming to {} at {} Hz, code {:02X}{}", initial.link_name, initial.rate_hz, config.code,
               config.weapons ? ", WEAPONS ENABLED" : "");
  spdlog::info("mapping: {}", mapping_file(config));
  io::Bridge bridge(*input, frames, *link, io::BridgeOptions{.rate_millihertz = rate_mhz});
  ServiceReporter service(io::ServiceNotifier::from_environment());
  signals.reload_on_hangup();
  const io::RunControl control{
      [&] { return poll_requests(signals, job); },
      [&] { suspend_process(job, display, bridge.shutdown_report(), initial.link_name); },
      [&] { reload_settings(opt, config, frames, board, service); }};
  bridge.run(control, [&](const io::TickReport& r) {
    board.observe(r);
    service.observe(r, board.snapshot());
  });
  display.reset();
  service.stopping();

  const auto end = board.snapshot();
  std::string why = "end of the input";
  if (signals.signal_number() != 0) why = std::string("SIG") + sigabbrev_np(signals.signal_number());
  spdlog::info("stopped ({}): {} frames sent, {} ticks skipped (link busy), {} with the link down", why,
               end.link.sent, end.link.busy, end.link.down);
  if (sim) {
    sim->stop();
    const auto v = sim->snapshot();
    spdlog::info("sim vehicle decoded {} frames: {} valid, {} bad checksum, {} invalid", v.stats.frames,
                 v.stats.valid, v.stats.bad_checksum, v.stats.invalid);
  }
  if (!bridge.shutdown_report().ok()) {
    spdlog::error("{}", failed_neutral_frames(bridge.shutdown_report(), initial.link_name));
    return kExitRuntime;
  }
  return kExitOk;
}

}  // namespace

void add_run_command(CLI::App& app, int& exit_code) {
  auto opt = std::make_shared<RunOptions>();
  auto* cmd = app.add_subcommand(
      "run",
      "The bridge: the live controller (or an event script played in real time) to the link,\n"
      "one frame every period, until Ctrl-C/SIGTERM or the end of the script; then neutral\n"
      "frames, drain, close. Ctrl-Z sends the neutral frames before stopping; after fg the\n"
      "deadman needs a fresh press. SIGHUP (systemctl reload) rereads the config file and the\n"
      "mapping: neutral frames, then a fresh deadman press. Flags override the config file.\n"
      "With no port, frames go to a built-in simulated vehicle (sim).");
  opt->cmd = cmd;
  cmd->add_option("--config", opt->config,
                  "config file (key=value; default: $XDG_CONFIG_HOME/andros-bridge/andros-bridge.conf,\n"
                  "then /etc/andros-bridge/andros-bridge.conf, if present)");
  cmd->add_option("--robot", opt->robot, "robot type: " + robot_list() + " (default HD1)");
  cmd->add_option("--mapping", opt->mapping, "a mapping file instead of the robot's shipped one");
  cmd->add_option("--port", opt->port, "PATH (serial device), sim (default) or tcp:HOST:PORT");
  cmd->add_option("--baud", opt->baud, "9600 (default), 19200, 38400, 57600 or 115200");
  cmd->add_option("--code", opt->code, "dip-switch code for byte 11, in hex (default 01)");
  cmd->add_option("--rate", opt->rate, "frames per second, e.g. 25 or 12.5 (default 25; rate x 360 bits must fit the baud)");
  cmd->add_flag("--weapons", opt->weapons, "enable weapon signals for this run (still need deadman and arming)");
  cmd->add_option("--input", opt->input, "sdl (the controller, default) or an event script FILE");
  add_sdl_options(cmd, opt->sdl);
  cmd->callback([opt, &exit_code] { exit_code = run_bridge(*opt); });
}

}  // namespace andros::cli
