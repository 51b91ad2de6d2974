#pragma once
// `run`'s flight recorder (docs/recording.md): a session file per run in the
// state folder, fed from the loop's input, controls and reports, written by
// a thread of its own. Whatever befalls it (no folder, a full or stalled
// disk) is logged and counted; it never stops or delays the run.

#include <memory>
#include <string>

#include "andros/cli/settings.hpp"
#include "andros/input/input_source.hpp"
#include "andros/link/link.hpp"
#include "andros/record/recorded_loop.hpp"
#include "andros/record/recorder.hpp"
#include "andros/view/operator_screens.hpp"
#include "run_reload.hpp"
#include "session_files.hpp"

namespace andros::cli {

class RunRecording {
 public:
  /// The session of this run, started: null when config says not to record,
  /// or when the session cannot be created (said in the log). Rotates the
  /// folder's older sessions first. Call before the loop's thread starts.
  static std::unique_ptr<RunRecording> start(const Settings& config, const EngineSetup& engine, const link::Link& link,
                                             input::InputSource& input);

  /// The input the loop must read: the real one, with what it applies recorded.
  input::InputSource& input() { return input_; }
  /// The loop's controls, recorded; reload's settings are asked after an ok reload.
  run::RunControl control(run::RunControl inner, const Settings& config, const RunReload& reload);
  void observe(const run::TickReport& report);
  /// A record the command adds (the trainer's course after the header, its score before the end).
  void add(std::string payload) { recorder_.add(std::move(payload)); }
  /// After the run: the end record, the writer closed (a stalled disk is
  /// waited for a second at most), the closing line logged, the folder rotated.
  void finish(const std::string& why);

  /// For the status screen (any thread): the session, or what was dropped.
  void describe(view::RunStatus& status) const;

  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

  RunRecording(std::filesystem::path path, std::unique_ptr<record::RecordSink> sink, input::InputSource& input,
               RotationLimits rotation);

 private:
  std::filesystem::path path_;
  record::SessionWriter writer_;
  record::Recorder recorder_;
  record::RecordingInput input_;
  RotationLimits rotation_;
  bool warned_ = false;  ///< the first record dropped or lost has been logged
};

}  // namespace andros::cli
