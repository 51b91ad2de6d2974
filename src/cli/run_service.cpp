#include "run_service.hpp"

#include <spdlog/fmt/fmt.h>

#include "andros/base/clock.hpp"
#include "andros/base/sink_text.hpp"

namespace andros::cli {

std::string service_status_line(const view::RunStatus& s) {
  std::string state;
  if (s.shutting_down()) state = "stopping: neutral frames";
  else if (s.enabled()) state = s.enable_text;
  else state = std::string(run::to_string(s.state)) + ": " + s.enable_text;
  std::string link = fmt::format("link {}: {}", s.link_name, link::to_string(s.link_state));
  if (!s.far_end_reading) link += " (neutral frames only: the server stalled)";
  else if (!s.link_detail.empty() && s.link_state != link::LinkState::kUp) link += " (" + s.link_detail + ")";
  return fmt::format("{}; {}; {}; {:g} Hz", s.robot, state, link, s.rate_hz);
}

void ServiceReporter::observe(const run::TickReport& report, const view::RunStatus& status) {
  if (!notifier_.active()) return;
  notifier_.watchdog(monotonic_ns());
  std::string line = service_status_line(status);
  if (!reload_failure_.empty()) line += "; " + reload_failure_;
  std::string message;
  if (!ready_ && report.result == link::SendResult::kSent && !report.shutting_down()) {
    ready_ = true;
    message = "READY=1\n";
  }
  if (line != status_) {
    status_ = line;
    // One line whatever a link's detail or a reload's error holds: a newline would start a field of its own.
    message += "STATUS=" + terminal_line(line);
  }
  if (!message.empty()) notifier_.send(message);
}

void ServiceReporter::reloading() { notifier_.send("RELOADING=1\nSTATUS=reloading"); }

void ServiceReporter::reloaded(std::string failure) {
  reload_failure_ = std::move(failure);
  status_.clear();  // the next tick says where things stand
  notifier_.send("READY=1");
}

void ServiceReporter::stopping() { notifier_.send("STOPPING=1"); }

}  // namespace andros::cli
