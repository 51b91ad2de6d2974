#pragma once
/// The run loop: on every tick of an absolute-time clock, pump the input,
/// compute the frame, send it; on a stop request or the end of the input,
/// send neutral frames at the normal period, drain and close the link. A
/// suspend request (job control) sends the same neutral frames, then pauses;
/// a reload request sends them, swaps the settings, and starts afresh.

#include <cstdint>
#include <functional>
#include <string>

#include "andros/frame.hpp"
#include "andros/input.hpp"
#include "andros/input_source.hpp"
#include "andros/io/link.hpp"
#include "andros/tick_schedule.hpp"

namespace andros::io {

/// What computes the frames: the mapping engine in `run`, a fixed frame in
/// the benchmarks and tests.
class FrameSource {
 public:
  virtual ~FrameSource() = default;
  /// The frame for the tick at now_ms (ms since start) from this input.
  virtual DataBytes step(const InputState& input, std::int64_t now_ms) = 0;
  /// The frame sent at shutdown.
  [[nodiscard]] virtual DataBytes neutral() const = 0;
  /// "enabled", or why not ("deadman released"), for the operator.
  [[nodiscard]] virtual std::string enable_text() const = 0;
  [[nodiscard]] virtual bool enabled() const = 0;
  /// The mapping layer in use ("" for the base layer).
  [[nodiscard]] virtual std::string layer() const { return {}; }
  /// After a pause: the next step is a start-up again (presses made before it
  /// are history; the deadman needs a fresh press).
  virtual void restart() = 0;
};

/// What one tick did, for the status view and the log.
struct TickReport {
  std::int64_t tick = 0;     ///< index on the clock
  std::int64_t t_ms = 0;     ///< the tick's time, ms since start
  std::int64_t skipped = 0;  ///< ticks skipped before this one after a stall
  const DataBytes* data = nullptr;
  SendResult result = SendResult::kDown;
  bool shutting_down = false;
  const InputState* input = nullptr;
  bool reloading = false;    ///< one of a reload's neutral frames
};

struct BridgeOptions {
  std::int64_t rate_millihertz = kDefaultRateMillihertz;
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

  Bridge(InputSource& input, FrameSource& frames, Link& link, BridgeOptions options)
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
  /// Neutral frames from tick `tick` on (tick is left at the next one to
  /// send); returns how many the link took.
  int send_neutral(std::int64_t start_ns, std::int64_t& tick, const Observer& observe, bool reloading);

  InputSource& input_;
  FrameSource& frames_;
  Link& link_;
  BridgeOptions options_;
  TickSchedule schedule_;
  InputState state_;
  ShutdownReport shutdown_report_;
};

/// Sleeps until the monotonic clock reads abs_ns (clock_nanosleep, TIMER_ABSTIME).
void sleep_until_ns(std::int64_t abs_ns);

}  // namespace andros::io
