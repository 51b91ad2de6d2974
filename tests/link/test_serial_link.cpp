#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/file.h>
#include <sys/ioctl.h>
#include <sys/prctl.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>

#include "andros/base/clock.hpp"
#include "andros/link/pty_pair.hpp"
#include "andros/link/serial_link.hpp"
#include "support/frame_reader.hpp"

namespace andros::link {
namespace {

protocol::Frame test_frame(std::uint8_t drive) {
  protocol::ControlState s;
  s[protocol::signal_id("drive")] = drive;
  s[protocol::signal_id("pivot")] = 128;
  return protocol::encode(protocol::FrameBuilder(0x01).build(s));
}

/// Sends a frame every 10 ms until one is read back on fd or 2 s pass.
bool frame_gets_through(SerialLink& link, int fd, std::uint8_t drive) {
  test::FrameReader reader(fd);
  for (int i = 0; i < 200; ++i) {
    link.send(test_frame(drive), monotonic_ns());
    const auto got = reader.next(1, 10);
    if (!got.empty()) return got[0].valid && got[0].data[7] == drive;
  }
  return false;
}

TEST(SerialLink, WritesWholeFramesToAPty) {
  auto pty = open_pty_pair();
  SerialLink link(pty.path, 9600);
  EXPECT_EQ(link.state(), LinkState::kConnecting);
  for (std::uint8_t d = 100; d < 105; ++d) EXPECT_EQ(link.send(test_frame(d), monotonic_ns()), SendResult::kSent);
  EXPECT_EQ(link.state(), LinkState::kUp);
  test::FrameReader reader(pty.master.get());
  const auto frames = reader.next(5, 2000);
  ASSERT_EQ(frames.size(), 5u);
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_TRUE(frames[i].valid);
    EXPECT_EQ(frames[i].data[7], 100 + i);
  }
  EXPECT_EQ(link.counters().sent, 5u);
  link.drain_and_close(200);
  EXPECT_EQ(link.state(), LinkState::kConnecting);
}

std::string own_program_name() {
  std::ifstream in("/proc/self/comm");
  std::string name;
  std::getline(in, name);
  return name;
}

std::string own_pid_text() { return "(PID " + std::to_string(getpid()) + ")"; }

/// The message check_serial_port throws for path, or "" when it passes.
std::string check_message(const std::string& path) {
  try {
    check_serial_port(path, SourcePos{"andros.conf", 3, 12});
  } catch (const InputError& e) {
    EXPECT_EQ(e.pos().file, "andros.conf");
    EXPECT_EQ(e.pos().line, 3);
    EXPECT_EQ(e.pos().column, 12);
    return e.message();
  }
  return "";
}

/// While it lives, this process has the name a bridge has (/proc/PID/comm).
class NamedAsABridge {
 public:
  NamedAsABridge() {
    prctl(PR_GET_NAME, saved_.data());
    prctl(PR_SET_NAME, "andros-bridge");
  }
  ~NamedAsABridge() { prctl(PR_SET_NAME, saved_.data()); }
  NamedAsABridge(const NamedAsABridge&) = delete;
  NamedAsABridge& operator=(const NamedAsABridge&) = delete;

