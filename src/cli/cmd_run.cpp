// `andros-bridge run`: the bridge itself. Reads top to bottom: options ->
// config -> checks -> set-up (signals first, before any thread) -> run ->
// shut down.
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "andros/base/error.hpp"
#include "andros/base/job_control.hpp"
#include "andros/base/shutdown_signals.hpp"
#include "andros/base/text.hpp"
#include "andros/cli/config.hpp"
#include "andros/link/serial_link.hpp"
#include "andros/link/sim_vehicle.hpp"
#include "andros/link/tcp_link.hpp"
#include "andros/mapping/loader.hpp"
#include "andros/protocol/robots.hpp"
#include "andros/run/bridge.hpp"
#include "andros/run/engine_frames.hpp"
#include "andros/run/feedback.hpp"
#include "andros/view/run_status.hpp"
#include "andros/view/status_display.hpp"
#include "commands.hpp"
#include "run_input.hpp"
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
  input::SdlInputOptions sdl;  ///< --controller, --controller-db
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
    const auto robot = protocol::canonical_robot(opt.robot);
    if (!robot) {
      throw InputError(SourcePos{"--robot"}, "unknown robot " + quote(opt.robot) + " (one of " + protocol::robot_list() + ")");
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

std::unique_ptr<link::Link> make_link(const RunConfig& config, const link::SimVehicle* sim) {
  if (sim != nullptr) return std::make_unique<link::SerialLink>(sim->port_path(), config.baud);
  if (config.port.starts_with("tcp:")) return std::make_unique<link::TcpLink>(link::parse_tcp_spec(config.port, config.port_pos));
  link::check_serial_port(config.port, config.port_pos);
  return std::make_unique<link::SerialLink>(config.port, config.baud);
}

run::Request poll_requests(ShutdownSignals& signals, JobControlSignals& job) {
  if (signals.requested()) return run::Request::kStop;
  switch (job.poll()) {
    case JobControlSignals::Event::kStopAsked: return run::Request::kSuspend;
    case JobControlSignals::Event::kContinued:
      // Stopped by a SIGSTOP the loop could not answer: no neutral frames went first.
      spdlog::info("continued (SIGCONT): not enabled until the deadman is pressed again");
      return run::Request::kResumed;
    case JobControlSignals::Event::kNone: break;
  }
  return run::Request::kNone;
}

/// The error line for neutral frames that did not reach the link.
std::string failed_neutral_frames(const run::ShutdownReport& shut, const std::string& link) {
  const std::string what =
      shut.neutral_sent < shut.neutral_wanted
          ? "only " + std::to_string(shut.neutral_sent) + " of " + std::to_string(shut.neutral_wanted) +
                " neutral frames could be handed to the link"
          : std::string("the neutral frames were not seen to reach the far end before the link closed");
  return what + " (" + link + "): the vehicle may still be acting on the last command it got";
}

/// What the rumble and light are chosen from. Until the engine's status
/// reaches the observer by value, its reason for not being enabled is read
/// back from its text (describe()).
run::FeedbackStatus feedback_status(const run::TickReport& r, const run::FrameSource& frames, const link::Link& link) {
  using mapping::EnableState;
  EnableState enable = EnableState::kEnabled;
  if (!frames.enabled()) {
    enable = EnableState::kDeadmanReleased;
    for (const auto state : {EnableState::kNoController, EnableState::kDeadmanNotFresh}) {
      if (frames.enable_text() == mapping::describe(state)) enable = state;
    }
  }
  return {r.input->connected(), enable, link.state() == link::LinkState::kUp && link.motion_allowed()};
}

/// Ctrl-Z, after the neutral frames: the terminal back to the shell, the log
/// out, then stop until continued (fg, bg, SIGCONT), and redraw.
void suspend_process(JobControlSignals& job, std::optional<view::StatusDisplay>& display,
                     const run::ShutdownReport& neutral, const std::string& link) {
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

int run_bridge(const RunOptions& opt) {
  const RunConfig config = resolve_config(opt);
  const std::int64_t rate_mhz = rate_millihertz(config);  // refuses a rate the link cannot carry

  // A reader that went away (`2>&1 | head`, a hung-up ssh session) is a
  // write error, never a signal that ends the run between two frames. (The
  // data commands keep the default: `frame decode | head` just ends.)
  std::signal(SIGPIPE, SIG_IGN);
  // Blocked before anything starts a thread (SDL does), so that every thread inherits the mask.
  ShutdownSignals signals;
  JobControlSignals job;
  mapping::Mapping mapping = config.mapping.empty() ? mapping::load_robot_mapping(config.robot)
                                                    : mapping::load_mapping(config.mapping);
  const mapping::FeedbackTable feedback_table = mapping.feedback;
  const auto frames = run::make_engine_frames(
      mapping::Engine(std::move(mapping), mapping::EngineOptions{.weapons = config.weapons, .code = config.code}));
  std::unique_ptr<input::InputSource> input;
  try {
    input = make_input_source(config.input, opt.sdl, [&signals] { return signals.requested(); });
  } catch (const ReadStopped&) {
    // Nothing has been sent: there is no frame to neutralise, and the stop was asked for.
    spdlog::info("stopped (SIG{}) while reading the input, before the first frame",
                 sigabbrev_np(signals.signal_number()));
    return kExitOk;
  }
  std::unique_ptr<link::SimVehicle> sim;
  if (config.port == kSimPort) sim = std::make_unique<link::SimVehicle>(config.code);
  const auto link = make_link(config, sim.get());

  view::RunStatus initial;
  initial.robot = config.mapping.empty() ? config.robot : config.mapping;
  initial.code = config.code;
  initial.rate_hz = static_cast<double>(rate_mhz) / 1000.0;
  initial.input = config.input == "sdl" ? "controller" : config.input;
  initial.link_name = sim ? "sim vehicle on " + link->name() : link->name();
  view::RunStatusBoard board(initial, *link, *frames, sim.get());
  std::optional<view::StatusDisplay> display;
  if (view::is_interactive(STDOUT_FILENO)) display.emplace([&board] { return board.compose(); }, kRedrawsPerSecond);

  if (sim) sim->start();
  if (display) display->start();
  spdlog::info("streaming to {} at {} Hz, code {:02X}{}", initial.link_name, initial.rate_hz, config.code,
               config.weapons ? ", WEAPONS ENABLED" : "");
  run::Bridge bridge(*input, *frames, *link, run::BridgeOptions{.rate_millihertz = rate_mhz});
  const run::RunControl control{
      [&] { return poll_requests(signals, job); },
      [&] { suspend_process(job, display, bridge.shutdown_report(), initial.link_name); }};
  // On the loop's thread, which owns SDL: the rumble starts without waiting.
  run::FeedbackNotifier feedback(feedback_table, *input);
  bridge.run(control, [&](const run::TickReport& r) {
    board.observe(r);
    if (!r.shutting_down) feedback.observe(feedback_status(r, *frames, *link));
  });
  display.reset();

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
      "deadman needs a fresh press. Flags override the config file. With no port, frames go\n"
      "to a built-in simulated vehicle (sim).");
  opt->cmd = cmd;
  cmd->add_option("--config", opt->config,
                  "config file (key=value; default: $XDG_CONFIG_HOME/andros-bridge/andros-bridge.conf,\n"
                  "then /etc/andros-bridge/andros-bridge.conf, if present)");
  cmd->add_option("--robot", opt->robot, "robot type: " + protocol::robot_list() + " (default HD1)");
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
