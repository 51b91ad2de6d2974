#include "andros/link/pty_pair.hpp"

#include <fcntl.h>
#include <pty.h>

#include <cerrno>
#include <cstring>

#include "andros/base/error.hpp"
#include "andros/link/serial_link.hpp"
#include "andros/protocol/frame.hpp"

namespace andros::link {

PtyPair open_pty_pair() {
  int master = -1;
  int slave = -1;
  char name[256] = {};
  if (openpty(&master, &slave, name, nullptr, nullptr) != 0) {
    throw RuntimeError(std::string("cannot open a pseudo-terminal: ") + std::strerror(errno));
  }
  PtyPair pair{UniqueFd(master), UniqueFd(slave), name};
  fcntl(master, F_SETFD, FD_CLOEXEC);
  fcntl(slave, F_SETFD, FD_CLOEXEC);
  configure_raw_8n1(master, protocol::kSwitchboxBaud);
  return pair;
}

}  // namespace andros::link
