#include "run_status.hpp"

#include <spdlog/spdlog.h>

namespace andros::cli {
namespace {

constexpr const char* kNeutralOnly = "neutral frames only: the server stalled and has not been seen reading since";

}  // namespace

void RunStatusBoard::observe(const io::TickReport& r) {
  const auto now = io::monotonic_ns();
  io::RunStatus next;
  {
    const std::lock_guard lock(mutex_);
    if (r.result == io::SendResult::kSent) timing_.add(now);
    next = status_;
    next.t_ms = r.t_ms;
    next.sent = *r.data;
    next.shutting_down = r.shutting_down;
    next.connected = r.input->connected();
    if (next.connected) next.controller = r.input->name().empty() ? "controller" : r.input->name();
    next.enabled = frames_.enabled() && !r.shutting_down && !r.reloading;
    next.enable_text = r.reloading ? "reloading the settings" : frames_.enable_text();
    next.layer = frames_.layer();
    next.link_state = link_.state();
    next.motion_allowed = link_.motion_allowed();
    next.link_detail = next.motion_allowed ? link_.detail() : kNeutralOnly;
    next.link = link_.counters();
    next.sent_timing = timing_.summary(now);
    std::swap(status_, next);  // next now holds the previous status
  }
  log_changes(next, status_);
  if (r.skipped > 0) spdlog::warn("clock stalled: {} tick(s) skipped, none sent late in a burst", r.skipped);
  first_tick_ = false;
}

void RunStatusBoard::log_changes(const io::RunStatus& before, const io::RunStatus& after) const {
  if (after.shutting_down) {
    if (!before.shutting_down) spdlog::info("stopping: sending neutral frames");
    return;
  }
  if (before.motion_allowed != after.motion_allowed) {
    if (after.motion_allowed) spdlog::info("link {}: the server is reading again: frames follow the controller", after.link_name);
    else spdlog::warn("link {}: {}", after.link_name, kNeutralOnly);
  }
  if (first_tick_ || before.connected != after.connected) {
    if (after.connected) spdlog::info("controller: {}", after.controller);
    else spdlog::info("controller: none connected");
  }
  if (first_tick_ || before.enabled != after.enabled || before.enable_text != after.enable_text) {
    if (after.enabled) spdlog::info("{}", after.enable_text);
    else spdlog::info("not enabled: {}", after.enable_text);
  }
  if (!first_tick_ && before.layer != after.layer) {
    spdlog::info("layer: {}", after.layer.empty() ? "base" : after.layer);
  }
}

std::string RunStatusBoard::compose() const {
  io::RunStatus s = snapshot();
  if (vehicle_ != nullptr) s.vehicle = vehicle_->snapshot();
  return io::render_run_view(s, true);
}

void RunStatusBoard::set_robot(std::string robot) {
  const std::lock_guard lock(mutex_);
  status_.robot = std::move(robot);
}

io::RunStatus RunStatusBoard::snapshot() const {
  const std::lock_guard lock(mutex_);
  return status_;
}

}  // namespace andros::cli
