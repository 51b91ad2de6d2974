// JobControlSignals: Ctrl-Z as a request the loop answers, then a stop of the
// whole process. Each case runs in a forked child (a stopped test binary would
// hang the suite), which reports through its exit code; the parent sees every
// stop with waitpid(WUNTRACED), so nothing here waits on a clock.
#include "andros/base/job_control.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <functional>

namespace andros {
namespace {

using Event = JobControlSignals::Event;
using Stop = JobControlSignals::Stop;

/// The child's exit codes: 0 when every step went as expected, else the step that did not.
constexpr int kAsked = 1;     // poll() did not see the Ctrl-Z
constexpr int kOutcome = 2;   // stop_process() said the wrong thing
constexpr int kLeftOver = 3;  // a signal already answered was still there to poll

/// Runs body in a child process with its own JobControlSignals; returns the child's pid.
pid_t fork_child(const std::function<int(JobControlSignals&)>& body) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    JobControlSignals job;
    ::_exit(body(job));
  }
  return pid;
}

/// The child's next change: stopped or ended (waitpid's status).
int next_change(pid_t pid) {
  int status = 0;
  EXPECT_EQ(::waitpid(pid, &status, WUNTRACED), pid);
  return status;
}

/// Ends a child that stopped where it should not have, and reaps it.
void end_stopped(pid_t pid) {
  ::kill(pid, SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
}

/// Ctrl-Z, seen by the loop's poll; the neutral frames would go out next.
int ctrl_z(JobControlSignals& job) {
  ::raise(SIGTSTP);
  return job.poll() == Event::kStopAsked && job.stop_signal() == SIGTSTP ? 0 : kAsked;
}

/// The child stops once, goes on at SIGCONT, and exits 0 without stopping again.
void expect_stops_once_then_ends_well(pid_t pid) {
  ASSERT_GT(pid, 0);
  const int stopped = next_change(pid);
  ASSERT_TRUE(WIFSTOPPED(stopped)) << "ended without stopping, status " << stopped;
  EXPECT_EQ(WSTOPSIG(stopped), SIGSTOP);
  ::kill(pid, SIGCONT);
  const int ended = next_change(pid);
  if (WIFSTOPPED(ended)) end_stopped(pid);
  ASSERT_FALSE(WIFSTOPPED(ended)) << "stopped a second time";
  ASSERT_TRUE(WIFEXITED(ended)) << "status " << ended;
  EXPECT_EQ(WEXITSTATUS(ended), 0);
}

TEST(JobControlSignals, ACtrlZStopsTheProcessUntilItIsContinued) {
  const pid_t pid = fork_child([](JobControlSignals& job) {
    if (const int bad = ctrl_z(job)) return bad;
    if (job.stop_process() != Stop::kStopped) return kOutcome;
    return job.poll() == Event::kNone ? 0 : kLeftOver;  // the SIGCONT was answered by returning
  });
  expect_stops_once_then_ends_well(pid);
}

// `kill -TSTP; sleep 0.08; kill -CONT`: the SIGCONT lands during the neutral
// frames, before the process stops itself. Stopping then would clear it and
// stop the process for good (and SIGTERM, blocked, would never end it).
TEST(JobControlSignals, ASigcontDuringTheNeutralFramesMeansItDoesNotStop) {
  const pid_t pid = fork_child([](JobControlSignals& job) {
    if (const int bad = ctrl_z(job)) return bad;
    ::raise(SIGCONT);
    if (job.stop_process() != Stop::kContinuedBeforeStop) return kOutcome;
    return job.poll() == Event::kNone ? 0 : kLeftOver;  // the SIGCONT was answered, not a resume to come
  });
  ASSERT_GT(pid, 0);
  const int status = next_change(pid);
  if (WIFSTOPPED(status)) end_stopped(pid);
  ASSERT_FALSE(WIFSTOPPED(status)) << "stopped although continued before the stop";
  ASSERT_TRUE(WIFEXITED(status)) << "status " << status;
  EXPECT_EQ(WEXITSTATUS(status), 0);
}

TEST(JobControlSignals, ASecondCtrlZDuringTheNeutralFramesIsAnsweredByTheOneStop) {
  const pid_t pid = fork_child([](JobControlSignals& job) {
    if (const int bad = ctrl_z(job)) return bad;
    ::raise(SIGTSTP);
    if (job.stop_process() != Stop::kStopped) return kOutcome;
    return job.poll() == Event::kNone ? 0 : kLeftOver;
  });
  expect_stops_once_then_ends_well(pid);
}

// The last word counts: a Ctrl-Z after the SIGCONT asks for the stop again.
TEST(JobControlSignals, ACtrlZAfterTheSigcontStillStops) {
  const pid_t pid = fork_child([](JobControlSignals& job) {
    if (const int bad = ctrl_z(job)) return bad;
    ::raise(SIGCONT);
    ::raise(SIGTSTP);
    if (job.stop_process() != Stop::kStopped) return kOutcome;
    return job.poll() == Event::kNone ? 0 : kLeftOver;
  });
  expect_stops_once_then_ends_well(pid);
}

}  // namespace
}  // namespace andros
