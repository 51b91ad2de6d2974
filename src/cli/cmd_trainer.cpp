// `andros-bridge trainer`: `run`'s loop (the same pad, mapping, safety rules,
// state machine, recorder and status view) with the link always the
// simulated vehicle, whose frames drive a vehicle model shown on a local
// web page (docs/trainer.md). It never opens a serial port or a TCP link.
#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include <atomic>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <semaphore>
#include <string>
#include <thread>

#include "andros/base/error.hpp"
#include "andros/base/text.hpp"
#include "andros/cli/command_line.hpp"
#include "andros/cli/settings.hpp"
#include "andros/record/session.hpp"
#include "andros/run/operating_state.hpp"
#include "andros/trainer/course_file.hpp"
#include "andros/trainer/course_score.hpp"
#include "andros/trainer/trainer_feed.hpp"
#include "andros/trainer/trainer_page.hpp"
#include "andros/trainer/trainer_replay.hpp"
#include "andros/trainer/trainer_server.hpp"
#include "andros/vehicle/robot_figures.hpp"
#include "commands.hpp"
#include "run_bridge.hpp"
#include "sdl_options.hpp"
#include "session_files.hpp"

namespace andros::cli {
namespace {

struct TrainerOptions {
  RunOptions run;
  std::string listen;        ///< --listen ADDR:PORT; empty: 127.0.0.1 and the default port
  bool exit_at_end = false;  ///< --exit-at-end: no page kept up after the script
  std::string session;       ///< --session NAME: a recorded session replayed as motion, no loop at all
  std::string course;        ///< --course NAME|FILE; empty: open ground
  std::size_t clients = trainer::HubLimits{}.max_clients;
};

/// What the trainer sets up around `run`'s loop, alive for the whole run.
class Trainer {
 public:
  explicit Trainer(const TrainerOptions& opt) : opt_(opt) {}
  ~Trainer() { stop_motion(); }
  Trainer(const Trainer&) = delete;
  Trainer& operator=(const Trainer&) = delete;

  RunHooks hooks() {
    RunHooks h;
    h.check = [this](const Settings& config) { check(config); };
    h.input = [this](input::InputSource& inner) -> input::InputSource& {
      input_.emplace(inner, *feed_);
      return *input_;
    };
    h.start = [this](const Settings&) { return start(); };
    h.observe = [this](const run::TickReport& r, const view::RunStatusBoard& board) { observe(r, board); };
    h.after_run = [this](ShutdownRequest& stop) { after_run(stop); };
    if (!opt_.course.empty()) {
      h.opening_record = [this] {
        return record::payload::course({course_->course.name, course_->path, course_->text});
      };
      h.closing_record = [this] { return record::payload::score(last_t_ms_, trainer::score_json(scorer_->score())); };
    }
    return h;
  }

 private:
  /// A trainee must never move a real vehicle believing it is the simulator:
  /// any port but the simulated vehicle is refused, whoever set it.
  void check(const Settings& config) {
    if (config.port != kSimPort) {
      throw InputError(config.port_pos, "the trainer drives only its simulated vehicle: port '" +
                                            printable_text(config.port) +
                                            "' refused (use 'andros-bridge run' for a real link)");
    }
    listen_ = opt_.listen.empty() ? trainer::ListenAddress{} : trainer::parse_listen(opt_.listen, {"--listen"});
    hub_ = std::make_unique<trainer::StreamHub>(trainer::HubLimits{.max_clients = opt_.clients});
    const auto& figures = vehicle::figures_for(config.robot);
    std::optional<vehicle::Course> course;
    if (!opt_.course.empty()) {
      course_ = trainer::load_course(opt_.course);
      course = course_->course;
      scorer_.emplace(figures, course_->course);
    }
    feed_ = std::make_unique<trainer::TrainerFeed>(figures, *hub_, course);
  }

  /// The server, on a thread of its own; its failure never stops driving.
  std::string start() {
    motion_ = std::thread([this] { move(); });
    if (!listen_.loopback()) {
      spdlog::warn("the trainer's page listens on {}, not only this machine: whoever reaches it sees the vehicle",
                   listen_.host_header());
    }
    server_ =
        std::make_unique<trainer::TrainerServer>(trainer::ServerOptions{.listen = listen_}, *hub_,
                                                 trainer::trainer_page(), [this] { return feed_->state_with_trail(); });
    std::string why;
    if (!server_->start(&why)) {
      spdlog::error("trainer: {}: no page, driving goes on (--listen ADDR:PORT for another port)", why);
      server_.reset();
      return "simulated vehicle only; no page: " + why;
    }
    spdlog::info("trainer: the simulated vehicle's page is at {}", listen_.url());
    return "simulated vehicle only; page " + listen_.url();
  }

