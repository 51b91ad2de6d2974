// A CPU-time limit met with neutral frames (andros/base/cpu_limit.hpp): run
// lowers its soft limit under the hard one, so that the kernel's SIGXCPU (a
// stop) comes before its SIGKILL. Issue 34: `ulimit -t 5` sets soft = hard,
// and the run was killed mid-drive with a motion frame last on the wire.
#include "andros/base/cpu_limit.hpp"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace andros {
namespace {

TEST(CpuLimit, TheSoftLimitComesBeforeTheHardOne) {
  // bash's `ulimit -t 5`: soft = hard.
  EXPECT_EQ(lowered_cpu_soft_limit(5, 5), 3u);
  EXPECT_EQ(lowered_cpu_soft_limit(std::nullopt, 100), 98u);  // only a hard limit
  EXPECT_EQ(lowered_cpu_soft_limit(99, 100), 98u);
  // Already low enough, or no limit at all: left as it is.
  EXPECT_EQ(lowered_cpu_soft_limit(10, 100), std::nullopt);
  EXPECT_EQ(lowered_cpu_soft_limit(std::nullopt, std::nullopt), std::nullopt);
  EXPECT_EQ(lowered_cpu_soft_limit(7, std::nullopt), std::nullopt);
  // A short hard limit keeps half of it.
  EXPECT_EQ(lowered_cpu_soft_limit(3, 3), 2u);
  EXPECT_EQ(lowered_cpu_soft_limit(2, 2), 1u);
  EXPECT_EQ(lowered_cpu_soft_limit(1, 1), std::nullopt);  // no whole second to give
}

/// The soft limit a child process has after keep_room_before_cpu_kill(), under soft = hard = seconds.
rlim_t soft_after(rlim_t seconds) {
  int pipe_fds[2];
  if (pipe(pipe_fds) != 0) return 0;
  const pid_t child = fork();
  if (child == 0) {
    rlimit limit{seconds, seconds};
    setrlimit(RLIMIT_CPU, &limit);
    (void)keep_room_before_cpu_kill();
    getrlimit(RLIMIT_CPU, &limit);
    (void)!write(pipe_fds[1], &limit.rlim_cur, sizeof limit.rlim_cur);
    _exit(0);
  }
  close(pipe_fds[1]);
  rlim_t soft = 0;
  if (read(pipe_fds[0], &soft, sizeof soft) != sizeof soft) soft = 0;
  close(pipe_fds[0]);
  int status = 0;
  waitpid(child, &status, 0);
  return soft;
}

TEST(CpuLimit, ThisProcessLowersItsOwnSoftLimit) {
  EXPECT_EQ(soft_after(600), 598u);
  EXPECT_EQ(soft_after(5), 3u);
}

}  // namespace
}  // namespace andros
