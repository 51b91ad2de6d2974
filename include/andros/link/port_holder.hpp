#pragma once
/// Who holds a serial port, so that a refusal (at start) or a port taken
/// during the run can name the process: "andros-bridge (PID 1234)".
///
/// Read from /proc/locks. The link locks its port with flock(2), which other
/// programs and the flock(1) tool respect but which has no call that tells
/// the holder; the kernel lists every flock with its owner's PID in
/// /proc/locks, and reading it needs no open of the port (another holder's
/// TIOCEXCL refuses one). The alternatives give less: an OFD lock's owner
/// reads as PID -1 (F_OFD_GETLK and /proc/locks alike); a classic POSIX
/// record lock (F_GETLK) needs the port open, and the process loses it on
/// any close of the device, by any of its descriptors; a UUCP lock file
/// (/run/lock/LCK..ttyUSB0) needs a directory that is often not writable by
/// the user, and goes stale when its writer dies. The PID shown is the one
/// that took the lock; a holder in another PID namespace (a container) is
/// shown to us as 0, which reads as "another program".

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace andros::link {

/// A process holding a port. pid 0: not known.
struct PortHolder {
  int pid = 0;
  std::string program;  ///< its name (/proc/PID/comm, printable ASCII only); empty when not known
};

/// The file a lock is on, as /proc/locks names it: the device of the file
/// system that holds the node (st_dev) and its inode number.
struct LockedFile {
  unsigned dev_major = 0;
  unsigned dev_minor = 0;
  std::uint64_t inode = 0;
};

/// The owner's PID if line (one line of /proc/locks) is a lock held (not one
/// waited for) on file, with a PID that is known (> 0); nullopt otherwise.
std::optional<int> lock_owner(std::string_view line, const LockedFile& file);

/// Who holds a lock on the file at path now (a symlink is followed); {} when
/// no lock is listed, or /proc/locks cannot be read.
PortHolder find_port_holder(const std::string& path);

/// The holder for a message: "andros-bridge (PID 1234)", "another program
/// (PID 1234)" when its name cannot be read, "another program" when not known.
std::string describe(const PortHolder& holder);

/// The name andros-bridge runs under, as /proc/PID/comm shows it.
inline constexpr std::string_view kBridgeProgram = "andros-bridge";

}  // namespace andros::link