  void observe(const run::TickReport& r, const view::RunStatusBoard& board) {
    // The state's words change seldom: formed only when the state or its text does.
    if (r.state != last_state_ || r.tick % kWordsEveryTicks == 0) {
      const auto status = board.status();
      words_ = view::state_words(status);
      layer_ = status.layer;
      last_state_ = r.state;
    }
    last_tick_ = r.tick;
    last_t_ms_ = r.t_ms;
    // The vehicle gets what the session records: the frame the link took, at its tick's time.
    const bool delivered = r.delivered();
    feed_->queue_tick(r.t_ms, r.data, delivered);
    wake_.release();
    observe_course(r);
    feed_->observe(trainer::LoopFacts{.tick = r.tick,
                                      .t_ms = r.t_ms,
                                      .state = words_,
                                      .state_name = std::string(run::to_string(r.state)),
                                      .layer = layer_,
                                      .sent = delivered,
                                      .pad = {},  // the pad: the feed's own, from the input's pump
                                      .score = score_});
  }

  // --- The course's score (docs/trainer.md, "The score") ---

  /// Each tick into the scorer, on the loop's thread (the frames at their
  /// ticks' times: the same session gives the same score); the page's copy of
  /// the score made again every few ticks.
  void observe_course(const run::TickReport& r) {
    if (!scorer_) return;
    scorer_->on_tick(r);
    if (r.tick % kWordsEveryTicks == 0) score_ = trainer::score_json(scorer_->score());
  }

  /// The score on the terminal when the input has ended, and on the page.
  void print_score() {
    if (!scorer_) return;
    const auto score = scorer_->score();
    score_ = trainer::score_json(score);
    std::fputs(trainer::score_text(score).c_str(), stdout);
    std::fflush(stdout);
  }

  /// The motion thread: the loop's ticks into the model as they come (the
  /// loop wakes it; at least every kMotionEvery), until stop_motion().
  void move() {
    while (!motion_stop_.load()) {
      (void)wake_.try_acquire_for(kMotionEvery);
      feed_->take_ticks();
    }
  }

  /// Ends the motion thread, then takes what the loop queued after its last turn.
  void stop_motion() {
    if (motion_.joinable()) {
      motion_stop_.store(true);
      wake_.release();
      motion_.join();
    }
    if (feed_) feed_->take_ticks();
  }

  void after_run(ShutdownRequest& stop) {
    stop_motion();
    // Where the vehicle ended, to the bit: a replay of the session says the same (docs/trainer.md).
    spdlog::info("trainer: the vehicle {}", feed_->summary());
    if (const auto lost = feed_->lost_ticks(); lost != 0) {
      spdlog::warn("trainer: {} ticks found the model's queue full: the model is not the session's", lost);
    }
    print_score();
    if (opt_.exit_at_end || !server_ || stop.requested()) return;
    spdlog::info("trainer: the input has ended; the page stays up at {} until Ctrl-C", listen_.url());
    // The page shows where the vehicle ended, and says the run is over (not "shutting down" for ever).
    feed_->observe(trainer::LoopFacts{.tick = last_tick_,
                                      .t_ms = last_t_ms_,
                                      .state = "INPUT ENDED: the page stays up until Ctrl-C",
                                      .state_name = "ended",
                                      .layer = "",
                                      .pad = {},
                                      .score = score_});
    feed_->republish();
    stop.sleep_until(kNoDeadline);
  }

  static constexpr std::chrono::milliseconds kMotionEvery{100};
  /// The state's words are formed again at least this often (the enable text's countdowns).
  static constexpr std::int64_t kWordsEveryTicks = 5;