 private:
  std::array<char, 17> saved_{};
};

TEST(SerialLink, IsExclusiveAndNamesWhoHoldsThePort) {
  auto pty = open_pty_pair();
  SerialLink first(pty.path, 9600);
  SerialLink second(pty.path, 9600);
  ASSERT_EQ(first.send(test_frame(1), monotonic_ns()), SendResult::kSent);
  EXPECT_EQ(second.send(test_frame(2), monotonic_ns()), SendResult::kDown);
  EXPECT_EQ(second.detail(), "taken by " + own_program_name() + " " + own_pid_text());
  // Given back: the second link takes it at its next attempt, and says nothing of a holder.
  ASSERT_EQ(test::FrameReader(pty.master.get()).next(1, 2000).size(), 1u);  // the first link's frame
  first.drain_and_close(200);
  EXPECT_TRUE(frame_gets_through(second, pty.master.get(), 3));
  EXPECT_EQ(second.detail(), "");
}

TEST(CheckSerialPort, RefusesAPortAnotherBridgeHolds) {
  auto pty = open_pty_pair();
  const NamedAsABridge named;
  SerialLink first(pty.path, 9600);
  ASSERT_EQ(first.send(test_frame(1), monotonic_ns()), SendResult::kSent);
  EXPECT_EQ(check_message(pty.path), "serial port '" + pty.path + "' is in use by andros-bridge " + own_pid_text() +
                                         ": a second bridge is refused");
}

TEST(CheckSerialPort, RefusesAPortAnotherProgramLocks) {
  auto pty = open_pty_pair();
  const UniqueFd held(::open(pty.path.c_str(), O_RDWR | O_NOCTTY | O_CLOEXEC));
  ASSERT_EQ(flock(held.get(), LOCK_EX | LOCK_NB), 0);
  EXPECT_EQ(check_message(pty.path), "serial port '" + pty.path + "' is in use by " + own_program_name() + " " +
                                         own_pid_text() + ": the bridge will not share it");
}

TEST(CheckSerialPort, PassesAPortNobodyHolds) {
  auto pty = open_pty_pair();
  EXPECT_EQ(check_message(pty.path), "");
  EXPECT_EQ(check_message(pty.path), "");  // the check's own lock went with its descriptor
  SerialLink first(pty.path, 9600);
  ASSERT_EQ(first.send(test_frame(1), monotonic_ns()), SendResult::kSent);
  first.drain_and_close(200);
  EXPECT_EQ(check_message(pty.path), "");  // closed: its lock went with it
}

// A pseudo-terminal keeps TIOCEXCL after its last close, and would refuse
// every later open but root's, the bridge's own reopen included.
TEST(SerialLink, GivesUpExclusiveModeWhenItCloses) {
  auto pty = open_pty_pair();
  const auto exclusive_now = [&pty] {
    const UniqueFd fd(::open(pty.path.c_str(), O_RDWR | O_NOCTTY | O_CLOEXEC));
    if (!fd) return errno == EBUSY ? 1 : -1;  // refused by TIOCEXCL (all but root)
    int exclusive = -1;
    EXPECT_EQ(ioctl(fd.get(), TIOCGEXCL, &exclusive), 0);
    return exclusive;
  };
  {
    SerialLink link(pty.path, 9600);
    ASSERT_EQ(link.send(test_frame(1), monotonic_ns()), SendResult::kSent);
    EXPECT_EQ(exclusive_now(), 1);
    link.drain_and_close(200);
    EXPECT_EQ(exclusive_now(), 0);
    ASSERT_EQ(link.send(test_frame(2), monotonic_ns() + kNsPerSecond), SendResult::kSent);
  }
  EXPECT_EQ(exclusive_now(), 0);  // destroyed while open
}

TEST(SerialLink, RefusesSomethingThatIsNotATty) {
  const auto path = std::filesystem::temp_directory_path() / ("andros-not-a-tty-" + std::to_string(getpid()));
  std::fclose(std::fopen(path.c_str(), "w"));
  SerialLink link(path, 9600);
  EXPECT_EQ(link.send(test_frame(1), monotonic_ns()), SendResult::kDown);
  EXPECT_NE(link.detail().find("not a tty"), std::string::npos) << link.detail();
  std::filesystem::remove(path);
}

TEST(SerialLink, ResumesWhenTheSymlinkComesBackOnANewDevice) {
  const auto dir = std::filesystem::temp_directory_path() / ("andros-replug-" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const auto link_path = dir / "andros-switchbox";
  auto first = std::make_unique<PtyPair>(open_pty_pair());
  std::filesystem::create_symlink(first->path, link_path);

  SerialLink link(link_path, 9600);
  ASSERT_TRUE(frame_gets_through(link, first->master.get(), 10));

  // Unplug: the device goes away with its symlink.
  first.reset();
  std::filesystem::remove(link_path);
  SendResult result = SendResult::kSent;
  for (int i = 0; i < 10 && result == SendResult::kSent; ++i) result = link.send(test_frame(11), monotonic_ns());
  EXPECT_EQ(result, SendResult::kDown);
  EXPECT_EQ(link.state(), LinkState::kConnecting);
  EXPECT_EQ(link.counters().losses, 1u);

  // Replug: the same symlink now names another device.
  auto second = open_pty_pair();
  std::filesystem::create_symlink(second.path, link_path);
  EXPECT_TRUE(frame_gets_through(link, second.master.get(), 12));
  EXPECT_EQ(link.state(), LinkState::kUp);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace andros::link
