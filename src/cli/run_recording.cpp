#include "run_recording.hpp"

#include <spdlog/spdlog.h>
#include <unistd.h>

#include <ctime>
#include <filesystem>

#include "andros/base/error.hpp"
#include "andros/base/version.hpp"

namespace andros::cli {
namespace {

namespace fs = std::filesystem;

record::SessionSettings session_settings(const Settings& config, const std::string& robot,
                                         const std::string& mapping_file, int center,
                                         std::vector<record::MappingSource> sources) {
  record::SessionSettings s;
  s.robot = robot;
  s.mapping_file = mapping_file;
  s.rate_millihertz = config.rate.millihertz;
  s.weapons = config.weapons;
  s.code = config.code;
  s.center = center;
  s.port = config.port;
  s.baud = config.baud;
  s.input = config.input;
  s.config = config.config_file;
  s.sources = std::move(sources);
  return s;
}

std::string local_time_text(std::time_t now) {
  std::tm local{};
  localtime_r(&now, &local);
  char text[40];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%S%z", &local);
  return text;
}

std::string host_name() {
  char name[256] = {};
  if (gethostname(name, sizeof name - 1) != 0) return "?";
  return name;
}

}  // namespace

RunRecording::RunRecording(fs::path path, std::unique_ptr<record::RecordSink> sink, input::InputSource& input,
                           RotationLimits rotation)
    : path_(std::move(path)),
      writer_(std::move(sink)),
      recorder_(writer_),
      input_(input, recorder_),
      rotation_(rotation) {}

std::unique_ptr<RunRecording> RunRecording::start(const Settings& config, const EngineSetup& engine,
                                                  const link::Link& link, input::InputSource& input) {
  if (!config.record) return nullptr;
  const fs::path dir = session_dir(config.record_dir);
  const std::time_t now = std::time(nullptr);
  const fs::path path = new_session_path(dir, now, static_cast<long>(getpid()));
  const RotationLimits limits{static_cast<std::uint64_t>(config.record_max_mb) * 1'000'000ULL,
                              static_cast<std::int64_t>(config.record_max_days) * 24 * 3600};
  std::unique_ptr<record::RecordSink> sink;
  try {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) throw RuntimeError(dir.string() + ": cannot create: " + ec.message());
    for (const auto& old : rotate_sessions(dir, limits, path, now))
      spdlog::info("recorder: removed {} (rotation)", old.string());
    sink = std::make_unique<record::FileRecordSink>(path.string());
  } catch (const std::exception& e) {
    // Driving goes on without a record: said loudly, once.
    spdlog::warn("recorder: {}: this run is not recorded", e.what());
    return nullptr;
  }
  auto rec = std::make_unique<RunRecording>(path, std::move(sink), input, limits);
  auto settings = session_settings(config, engine.robot, engine.mapping_file, engine.center, engine.sources);
  settings.supervised = input.supervised();
  rec->recorder_.header(kVersion, local_time_text(now), static_cast<long>(getpid()), host_name(), settings,
                        link.status());
  spdlog::info("recording to {}", path.string());
  return rec;
}

run::RunControl RunRecording::control(run::RunControl inner, const Settings& config, const RunReload& reload) {
  return record::recorded_control(std::move(inner), recorder_, [this, &config, &reload] {
    const auto& applied = reload.applied();
    auto settings = session_settings(config, applied.robot, applied.mapping_file, applied.center, applied.sources);
    settings.supervised = input_.supervised();
    return settings;
  });
}

void RunRecording::observe(const run::TickReport& report) {
  recorder_.observe(report);
  if (!warned_ && (writer_.dropped() != 0 || writer_.lost() != 0)) {
    warned_ = true;
    const auto error = writer_.error();
    spdlog::warn("recorder: records dropped ({}): the session {} is incomplete; driving goes on",
                 error.empty() ? "the disk is not keeping up" : error, path_.string());
  }
}

void RunRecording::describe(view::RunStatus& status) const {
  const auto missing = writer_.dropped() + writer_.lost();
  status.recorder_failing = missing != 0;
  if (missing == 0) {
    status.recorder = path_.string();
    return;
  }
  const auto error = writer_.error();
  status.recorder = std::to_string(missing) + " records dropped (" +
                    (error.empty() ? "the disk is not keeping up" : error) + "): " + path_.filename().string() +
                    " is incomplete";
}

void RunRecording::finish(const std::string& why) {
  recorder_.end(why);
  const bool whole = writer_.close(1000);
  if (whole) {
    spdlog::info("recorded {} records to {} (last hash {})", writer_.written(), path_.string(), writer_.last_hash());
  } else {
    const auto error = writer_.error();
    spdlog::warn("recorder: {} records dropped, {} lost{}: {} is incomplete", writer_.dropped(), writer_.lost(),
                 error.empty() ? "" : " (" + error + ")", path_.string());
  }
  for (const auto& old : rotate_sessions(path_.parent_path(), rotation_, path_, std::time(nullptr))) {
    spdlog::info("recorder: removed {} (rotation)", old.string());
  }
}

}  // namespace andros::cli