  const TrainerOptions& opt_;
  trainer::ListenAddress listen_;
  std::unique_ptr<trainer::StreamHub> hub_;
  std::unique_ptr<trainer::TrainerFeed> feed_;
  std::optional<trainer::CourseFile> course_;
  std::optional<trainer::CourseScorer> scorer_;  ///< the loop's thread's
  std::string score_;                            ///< the latest score, as JSON ("" without a course)
  std::optional<trainer::WatchedInput> input_;
  std::unique_ptr<trainer::TrainerServer> server_;
  std::optional<run::OpState> last_state_;
  std::string words_;
  std::string layer_;
  std::int64_t last_tick_ = -1;
  std::int64_t last_t_ms_ = 0;
  std::thread motion_;
  std::counting_semaphore<> wake_{0};
  std::atomic<bool> motion_stop_{false};
};

/// `trainer --session NAME`: the session's frames as the vehicle's motion
/// on the page (docs/trainer.md, "Replaying a session"). No loop, no link,
/// no mapping or course of this machine: the session alone, read as verify
/// reads it.
int replay_session(const TrainerOptions& opt) {
  for (const auto& row : settings_table()) {
    if ((row.commands & kRun) != 0 && opt.run.settings->given(flag_name(row))) {
      throw InputError(SourcePos{std::string(flag_name(row))},
                       "not with --session: the session is replayed with what it recorded");
    }
  }
  if (!opt.course.empty()) {
    throw InputError(SourcePos{"--course"}, "not with --session: a session is replayed on the course it recorded");
  }
  auto checked = record::read_checked_session(opt.session);
  if (checked.unreadable) throw *checked.unreadable;
  const auto& verdict = checked.verdict;
  std::string note;
  if (!verdict.intact) {
    note = fmt::format("NOT INTACT: {}: the {} records before it replayed, not evidence (andros-bridge verify)",
                       verdict.problem, verdict.records);
  } else if (verdict.cut_short_line != 0) {
    note = record::cut_short_text(verdict);
  }
  if (!note.empty()) spdlog::warn("{}", note);
  const trainer::SessionReplay replay(std::move(*checked.session), note);
  spdlog::info("trainer: the session's vehicle {}", trainer::trail_summary(replay.motion().end()));
  if (opt.exit_at_end) return kExitOk;

  ShutdownRequest stop(kRunShutdownSignals);  // before the server's threads: they inherit the blocked signals
  const auto listen = opt.listen.empty() ? trainer::ListenAddress{} : trainer::parse_listen(opt.listen, {"--listen"});
  if (!listen.loopback()) {
    spdlog::warn("the trainer's page listens on {}, not only this machine: whoever reaches it sees the vehicle",
                 listen.host_header());
  }
  trainer::StreamHub hub(trainer::HubLimits{.max_clients = opt.clients});
  trainer::TrainerServer server(trainer::ServerOptions{.listen = listen}, hub, trainer::trainer_page(),
                                [&replay] { return replay.end_state(); });
  server.add_json("/replay", [&replay](const trainer::TrainerServer::Params&, std::string*) {
    return std::optional(replay.replay_json());
  });
  server.add_json("/motion", [&replay](const trainer::TrainerServer::Params& params, std::string* why) {
    const auto t = params.find("t");
    double seconds = -1;
    if (t != params.end()) {
      const auto& text = t->second;
      const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), seconds);
      if (ec != std::errc() || end != text.data() + text.size()) seconds = -1;
    }
    if (!std::isfinite(seconds) || seconds < 0 || seconds > static_cast<double>(record::kMaxSessionMs) / 1000) {
      *why = "/motion?t=SECONDS: the time in the session, 0 or more";
      return std::optional<std::string>();
    }
    return std::optional(replay.state_at(std::llround(seconds * 1000)));
  });
  std::string why;
  if (!server.start(&why)) throw RuntimeError("trainer: " + why + " (--listen ADDR:PORT for another port)");
  spdlog::info("trainer: the session's replay is at {} until Ctrl-C", server.address().url());
  stop.sleep_until(kNoDeadline);
  return kExitOk;
}

}  // namespace

void add_trainer_command(CLI::App& app, int& exit_code) {
  auto opt = std::make_shared<TrainerOptions>();
  auto* cmd = app.add_subcommand(
      "trainer",
      "The trainer: 'run' with the link always the built-in simulated vehicle, whose frames drive a\n"
      "model of the robot shown on a local web page (http://127.0.0.1:" +
          std::to_string(trainer::kDefaultPort) +
          "/ by default; docs/trainer.md): the same pad,\n"
          "mapping, safety rules and status view. A port other than sim (flag or config file) is refused.\n"
          "After an event script ends the page stays up until Ctrl-C (--exit-at-end: not).");
  opt->run.settings = std::make_unique<CommandLine>(*cmd, kRun);
  // `run`'s row says where frames may go; the trainer takes only one place
  // (wrapped by hand, as the settings table's help is).
  cmd->get_option("--port")
      ->description(
          "where frames go: only sim, the built-in simulated vehicle (the default); a serial\n"
          "device or a TCP link, here or in the config file, is refused")
      ->type_name("sim")
      ->default_str("");
  add_sdl_options(cmd, opt->run.sdl);
  cmd->add_option("--listen", opt->listen,
                  "Serve the page on ADDR:PORT (default 127.0.0.1:" + std::to_string(trainer::kDefaultPort) +
                      "); any address but 127.0.0.1 is warned about: whoever reaches it sees the vehicle")
      ->type_name("ADDR:PORT");
  cmd->add_flag("--exit-at-end", opt->exit_at_end,
                "End when the event script ends (no page kept up): for tests; with --session, once\n"
                "the session's motion is computed (its end printed)");
  cmd->add_option("--session", opt->session,
                  "Replay a recorded session (any: a trainer run or a real drive; its bare name as\n"
                  "'sessions' prints it) as the vehicle's motion, with play, pause, speed and a time\n"
                  "slider on the page: no link, no loop, nothing read but the session (docs/trainer.md)")
      ->type_name("NAME");
  cmd->add_option(
         "--course", opt->course,
         "A training course: a shipped one by NAME (basic, stairs, car, weapons) or a course FILE\n"
         "(docs/trainer.md, \"Courses\"); walls stop the vehicle, the page draws the course, the score ends the run")
      ->type_name("NAME|FILE");
  cmd->callback([opt, &exit_code] {
    if (!opt->session.empty()) {
      opt->session = find_session(opt->session);  // a bare session name, as `sessions` prints it
      exit_code = replay_session(*opt);
      return;
    }
    Trainer trainer(*opt);
    exit_code = run_bridge(opt->run, trainer.hooks());
  });
}

}  // namespace andros::cli
