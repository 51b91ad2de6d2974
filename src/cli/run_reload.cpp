#include "run_reload.hpp"

#include <spdlog/fmt/fmt.h>

namespace andros::cli {

std::string needs_restart(const RunConfig& running, const RunConfig& fresh) {
  std::string changed;
  const auto note = [&changed](const char* key, const std::string& from, const std::string& to) {
    if (from == to) return;
    changed += fmt::format("{}{} {} -> {}", changed.empty() ? "" : ", ", key, from, to);
  };
  note("serialport", running.port, fresh.port);
  note("baudrate", std::to_string(running.baud), std::to_string(fresh.baud));
  note("code", fmt::format("{:02X}", running.code), fmt::format("{:02X}", fresh.code));
  note("rate", fmt::format("{:g}", static_cast<double>(rate_millihertz(running)) / 1000.0),
       fmt::format("{:g}", static_cast<double>(rate_millihertz(fresh)) / 1000.0));
  note("input", running.input, fresh.input);
  if (changed.empty()) return {};
  return changed + ": a reload changes the robot, mapping and weapons only; restart the bridge for these";
}

}  // namespace andros::cli
