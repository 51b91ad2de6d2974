#pragma once
/// The run loop: on every tick of an absolute-time clock, pump the input,
/// compute the frame, send it; on a stop request or the end of the input,
/// send neutral frames at the normal period, drain and close the link. A
/// suspend request (job control) sends the same neutral frames, then pauses;
/// a reload request sends them, swaps the settings, and starts afresh.

#include <cstdint>
#include <functional>
#include <string>

#include "andros/input/input_source.hpp"
#include "andros/input/snapshot.hpp"
#include "andros/link/link.hpp"
#include "andros/mapping/engine_status.hpp"
#include "andros/protocol/frame.hpp"
#include "andros/timing/tick_schedule.hpp"

namespace andros::run {

/// One step's result, by value: the frame and the engine's state after it.
struct Step {
  protocol::DataBytes data{};
  mapping::EngineStatus status;
};

/// What computes the frames: the mapping engine in `run`, a fixed frame in
/// the benchmarks and tests.
class FrameSource {
 public:
  virtual ~FrameSource() = default;
  /// The frame for the tick at now_ms (ms since start) from this input.
  virtual Step step(const input::InputState& input, std::int64_t now_ms) = 0;
  /// The frame sent at shutdown.
  [[nodiscard]] virtual protocol::DataBytes neutral() const = 0;
  /// After a pause: the next step is a start-up again (presses made before it
  /// are history; the deadman needs a fresh press).
  virtual void restart() = 0;
};

/// What one tick did, for the status view and the log. Values only, copied by
/// the loop: whoever reads a report never reaches back into the loop, the
/// engine or the link (docs/architecture.md).
struct TickReport {
  std::int64_t tick = 0;     ///< index on the clock
  std::int64_t t_ms = 0;     ///< the tick's time, ms since start
  std::int64_t skipped = 0;  ///< ticks skipped before this one after a stall
  protocol::DataBytes data{};  ///< the frame offered to the link (result: whether it took it)
  link::SendResult result = link::SendResult::kDown;
  bool shutting_down = false;
  bool connected = false;    ///< a controller is connected
  std::string controller;    ///< its name (may be empty)
  mapping::EngineStatus engine;  ///< after this tick's step (shutting down: the last step's)
  link::LinkStatus link;     ///< after this tick's send
  bool reloading = false;   ///< one of a reload's neutral frames
};

struct BridgeOptions {
  std::int64_t rate_millihertz = timing::kDefaultRateMillihertz;
  int shutdown_frames = 3;     ///< neutral frames sent at the end
  int shutdown_extra_ticks = 5;///< ticks allowed beyond those for frames the link refused
  int drain_timeout_ms = 300;
};

/// What the world around the loop asks of it, read at each tick.
enum class Request : std::uint8_t {
  kNone,
  kStop,     ///< end the run (SIGINT, SIGTERM)
  kSuspend,  ///< job control (Ctrl-Z): neutral frames, then pause until the process goes on
  kResumed,  ///< the process was stopped behind the loop's back (SIGSTOP) and goes on
  kReload,   ///< reread the settings (SIGHUP): neutral frames, RunControl::reload, then afresh
};

struct RunControl {
  std::function<Request()> poll;
  /// Called after a suspend's neutral frames (link drained and closed);
  /// returns when the run goes on.
  std::function<void()> pause;
  /// Called after a reload's neutral frames (the link stays open), on the
  /// loop's thread: swaps the frame source's settings, or keeps them and
  /// says why. The frame source is then restarted (a fresh deadman press).
  std::function<void()> reload = [] {};
};

/// How the neutral frames at the end went.
struct ShutdownReport {
  int neutral_sent = 0;  ///< neutral frames the link took
  int neutral_wanted = 0;
  bool drained = false;  ///< and the link then had them out before it closed
  [[nodiscard]] bool ok() const { return neutral_sent >= neutral_wanted && drained; }
};

class Bridge {
 public:
  using StopCheck = std::function<bool()>;
  using Observer = std::function<void(const TickReport&)>;

  Bridge(input::InputSource& input, FrameSource& frames, link::Link& link, BridgeOptions options)
      : input_(input), frames_(frames), link_(link), options_(options), schedule_(options.rate_millihertz) {}

  /// Runs until a stop request or the end of the input, then shuts down. A
  /// request seen on tick k is answered on tick k: its frame is the first
  /// neutral one. Never throws for a link problem; an InputError from a
  /// script still escapes (after the neutral frames).
  void run(const RunControl& control, const Observer& observe);
  /// The same, with stop() as the only request.
  void run(const StopCheck& stop, const Observer& observe);

  /// After run(): whether the neutral frames reached the link. When not, the
  /// vehicle may still be acting on the last frame it got: the caller says so
  /// and exits 1.
  [[nodiscard]] const ShutdownReport& shutdown_report() const { return shutdown_report_; }

 private:
  void shutdown(std::int64_t start_ns, std::int64_t tick, const Observer& observe);
  /// The values a tick's report carries, copied now.
  [[nodiscard]] TickReport report(std::int64_t tick, std::int64_t t_ms, std::int64_t skipped,
                                  const protocol::DataBytes& data, link::SendResult result,
                                  bool shutting_down) const;
  /// Neutral frames from tick `tick` on (tick is left at the next one to
  /// send); returns how many the link took.
  int send_neutral(std::int64_t start_ns, std::int64_t& tick, const Observer& observe, bool reloading);

  input::InputSource& input_;
  FrameSource& frames_;
  link::Link& link_;
  BridgeOptions options_;
  timing::TickSchedule schedule_;
  input::InputState state_;
  mapping::EngineStatus engine_status_;  ///< the last step's
  ShutdownReport shutdown_report_;
};

}  // namespace andros::run
