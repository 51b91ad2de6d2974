#pragma once
/// A serial device (USB adapter, UART, or a pseudo-terminal): raw 8N1, no flow
/// control, opened exclusively (flock and TIOCEXCL). On a write error the
/// device is closed and the same path (a udev symlink survives a replug) is
/// reopened every 200 ms. While another program holds it, detail() names that
/// program: "taken by picocom (PID 1234)".

#include "andros/base/error.hpp"
#include "andros/link/reconnecting_link.hpp"

namespace andros::link {

inline constexpr int kSerialRetryMs = 200;

class SerialLink final : public ReconnectingLink {
 public:
  SerialLink(std::string path, int baud);
  ~SerialLink() override;
  SerialLink(const SerialLink&) = delete;
  SerialLink& operator=(const SerialLink&) = delete;

 protected:
  OpenResult open_step(std::int64_t now_ns, std::string& why) override;
  int queued_bytes() const override;
  void finish_drain() override;
  void close_fd() override;

 private:
  std::string path_;
  int baud_;
};

/// Start-up check of a serial port path, so that a mistyped port is bad
/// input (exit 2) rather than a link retried for ever: a path that exists but
/// is not a terminal device (a file, /dev/null), or that this user may not open, throws
/// InputError at pos. So does a port that another program holds (another
/// bridge's lock, or its TIOCEXCL), naming it: "... is in use by andros-bridge
/// (PID 1234): a second bridge is refused". A path that does not exist yet
/// passes: the adapter may be plugged in after the bridge starts, and the link
/// waits for it.
void check_serial_port(const std::string& path, const SourcePos& pos);

/// Puts an open tty into raw 8N1 at baud with no flow control. Returns false
/// with errno set on failure. Shared by the link and `monitor`.
bool configure_raw_8n1(int fd, int baud);

}  // namespace andros::link
