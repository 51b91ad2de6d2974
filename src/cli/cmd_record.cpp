// `andros-bridge record`: the live controller's events as an event script.
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <ctime>
#include <memory>
#include <ostream>

#include "andros/base/error.hpp"
#include "andros/base/output_file.hpp"
#include "andros/base/shutdown_request.hpp"
#include "andros/base/sink_text.hpp"
#include "andros/base/text_file.hpp"
#include "andros/base/version.hpp"
#include "andros/cli/command_line.hpp"
#include "andros/input/script_recorder.hpp"
#include "commands.hpp"
#include "sdl_options.hpp"

namespace andros::cli {
namespace {

struct RecordCommandOptions {
  input::SdlInputOptions sdl;
  std::unique_ptr<CommandLine> settings;  ///< the settings table's flags
};

std::string utc_now() {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return text;
}

int record(const Settings& settings, input::SdlInput& input, ShutdownRequest& stop) {
  const std::string& output = settings.script_output;
  OutputFile file(output, nullptr, OutputFile::NewFile::kAsWritten);  // a killed recording keeps what it saw
  std::ostream& out = file.stream();

  input::RecordOptions rec;
  rec.period_ms = 1000 / settings.read_rate_hz;
  rec.header = "andros-bridge " + std::string(kVersion) + " record, started " + utc_now() +
               "\ncontroller: " + input.selection() +
               (input.supervised() ? "\nsupervisor: " + input.supervisor_selection() : std::string()) +
               "\nt_ms    event       arguments";

  const bool progress = isatty(STDERR_FILENO) == 1;
  std::int64_t last_progress_ms = -1000;
  const auto show_progress = [&](const input::RecordStatus& s) {
    last_progress_ms = s.t_ms;
    std::fprintf(stderr, "\rrecording %.1f s, %lld events, controller %s%s (Ctrl-C ends)\033[K",
                 static_cast<double>(s.t_ms) / 1000.0, static_cast<long long>(s.events),
                 s.connected ? "connected" : "not connected",
                 !input.supervised()      ? ""
                 : s.supervisor_connected ? ", supervisor connected"
                                          : ", supervisor not connected");
  };
  const auto keep_going = [&](const input::RecordStatus& s) {
    if (progress && s.t_ms - last_progress_ms >= 500) show_progress(s);
    return out.good();  // a full disk ends it: nothing more would be kept
  };
  input::RecordStatus ended;
  try {
    ended = input::record_script(input, out, rec, stop, keep_going);
  } catch (const RuntimeError&) {
    file.check();  // the write's own reason (a full disk) first
    throw;
  }
  file.commit();
  if (progress) {
    show_progress(ended);
    std::fputc('\n', stderr);
  }
  if (ended.at_limit)
    std::fprintf(stderr, "the recording reached 24 h, the longest script 'replay' and 'run' take: ended there\n");
  std::fprintf(stderr, "recorded %lld events%s%s\n", static_cast<long long>(ended.events), output == "-" ? "" : " to ",
               output == "-" ? "" : terminal_text(output).c_str());
  return kExitOk;
}

int run_record(const RecordCommandOptions& opt) {
  const Settings settings = resolve_settings(*opt.settings);
  // Blocked before SDL starts its threads, so that every thread inherits the mask.
  ShutdownRequest stop(kRecordShutdownSignals);
  try {
    // SDL first (bad selection or mapping file: exit 2 before any file is made).
    input::SdlInputOptions sdl = opt.sdl;
    sdl.supervisor = settings.supervisor;
    sdl.supervisor_pos = settings.supervisor_pos;
    input::SdlInput input(sdl, [&stop] { return stop.requested(); });
    return record(settings, input, stop);
  } catch (const ReadStopped&) {
    std::fprintf(stderr, "stopped (SIG%s) while reading the controller database, before recording\n",
                 sigabbrev_np(stop.signal_number()));
    return kExitOk;
  }
}

}  // namespace

void add_record_command(CLI::App& app, int& exit_code) {
  auto opt = std::make_shared<RecordCommandOptions>();
  auto* cmd = app.add_subcommand("record",
                                 "Write the live controller's events as an event script (the text replay and\n"
                                 "'run --input' read) until SIGINT (Ctrl-C) or SIGTERM, then end it with 'T end'.\n"
                                 "Times are ms from the start of the recording.");
  opt->settings = std::make_unique<CommandLine>(*cmd, kRecord);
  add_sdl_options(cmd, opt->sdl);
  cmd->callback([opt, &exit_code] { exit_code = run_record(*opt); });
}

}  // namespace andros::cli
