#pragma once
// The engine `run` drives, made from the settings: at start and again on
// `systemctl reload` (SIGHUP, docs/running.md), which swaps it between
// neutral frames. A reload's files are read by a worker thread, so that the
// loop keeps ticking (and pinging the watchdog) however long they take.

#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "andros/cli/command_line.hpp"
#include "andros/cli/settings.hpp"
#include "andros/mapping/feedback.hpp"
#include "andros/record/session.hpp"
#include "andros/run/bridge.hpp"
#include "andros/run/feedback.hpp"
#include "andros/view/status_board.hpp"
#include "run_service.hpp"

namespace andros::cli {

/// What the settings' mapping gives the run: the frame source and what the
/// view and the rumble need from the mapping.
struct EngineSetup {
  std::shared_ptr<mapping::FrameSource> frames;
  std::string robot;                     ///< its robot type (the settings' when the mapping names none)
  std::string mapping_file;              ///< the file loaded
  int center = mapping::kDefaultCenter;  ///< drive and pivot's rest value (for the gauges)
  bool pad_names = true;                 ///< it reads game-controller names (a plain joystick sends none)
  mapping::FeedbackTable feedback;
  bool supervisor_buttons = false;             ///< the mapping has a `supervisor:` section
  std::vector<record::MappingSource> sources;  ///< the mapping's files as read, for the flight recorder
};

/// Loads the mapping the settings name and builds its engine. Throws
/// InputError for a bad mapping.
EngineSetup load_engine(const Settings& settings);

/// A reload changes the mapping (robot, mapping) and weapons. The port, baud,
/// code, rate, input and supervisor are the link's, the clock's and the
/// controllers': changing them needs a restart. Returns what changed among those ("" for nothing), for the refusal.
std::string needs_restart(const Settings& running, const Settings& fresh);

/// What a reload read: fresh settings and the engine they make, or why the
/// old ones stay.
struct ReloadResult {
  std::optional<Settings> settings;  ///< set when the reload may be applied
  EngineSetup setup;
  std::string note;   ///< said before "reloaded" ("config PATH was a pipe at start: ..."); "" for none
  std::string error;  ///< why it was refused, when settings is unset
};

/// Reads what a reload takes: the config file again (a regular file only;
/// the flags still override it), or, when the config was not a regular file
/// at start (`--config <(...)`: drained, it would read as empty), the
/// start's settings; then the mapping. A file that is not a regular one, a
/// bad line or mapping, or a change that needs a restart is an error result.
/// Reads only its arguments and the files, logs nothing: safe on a thread of
/// its own.
/// mapping: an event script's `reload MAPPING` (run --input), read instead
/// of the configured one; "" for the configured one.
ReloadResult read_reload(const GivenFlags& flags, const Settings& running, const std::string& mapping = "");

/// Runs a reload's reading on a thread of its own. start() returns at once;
/// poll() never waits. Nothing the worker runs may touch the loop's objects:
/// a task reads copies and returns a fresh result, and the swap is the
/// caller's, on the loop's thread.
class ReloadWorker {
 public:
  using Task = std::function<ReloadResult()>;

  ReloadWorker() = default;
  /// A task still running (a file system that does not answer) is left to
  /// end with the process: its thread holds only its own copies.
  ~ReloadWorker();
  ReloadWorker(const ReloadWorker&) = delete;
  ReloadWorker& operator=(const ReloadWorker&) = delete;

  /// Starts task on a thread of its own; true. While a task runs, the new one
  /// is queued instead (false): it runs once the running one ends, whose
  /// result is then dropped, so that the result poll() gives is of files read
  /// after the last start (a later start replaces a task already queued).
  bool start(Task task);
  /// Never waits: nullopt while a task runs (or none was started), then the
  /// last task's result, once. An exception out of a task is an error result.
  std::optional<ReloadResult> poll();
  /// A task runs, or its result waits for poll().
  [[nodiscard]] bool busy() const { return thread_.joinable(); }

 private:
  /// Shared with the thread, which may outlive the worker.
  struct State {
    std::mutex mutex;
    std::optional<Task> queued;
    std::optional<ReloadResult> result;  ///< set when the thread is done
  };
  static void work(const std::shared_ptr<State>& state, Task task);

  std::shared_ptr<State> state_;
  std::thread thread_;
};

/// How a reload ended, for the loop: ok false when the old settings stay;
/// message is the line logged.
using ReloadOutcome = run::ReloadOutcome;

/// What a reload swaps besides the frame source (the loop takes that from
/// the outcome), all owned by `run` and used on the loop's thread.
struct ReloadTargets {
  Settings& settings;
  run::FeedbackNotifier& feedback;
  view::RunStatusBoard& board;
  ServiceReporter& service;
};

/// On the loop's thread: swaps in what an ok result read (rumble
/// table, settings, the board's robot and mapping) or keeps the old settings;
/// logs the outcome, tells the service manager (READY=1, or the failure in
/// STATUS=) and returns it (with the new frame source, for the loop).
ReloadOutcome apply_reload(ReloadResult result, const ReloadTargets& to);

/// `run`'s reload as the loop calls it, on the loop's thread: begin() when a
/// reload starts (RELOADING=1; the worker reads, and begin returns at once),
/// then finish() once a tick (never waits): nullopt while the worker reads,
/// then the outcome, applied, once. A begin() while a reload is being read
/// (a second SIGHUP) reads the files again once the running read ends, and
/// only that read is applied (so the outcome is of the files as they were
/// after the last SIGHUP).
class RunReload {
 public:
  RunReload(GivenFlags flags, const ReloadTargets& targets) : flags_(std::move(flags)), to_(targets) {}

  void begin(const std::string& mapping = "");
  std::optional<ReloadOutcome> finish();

  /// What the last reload that was applied put in place (the flight recorder's).
  struct Applied {
    std::string robot;
    std::string mapping_file;
    int center = mapping::kDefaultCenter;
    std::vector<record::MappingSource> sources;
  };
  [[nodiscard]] const Applied& applied() const { return applied_; }

 private:
  GivenFlags flags_;
  ReloadTargets to_;
  ReloadWorker worker_;
  Applied applied_;
};

}  // namespace andros::cli
