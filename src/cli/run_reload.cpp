#include "run_reload.hpp"

#include <spdlog/fmt/fmt.h>

#include "andros/mapping/engine.hpp"
#include "andros/mapping/loader.hpp"
#include "andros/run/engine_frames.hpp"

namespace andros::cli {

EngineSetup load_engine(const Settings& settings) {
  auto mapping = mapping::load_chosen_mapping(settings.mapping, settings.robot);
  EngineSetup setup;
  setup.robot = mapping->robot.value_or(settings.robot);
  setup.mapping_file = mapping->file;
  setup.center = mapping->center;
  setup.feedback = mapping->feedback;
  setup.frames = run::make_engine_frames(
      mapping::Engine(std::move(mapping), mapping::EngineOptions{.weapons = settings.weapons, .code = settings.code}));
  return setup;
}

std::string needs_restart(const Settings& running, const Settings& fresh) {
  std::string changed;
  const auto note = [&changed](const char* key, const std::string& from, const std::string& to) {
    if (from == to) return;
    changed += fmt::format("{}{} {} -> {}", changed.empty() ? "" : ", ", key, from, to);
  };
  note("serialport", running.port, fresh.port);
  note("baudrate", std::to_string(running.baud), std::to_string(fresh.baud));
  note("code", fmt::format("{:02X}", running.code), fmt::format("{:02X}", fresh.code));
  note("rate", fmt::format("{:g}", static_cast<double>(running.rate.millihertz) / 1000.0),
       fmt::format("{:g}", static_cast<double>(fresh.rate.millihertz) / 1000.0));
  note("input", running.input, fresh.input);
  if (changed.empty()) return {};
  return changed + ": a reload changes the robot, mapping and weapons only; restart the bridge for these";
}

}  // namespace andros::cli
