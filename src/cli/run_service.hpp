#pragma once
// `run` under a service manager (docs/running.md "As a service"): what it is
// told, from the run loop's own thread, so that a loop that stops ticking
// stops the watchdog pings.

#include <string>

#include "andros/base/service_notify.hpp"
#include "andros/run/bridge.hpp"
#include "andros/view/operator_screens.hpp"

namespace andros::cli {

class ServiceReporter {
 public:
  explicit ServiceReporter(ServiceNotifier notifier) : notifier_(std::move(notifier)) {}

  /// False when not run by a service manager: observe() would do nothing.
  [[nodiscard]] bool active() const { return notifier_.active(); }

  /// After each tick: WATCHDOG=1 when due, READY=1 once the link has taken
  /// the first frame, STATUS= when the one-line state changes.
  void observe(const run::TickReport& report, const view::RunStatus& status);
  /// RELOADING=1, before a reload's settings are read.
  void reloading();
  /// READY=1 after a reload; `failure` is why it kept the old settings ("" when it did not).
  void reloaded(std::string failure);
  /// STOPPING=1, after the neutral frames.
  void stopping();

 private:
  ServiceNotifier notifier_;
  bool ready_ = false;
  std::string status_;
  std::string reload_failure_;  ///< shown in STATUS= until the next reload
};

/// The one line: "ROBOT; enabled (or why not); link NAME: STATE; N Hz".
std::string service_status_line(const view::RunStatus& status);

}  // namespace andros::cli
