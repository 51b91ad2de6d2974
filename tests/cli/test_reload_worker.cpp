// A reload read off the loop's thread (docs/running.md "As a service",
// reload): what it reads, what it refuses, and a worker whose poll() never
// waits. No clock: a gate the test opens says when a task may end.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <atomic>
#include <condition_variable>
#include <filesystem>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "andros/cli/command_line.hpp"
#include "cli/run_reload.hpp"
#include "support/temp_dir.hpp"

namespace andros::cli {
namespace {

/// What a task waits for: the test opens it.
class Gate {
 public:
  void open() {
    {
      const std::lock_guard lock(mutex_);
      open_ = true;
    }
    changed_.notify_all();
  }
  void wait() {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [this] { return open_; });
  }

 private:
  std::mutex mutex_;
  std::condition_variable changed_;
  bool open_ = false;
};

/// A result that names itself, in its error text.
ReloadResult named(const std::string& name) {
  ReloadResult r;
  r.error = name;
  return r;
}

/// poll() until the worker gives its result: a bounded wait for the thread,
/// no assertion on how long it took.
ReloadResult wait_for(ReloadWorker& worker) {
  for (int i = 0; i < 20'000; ++i) {
    if (auto r = worker.poll()) return std::move(*r);
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ADD_FAILURE() << "the worker gave no result";
  return {};
}

TEST(ReloadWorker, PollNeverWaitsWhileTheTaskRuns) {
  auto gate = std::make_shared<Gate>();
  ReloadWorker worker;
  EXPECT_FALSE(worker.poll());  // none started
  ASSERT_TRUE(worker.start([gate] {
    gate->wait();
    return named("done");
  }));
  // The task cannot end before the gate opens: a poll() that waited for it would never return.
  for (int i = 0; i < 100; ++i) ASSERT_FALSE(worker.poll());
  EXPECT_TRUE(worker.busy());
  gate->open();
  EXPECT_EQ(wait_for(worker).error, "done");
  EXPECT_FALSE(worker.poll()) << "the result is given once";
  EXPECT_FALSE(worker.busy());
}

TEST(ReloadWorker, AStartWhileATaskRunsReadsAgainAfterItAndGivesOnlyTheLast) {
  auto gate = std::make_shared<Gate>();
  std::atomic<int> first_runs = 0;
  std::atomic<int> last_runs = 0;
  ReloadWorker worker;
  ASSERT_TRUE(worker.start([gate, &first_runs] {
    ++first_runs;
    gate->wait();
    return named("first");
  }));
  EXPECT_FALSE(worker.start([] { return named("dropped: replaced by the next start"); }));
  EXPECT_FALSE(worker.start([&last_runs] {
    ++last_runs;
    return named("last");
  }));
  EXPECT_FALSE(worker.poll());
  gate->open();
  EXPECT_EQ(wait_for(worker).error, "last");
  EXPECT_EQ(first_runs, 1);
  EXPECT_EQ(last_runs, 1);
  EXPECT_FALSE(worker.poll());
}

TEST(ReloadWorker, ATaskThatThrowsIsAnErrorResult) {
  ReloadWorker worker;
  worker.start([]() -> ReloadResult { throw std::runtime_error("disk on fire"); });
  const auto r = wait_for(worker);
  EXPECT_FALSE(r.settings);
  EXPECT_EQ(r.error, "disk on fire");
}

TEST(ReloadWorker, AStuckTaskDoesNotHoldItsWorkersEnd) {
  auto gate = std::make_shared<Gate>();
  auto ended = std::make_shared<std::atomic<bool>>(false);
  {
    ReloadWorker worker;
    worker.start([gate, ended] {
      gate->wait();
      *ended = true;
      return named("late");
    });
  }  // a destructor that joined would wait here for ever
  EXPECT_FALSE(*ended);
  gate->open();  // the detached thread ends on its own, with its own copies
  for (int i = 0; i < 20'000 && !*ended; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  EXPECT_TRUE(*ended);
}

/// `run`'s flags parsed from a command line, copied as a reload takes them.
GivenFlags run_flags(const std::string& args) {
  CLI::App app;
  const CommandLine flags(app, kRun);
  app.parse(args, false);
  return flags.given_flags();
}

constexpr const char* kPlain = "robot: HD1\ndeadman: leftshoulder\nbindings:\n  - analog: drive\n    axis: lefty\n";

class ReloadRead : public ::testing::Test {
 protected:
  testing::TempDir dir_;
  std::string conf_ = (dir_.path() / "bridge.conf").string();
  std::string mapping_ = dir_.write("plain.yaml", kPlain).string();
};

TEST_F(ReloadRead, ARegularConfigIsReadAgainWithTheFlagsOverIt) {
  dir_.write("bridge.conf", "mapping=plain.yaml\n");
  const auto flags = run_flags("--config " + conf_ + " --code 3c");
  const Settings running = resolve_settings(flags, ConfigRead::kStart);
  dir_.write("bridge.conf", "mapping=plain.yaml\nweapons=enabled\n");
  const auto r = read_reload(flags, running);
  ASSERT_TRUE(r.settings) << r.error;
  EXPECT_TRUE(r.settings->weapons);
  EXPECT_EQ(r.settings->code, 0x3C);
  EXPECT_EQ(r.setup.mapping_file, mapping_);
  EXPECT_NE(r.setup.frames, nullptr);
  EXPECT_EQ(r.note, "");
}

TEST_F(ReloadRead, AConfigReplacedByAFifoIsRefusedWithoutWaiting) {
  dir_.write("bridge.conf", "mapping=plain.yaml\n");
  const auto flags = run_flags("--config " + conf_);
  const Settings running = resolve_settings(flags, ConfigRead::kStart);
  std::filesystem::remove(conf_);
  ASSERT_EQ(::mkfifo(conf_.c_str(), 0600), 0);  // no writer: a read would wait for one for ever
  const auto r = read_reload(flags, running);
  EXPECT_FALSE(r.settings);
  EXPECT_EQ(r.error, conf_ + ": error: is a pipe, not a regular file");
  std::filesystem::remove(conf_);
  std::filesystem::create_directory(conf_);
  EXPECT_EQ(read_reload(flags, running).error, conf_ + ": error: is a directory, not a regular file");
}

TEST_F(ReloadRead, AConfigThatWasAPipeAtStartIsNotReadAgainButTheMappingIs) {
  int fds[2];
  ASSERT_EQ(::pipe(fds), 0);
  const std::string text = "mapping=" + mapping_ + "\nweapons=enabled\n";
  ASSERT_EQ(::write(fds[1], text.data(), text.size()), static_cast<ssize_t>(text.size()));
  ::close(fds[1]);
  const std::string pipe_path = "/dev/fd/" + std::to_string(fds[0]);
  const auto flags = run_flags("--config " + pipe_path);
  const Settings running = resolve_settings(flags, ConfigRead::kStart);
  ::close(fds[0]);
  EXPECT_EQ(running.config_file, pipe_path);
  EXPECT_EQ(running.config_stream, "a pipe");
  dir_.write("plain.yaml", std::string(kPlain).replace(7, 3, "WOLVERINE"));
  const auto r = read_reload(flags, running);
  ASSERT_TRUE(r.settings) << r.error;
  EXPECT_EQ(r.note, "config " + pipe_path + " was a pipe at start: not read again; mapping reread");
  // The start's settings, not the defaults an empty file would give.
  EXPECT_TRUE(r.settings->weapons);
  EXPECT_EQ(r.settings->mapping, mapping_);
  EXPECT_EQ(r.setup.robot, "WOLVERINE");  // the mapping was read again
}

TEST_F(ReloadRead, RefusesWhatNeedsARestartAndABadFile) {
  dir_.write("bridge.conf", "mapping=plain.yaml\n");
  const auto flags = run_flags("--config " + conf_);
  const Settings running = resolve_settings(flags, ConfigRead::kStart);
  dir_.write("bridge.conf", "mapping=plain.yaml\ncode=3C\n");
  EXPECT_EQ(read_reload(flags, running).error,
            "code 01 -> 3C: a reload changes the robot, mapping and weapons only; restart the bridge for these");
  dir_.write("bridge.conf", "weapons=disabled\nmapping=plain.yaml\nweapons=enabled\n");
  EXPECT_EQ(read_reload(flags, running).error, conf_ + ":3:1: error: key 'weapons' given twice (first at line 1)");
}

class NoInput final : public input::InputSource {
 public:
  void pump(input::TickInput& /*input*/, std::int64_t /*now_ms*/) override {}
  [[nodiscard]] bool finished(std::int64_t /*now_ms*/) const override { return false; }
};

std::optional<ReloadOutcome> wait_for(RunReload& reload) {
  for (int i = 0; i < 20'000; ++i) {
    if (auto out = reload.finish()) return out;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return std::nullopt;
}

TEST_F(ReloadRead, RunReloadSwapsOnTheCallersThreadOnlyWhenFinishGivesTheOutcome) {
  dir_.write("bridge.conf", "mapping=plain.yaml\n");
  const auto flags = run_flags("--config " + conf_);
  Settings settings = resolve_settings(flags, ConfigRead::kStart);
  NoInput input;
  run::FeedbackNotifier feedback({}, input);
  view::RunStatusBoard board(view::RunStatus{});
  ServiceReporter service{ServiceNotifier{}};
  RunReload reload(flags, ReloadTargets{settings, feedback, board, service});

  dir_.write("bridge.conf", "mapping=plain.yaml\nweapons=enabled\n");
  reload.begin();
  EXPECT_FALSE(settings.weapons) << "swapped before finish()";
  const auto ok = wait_for(reload);
  ASSERT_TRUE(ok);
  EXPECT_TRUE(ok->ok) << ok->message;
  EXPECT_EQ(ok->message, "reloaded (SIGHUP): mapping " + mapping_ +
                             ", WEAPONS ENABLED; not enabled until the deadman is pressed again");
  ASSERT_TRUE(ok->frames) << "the new frame source, for the loop to take";
  EXPECT_EQ(ok->frames->mapping().file, mapping_);
  EXPECT_TRUE(settings.weapons);
  EXPECT_TRUE(board.status().weapons);
  EXPECT_EQ(board.status().mapping_file, mapping_);
  EXPECT_FALSE(reload.finish()) << "the outcome is given once";

  dir_.write("bridge.conf", "mapping=plain.yaml\nrobot=R2D2\n");
  reload.begin();
  const auto bad = wait_for(reload);
  ASSERT_TRUE(bad);
  EXPECT_FALSE(bad->ok);
  EXPECT_NE(bad->message.find("reload (SIGHUP) failed, the old settings stay: " + conf_ + ":2:7: error: unknown robot"),
            std::string::npos)
      << bad->message;
  EXPECT_FALSE(bad->frames) << "the old frame source stays";
  EXPECT_TRUE(settings.weapons);
}

}  // namespace
}  // namespace andros::cli
