#include "run_reload.hpp"

#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <exception>
#include <stdexcept>
#include <utility>

#include "andros/mapping/engine.hpp"
#include "andros/mapping/loader.hpp"

namespace andros::cli {

namespace {

/// Whether any input the mapping reads is a game-controller name (the deadman, a layer key, a binding's input or arm).
bool reads_pad_names(const mapping::Mapping& m) {
  const auto pad = [](const mapping::InputUse& u) {
    return u.key.kind == input::InputKind::kPadButton || u.key.kind == input::InputKind::kPadAxis;
  };
  if (m.deadman && pad(*m.deadman)) return true;
  for (const auto& layer : m.layers) {
    if (pad(layer.input)) return true;
  }
  for (const auto ref : mapping::all_bindings(m)) {
    const auto& b = mapping::binding_at(m, ref);
    if (std::any_of(b.inputs.begin(), b.inputs.end(), pad) || (b.arm && pad(*b.arm))) return true;
  }
  return false;
}

}  // namespace

EngineSetup load_engine(const Settings& settings) {
  auto mapping = mapping::load_chosen_mapping(settings.mapping, settings.robot);
  EngineSetup setup;
  setup.robot = mapping->robot.value_or(settings.robot);
  setup.mapping_file = mapping->file;
  setup.center = mapping->center;
  setup.feedback = mapping->feedback;
  setup.supervisor_buttons = mapping->supervisor.has_value();
  setup.pad_names = reads_pad_names(*mapping);
  setup.sources = record::read_mapping_sources(mapping->chain);
  setup.frames = std::make_shared<mapping::Engine>(
      std::move(mapping), mapping::EngineOptions{.weapons = settings.weapons, .code = settings.code});
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
  note("rate", fmt::format("{:g}", static_cast<double>(running.rate.millihertz) / timing::kMillihertzPerHz),
       fmt::format("{:g}", static_cast<double>(fresh.rate.millihertz) / timing::kMillihertzPerHz));
  note("input", running.input, fresh.input);
  note("supervisor", running.supervisor, fresh.supervisor);
  if (changed.empty()) return {};
  return changed + ": a reload changes the robot, mapping and weapons only; restart the bridge for these";
}

ReloadResult read_reload(const GivenFlags& flags, const Settings& running, const std::string& mapping) {
  ReloadResult result;
  try {
    Settings fresh;
    if (!running.config_stream.empty()) {
      // Read once at start and drained since: read again, it would be an
      // empty file, and the robot and mapping would silently become the defaults.
      fresh = running;
      result.note = fmt::format("config {} was {} at start: not read again; mapping reread", running.config_file,
                                running.config_stream);
    } else {
      fresh = resolve_settings(flags, ConfigRead::kReload);
      if (auto why = needs_restart(running, fresh); !why.empty()) throw std::runtime_error(why);
    }
    if (!mapping.empty()) fresh.mapping = mapping;
    result.setup = load_engine(fresh);
    result.settings = std::move(fresh);
  } catch (const std::exception& e) {
    result.error = e.what();
  }
  return result;
}

ReloadWorker::~ReloadWorker() {
  if (!thread_.joinable()) return;
  bool done = false;
  {
    const std::lock_guard lock(state_->mutex);
    done = state_->result.has_value();
    state_->queued.reset();
  }
  // Joined only when it has ended: a read stuck in a file system must not hold the exit.
  if (done) thread_.join();
  else thread_.detach();
}

void ReloadWorker::work(const std::shared_ptr<State>& state, Task task) {
  while (true) {
    ReloadResult result;
    try {
      result = task();
    } catch (const std::exception& e) {
      result = ReloadResult{};
      result.error = e.what();
    } catch (...) {
      result = ReloadResult{};
      result.error = "unknown error";
    }
    const std::lock_guard lock(state->mutex);
    if (state->queued) {
      // Asked again while this one read: what it read may be older than the files now.
      task = std::move(*state->queued);
      state->queued.reset();
      continue;
    }
    state->result = std::move(result);
    return;
  }
}

bool ReloadWorker::start(Task task) {
  if (thread_.joinable()) {
    const std::lock_guard lock(state_->mutex);
    if (!state_->result) {
      state_->queued = std::move(task);
      return false;
    }
    // Ended, its result not taken yet: it is older than this request.
  }
  if (thread_.joinable()) thread_.join();
  state_ = std::make_shared<State>();
  // The thread inherits the loop's blocked signals: none of them is delivered to it.
  thread_ = std::thread(work, state_, std::move(task));
  return true;
}

std::optional<ReloadResult> ReloadWorker::poll() {
  if (!thread_.joinable()) return std::nullopt;
  std::optional<ReloadResult> result;
  {
    const std::lock_guard lock(state_->mutex);
    if (!state_->result) return std::nullopt;
    result = std::move(state_->result);
  }
  thread_.join();  // it has set its result and only returns
  state_.reset();
  return result;
}

ReloadOutcome apply_reload(ReloadResult result, const ReloadTargets& to) {
  if (!result.note.empty()) spdlog::info("{}", result.note);
  if (!result.settings) {
    ReloadOutcome out{false, "reload (SIGHUP) failed, the old settings stay: " + result.error};
    // Several errors of the files, a log line each (a log line is one line).
    for (std::string_view rest = out.message; !rest.empty();) {
      const auto nl = rest.find('\n');
      spdlog::error("{}", rest.substr(0, nl));
      rest.remove_prefix(nl == std::string_view::npos ? rest.size() : nl + 1);
    }
    to.service.reloaded("reload failed: " + result.error);
    return out;
  }
  EngineSetup& setup = result.setup;
  to.feedback.set_table(setup.feedback);
  to.settings = std::move(*result.settings);
  to.board.set_mapping(setup.robot, setup.mapping_file, to.settings.weapons, setup.center);
  to.board.set_pad_names(setup.pad_names);
  ReloadOutcome out{true,
                    fmt::format("reloaded (SIGHUP): mapping {}{}; not enabled until the deadman is pressed again",
                                setup.mapping_file, to.settings.weapons ? ", WEAPONS ENABLED" : ""),
                    to.settings.weapons, std::move(setup.frames)};
  spdlog::info("{}", out.message);
  to.service.reloaded("");
  return out;
}

void RunReload::begin(const std::string& mapping) {
  // The worker reads copies: the flags, and the settings as they are now.
  if (worker_.start(
          [flags = flags_, running = to_.settings, mapping] { return read_reload(flags, running, mapping); })) {
    to_.service.reloading();
  } else {
    spdlog::info("reload (SIGHUP) while a reload is being read: the files are read again once that read ends");
  }
}

std::optional<ReloadOutcome> RunReload::finish() {
  auto result = worker_.poll();
  if (!result) return std::nullopt;
  if (result->settings) {
    const EngineSetup& s = result->setup;
    applied_ = Applied{s.robot, s.mapping_file, s.center, s.sources};
  }
  return apply_reload(std::move(*result), to_);
}

}  // namespace andros::cli
