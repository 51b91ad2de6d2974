// `andros-bridge run`: the bridge itself. Reads top to bottom: options ->
// config -> checks -> set-up (signals first, before any thread) -> run ->
// shut down.
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <csignal>
#include <memory>
#include <optional>
#include <string>

#include "andros/base/cpu_limit.hpp"
#include "andros/base/error.hpp"
#include "andros/base/job_control.hpp"
#include "andros/base/shutdown_request.hpp"
#include "andros/base/text.hpp"
#include "andros/cli/command_line.hpp"
#include "andros/cli/config.hpp"
#include "andros/link/serial_link.hpp"
#include "andros/link/sim_vehicle.hpp"
#include "andros/link/tcp_link.hpp"
#include "andros/run/bridge.hpp"
#include "andros/run/feedback.hpp"
#include "andros/run/loop.hpp"
#include "andros/view/status_board.hpp"
#include "andros/view/terminal_display.hpp"
#include "commands.hpp"
#include "run_bridge.hpp"
#include "run_input.hpp"
#include "run_recording.hpp"
#include "run_reload.hpp"
#include "run_service.hpp"
#include "sdl_options.hpp"

namespace andros::cli {
namespace {

constexpr int kRunRedrawsPerSecond = 5;

std::unique_ptr<link::Link> make_link(const Settings& config, const link::SimVehicle* sim) {
  if (sim != nullptr) return std::make_unique<link::SerialLink>(sim->port_path(), config.baud);
  if (config.port.starts_with("tcp:"))
    return std::make_unique<link::TcpLink>(link::parse_tcp_spec(config.port, config.port_pos));
  link::check_serial_port(config.port, config.port_pos);
  return std::make_unique<link::SerialLink>(config.port, config.baud);
}

run::Request poll_requests(ShutdownRequest& stop, JobControlSignals& job) {
  // One sigpending() a tick rather than a sigtimedwait() for each signal set:
  // the sets are asked only when a signal waits or the stop knows something.
  if (!stop.has_unread() && !signals_pending()) return run::Request::kNone;
  if (stop.requested()) return run::Request::kShutdown;
  if (stop.reload_requested()) return run::Request::kReload;
  switch (job.poll()) {
    case JobControlSignals::Event::kStopAsked: return run::Request::kSuspend;
    case JobControlSignals::Event::kContinued:
      // Continued during a Ctrl-Z's neutral frames (the loop then does not stop
      // the process), or after a SIGSTOP the loop could not answer.
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

/// Ctrl-Z, after the neutral frames: the terminal back to the shell, the log
/// out, then stop until continued (fg, bg, SIGCONT), and redraw. A SIGCONT
/// during the neutral frames means it does not stop at all.
void suspend_process(JobControlSignals& job, std::optional<view::TerminalDisplay>& display,
                     const run::ShutdownReport& neutral, const std::string& link) {
  if (display) display->stop();
  if (neutral.ok()) {
    spdlog::info("suspended (SIG{}): neutral frames sent, link closed", sigabbrev_np(job.stop_signal()));
  } else {
    spdlog::error("suspended (SIG{}): {}", sigabbrev_np(job.stop_signal()), failed_neutral_frames(neutral, link));
  }
  spdlog::default_logger()->flush();  // bounded
  if (job.stop_process() == JobControlSignals::Stop::kContinuedBeforeStop) {
    spdlog::info("continued (SIGCONT) before it stopped: not enabled until the deadman is pressed again");
  } else {
    spdlog::info("resumed: not enabled until the deadman is pressed again");
  }
  if (display) display->start();
}

}  // namespace

int run_bridge(const RunOptions& opt, const RunHooks& hooks) {
  Settings config = resolve_settings(*opt.settings);  // refuses a rate the link cannot carry
  if (hooks.check) hooks.check(config);
  const std::int64_t rate_millihertz = config.rate.millihertz;

  // A reader that went away (`2>&1 | head`, a hung-up ssh session) is a
  // write error, never a signal that ends the run between two frames. (The
  // data commands keep the default: `frame decode | head` just ends.)
  std::signal(SIGPIPE, SIG_IGN);
  // A CPU-time limit's SIGKILL must not come first: SIGXCPU, a stop, does.
  if (const auto cpu = keep_room_before_cpu_kill(); !cpu.empty()) spdlog::info("{}", cpu);
  // Blocked before anything starts a thread (SDL does), so that every thread inherits the mask.
  ShutdownRequest stop(kRunShutdownSignals);
  JobControlSignals job;
  EngineSetup engine = load_engine(config);
  input::SdlInputOptions sdl = opt.sdl;
  sdl.supervisor = config.supervisor;
  sdl.supervisor_pos = config.supervisor_pos;
  std::unique_ptr<input::InputSource> input;
  try {
    input = make_input_source(config.input, sdl, [&stop] { return stop.requested(); });
  } catch (const ReadStopped&) {
    // Nothing has been sent: there is no frame to neutralise, and the stop was asked for.
    spdlog::info("stopped (SIG{}) while reading the input, before the first frame", sigabbrev_np(stop.signal_number()));
    return kExitOk;
  }
  if (!config.supervisor.empty() && config.input != kSdlInput) {
    spdlog::warn(
        "supervisor {} not read: the event script {} is the input ('T supervisor EVENT' lines are its "
        "supervisor's controller)",
        config.supervisor, config.input);
  }
  if (engine.supervisor_buttons && !input->supervised()) {
    spdlog::warn(
        "the mapping's supervisor: buttons have no controller to read (no --supervisor): its stop "
        "cannot be pressed, and weapons that need its consent never fire");
  }
  std::unique_ptr<link::SimVehicle> sim;
  if (config.port == kSimPort) sim = std::make_unique<link::SimVehicle>(config.code);
  if (sim && hooks.frames) sim->observe_frames(hooks.frames);
  const auto link = make_link(config, sim.get());
  // Logged once every setting has been checked, so that an error stays one line.
  spdlog::info("robot {}, mapping {}, port {}, code {:02X}{}", engine.robot, engine.mapping_file, config.port,
               config.code, config.weapons ? ", WEAPONS ENABLED" : "");

  // The flight recorder (docs/recording.md): a thread of its own, never in the loop's way.
  const auto recording = RunRecording::start(config, engine, *link, *input);
  if (recording && hooks.opening_record) recording->add(hooks.opening_record());
  input::InputSource& recorded_input = recording ? recording->input() : *input;
  input::InputSource& loop_input = hooks.input ? hooks.input(recorded_input) : recorded_input;

  view::RunStatus initial;
  initial.robot = engine.robot;
  initial.mapping_file = engine.mapping_file;
  initial.weapons = config.weapons;
  initial.code = config.code;
  initial.center = engine.center;
  initial.pad_names = engine.pad_names;
  initial.rate_hz = static_cast<double>(rate_millihertz) / timing::kMillihertzPerHz;
  initial.input = config.input == kSdlInput ? "controller" : config.input;
  initial.link_name = sim ? "sim vehicle on " + link->name() : link->name();
  if (hooks.start) initial.trainer = hooks.start(config);
  view::RunStatusBoard board(initial);  // fed by the loop's reports only
  const auto compose = [&board, &sim, &recording](view::TermSize size) {
    view::RunStatus status = board.status();
    if (sim) status.vehicle = sim->status();
    if (recording) recording->describe(status);
    return view::render_run_screen(status, size);
  };
  std::optional<view::TerminalDisplay> display;
  if (view::is_interactive(STDOUT_FILENO)) display.emplace(compose, kRunRedrawsPerSecond);

  if (sim) sim->start();
  if (display) display->start();
  spdlog::info("streaming to {} at {} Hz", initial.link_name, initial.rate_hz);
  // On the loop's thread, which owns SDL: the rumble starts without waiting.
  run::FeedbackNotifier feedback(engine.feedback, *input);
  ServiceReporter service(ServiceNotifier::from_environment());
  stop.reload_on_hangup();
  // SIGHUP (or a script's `reload [MAPPING]`, MAPPING relative to the script's
  // folder): the files read on a worker while the loop sends neutral frames;
  // swapped in on the loop's thread.
  RunReload reload(opt.settings->given_flags(), ReloadTargets{config, feedback, board, service});
  RealClock clock;
  run::LoopParts loop{.clock = clock,
                      .input = loop_input,
                      .frames = *engine.frames,
                      .link = *link,
                      .options = {.rate_millihertz = rate_millihertz, .rules = {config.weapons, config.code}},
                      .control = {},
                      .observers = {}};
  loop.control.poll = [&] { return poll_requests(stop, job); };
  loop.control.pause = [&](const run::ShutdownReport& neutral) {
    suspend_process(job, display, neutral, initial.link_name);
  };
  loop.control.begin_reload = [&](const std::string& mapping) {
    reload.begin(mapping.empty() ? "" : beside(config.input, mapping));
  };
  loop.control.finish_reload = [&] { return reload.finish(); };
  if (recording) {
    loop.control = recording->control(std::move(loop.control), config, reload);
    loop.observers.emplace_back([&](const run::TickReport& r) { recording->observe(r); });
  }
  loop.observers.emplace_back([&](const run::TickReport& r) {
    board.observe(r, *input);  // on the loop's thread, which owns SDL: it asks what kind a new controller is
    feedback.observe(r);
    // The board's copy is taken only for a service manager: not on every tick of a plain run.
    if (service.active()) service.observe(r, board.status());
  });
  if (hooks.observe) loop.observers.emplace_back([&](const run::TickReport& r) { hooks.observe(r, board); });
  const run::ShutdownReport neutral = run::run_loop(loop);
  display.reset();
  service.stopping();
  if (hooks.after_run) hooks.after_run(stop);

  const auto end = board.status();
  std::string why = "end of the input";
  if (stop.signal_number() != 0) why = std::string("SIG") + sigabbrev_np(stop.signal_number());
  if (recording && hooks.closing_record) recording->add(hooks.closing_record());
  if (recording) recording->finish(why);
  spdlog::info("stopped ({}): {} frames sent, {} ticks skipped (link busy), {} with the link down", why, end.link.sent,
               end.link.busy, end.link.down);
  if (end.gate_trips > 0) {
    spdlog::error("{} frame(s) replaced by the frame gate: an internal error (the log above says which rule)",
                  end.gate_trips);
  }
  if (sim) {
    sim->stop();
    const auto v = sim->status();
    spdlog::info("sim vehicle decoded {} frames: {} valid, {} bad checksum, {} invalid", v.stats.frames, v.stats.valid,
                 v.stats.bad_checksum, v.stats.invalid);
  }
  if (!neutral.ok()) {
    spdlog::error("{}", failed_neutral_frames(neutral, initial.link_name));
    return kExitRuntime;
  }
  return kExitOk;
}

void add_run_command(CLI::App& app, int& exit_code) {
  auto opt = std::make_shared<RunOptions>();
  auto* cmd =
      app.add_subcommand("run",
                         "The bridge: the live controller (or an event script played in real time) to the link,\n"
                         "one frame every period, until Ctrl-C/SIGTERM or the end of the script; then neutral\n"
                         "frames, drain, close. Ctrl-Z sends the neutral frames before stopping; after fg the\n"
                         "deadman needs a fresh press. SIGHUP (systemctl reload) rereads the config file (a regular\n"
                         "file only; one that was a pipe at start is not read again) and the mapping: neutral\n"
                         "frames, then a fresh deadman press. Flags override the config file.\n"
                         "With no port, frames go to a built-in simulated vehicle (sim).");
  opt->settings = std::make_unique<CommandLine>(*cmd, kRun);
  add_sdl_options(cmd, opt->sdl);
  cmd->callback([opt, &exit_code] { exit_code = run_bridge(*opt, RunHooks{}); });
}

}  // namespace andros::cli
