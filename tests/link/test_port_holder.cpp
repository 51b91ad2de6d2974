#include "andros/link/port_holder.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/file.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "andros/base/unique_fd.hpp"

namespace andros::link {
namespace {

const LockedFile kPts3{0x00, 0x1a, 3};

TEST(LockOwner, ReadsTheHolderOfALockOnTheFile) {
  EXPECT_EQ(lock_owner("1: FLOCK  ADVISORY  WRITE 1234 00:1a:3 0 EOF", kPts3), 1234);
  EXPECT_EQ(lock_owner("12: POSIX  ADVISORY  READ 77 00:1a:3 0 EOF", kPts3), 77);
  // The device's numbers are hex, the inode decimal.
  EXPECT_EQ(lock_owner("3: FLOCK  ADVISORY  WRITE 9 fe:101:4294967302 0 EOF", {0xfe, 0x101, 4294967302U}), 9);
}

TEST(LockOwner, IgnoresOtherFilesWaitersAndUnknownOwners) {
  EXPECT_EQ(lock_owner("1: FLOCK  ADVISORY  WRITE 1234 00:1a:4 0 EOF", kPts3), std::nullopt);   // another inode
  EXPECT_EQ(lock_owner("1: FLOCK  ADVISORY  WRITE 1234 00:1b:3 0 EOF", kPts3), std::nullopt);   // another file system
  EXPECT_EQ(lock_owner("1: -> FLOCK  ADVISORY  WRITE 55 00:1a:3 0 EOF", kPts3), std::nullopt);  // waiting, not holding
  EXPECT_EQ(lock_owner("1: OFDLCK ADVISORY  WRITE -1 00:1a:3 0 EOF", kPts3), std::nullopt);     // OFD: no PID
  EXPECT_EQ(lock_owner("1: FLOCK  ADVISORY  WRITE 0 00:1a:3 0 EOF", kPts3), std::nullopt);      // another namespace's
  EXPECT_EQ(lock_owner("", kPts3), std::nullopt);
  EXPECT_EQ(lock_owner("1: FLOCK  ADVISORY  WRITE 1234 00:1a 0 EOF", kPts3), std::nullopt);
  EXPECT_EQ(lock_owner("FLOCK  ADVISORY  WRITE 1234 00:1a:3 0 EOF", kPts3), std::nullopt);
  EXPECT_EQ(lock_owner("1: FLOCK  ADVISORY  WRITE 12x4 00:1a:3 0 EOF", kPts3), std::nullopt);
}

std::string own_program_name() {
  std::ifstream in("/proc/self/comm");
  std::string name;
  std::getline(in, name);
  return name;
}

TEST(PortHolder, FindsThisProcessHoldingAFlock) {
  const auto path = std::filesystem::temp_directory_path() / ("andros-holder-" + std::to_string(getpid()));
  std::fclose(std::fopen(path.c_str(), "w"));
  EXPECT_EQ(find_port_holder(path).pid, 0);
  {
    const UniqueFd fd(::open(path.c_str(), O_RDWR | O_CLOEXEC));
    ASSERT_EQ(flock(fd.get(), LOCK_EX | LOCK_NB), 0);
    const PortHolder holder = find_port_holder(path);
    EXPECT_EQ(holder.pid, getpid());
    EXPECT_EQ(holder.program, own_program_name());
  }
  EXPECT_EQ(find_port_holder(path).pid, 0);  // released with its descriptor
  std::filesystem::remove(path);
  EXPECT_EQ(find_port_holder(path).pid, 0);  // gone
}

TEST(PortHolder, IsDescribedByNameAndPid) {
  EXPECT_EQ(describe(PortHolder{1234, "andros-bridge"}), "andros-bridge (PID 1234)");
  EXPECT_EQ(describe(PortHolder{1234, ""}), "another program (PID 1234)");
  EXPECT_EQ(describe(PortHolder{}), "another program");
}

}  // namespace
}  // namespace andros::link
