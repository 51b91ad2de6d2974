#pragma once
/// The flight recorder (docs/recording.md): what the run loop did, written to
/// a session file (session.hpp) by a thread of its own. The loop only hands
/// records to a bounded queue that never blocks it: when the queue is full,
/// or the disk fails or stalls, records are dropped and counted, never a
/// frame delayed.

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "andros/input/input_source.hpp"
#include "andros/record/record_sink.hpp"
#include "andros/record/session.hpp"
#include "andros/run/bridge.hpp"

namespace andros::record {

/// The writer thread and the queue in front of it. push() is called from one
/// thread only (the loop's) and never waits: a single-producer ring.
class SessionWriter {
 public:
  static constexpr std::size_t kDefaultCapacity = 4096;

  /// Starts the thread.
  explicit SessionWriter(std::unique_ptr<RecordSink> sink, std::size_t capacity = kDefaultCapacity);
  /// close() if not yet.
  ~SessionWriter();
  SessionWriter(const SessionWriter&) = delete;
  SessionWriter& operator=(const SessionWriter&) = delete;

  /// Queues one record's payload (without SEQ or hash); false when the queue
  /// is full and it was dropped (counted). Never blocks.
  bool push(std::string payload);
  /// Counts one record that could not be made (its text could not be
  /// built): said by a `dropped` record, as a full queue's are.
  void drop();
  /// Lets the thread write what is queued and end, waiting at most timeout_ms
  /// for a stalled disk (then it is left behind, and what it held is lost).
  /// True when everything queued was written.
  bool close(int timeout_ms);

  /// Records the full queue refused, and those whose text could not be made (drop()).
  [[nodiscard]] std::uint64_t dropped() const;
  /// Records taken from the queue but not written (the disk failed, or was
  /// stalled at close).
  [[nodiscard]] std::uint64_t lost() const;
  /// Records written (the chain's length).
  [[nodiscard]] std::uint64_t written() const;
  /// The first write error ("" while none): recording stopped there.
  [[nodiscard]] std::string error() const;
  /// The last record's hash, once closed.
  [[nodiscard]] std::string last_hash() const;

 private:
  struct Shared;
  static void work(const std::shared_ptr<Shared>& shared);

  std::shared_ptr<Shared> shared_;
  std::thread thread_;
  bool closed_ = false;
};

/// The records of one run, from the loop's thread: the input decorator's
/// events, the requests and reloads the loop answered, and each tick's
/// report (a frame record only when something changed). No exception leaves
/// it: a record that cannot be made (memory, a text the JSON layer refuses)
/// is dropped and counted, and the loop goes on.
class Recorder {
 public:
  /// Where the payloads go: the writer's queue, or (replay) the comparison
  /// with the records a session holds. Never blocks the loop.
  using PayloadSink = std::function<void(std::string payload)>;

  explicit Recorder(SessionWriter& writer)
      : writer_(&writer), sink_([&writer](std::string payload) { writer.push(std::move(payload)); }) {}
  /// format: the session format whose records it makes (a replay makes
  /// those of the session it replays): before kSpacedFormat, no frame
  /// record is written again after kFrameRecordPeriodMs unchanged; before
  /// kTransitionFormat, no transition records, and only a tick's last stop press.
  explicit Recorder(PayloadSink sink, int format = kSessionFormat) : sink_(std::move(sink)), format_(format) {}

  /// Before the loop starts: the session's header.
  void header(std::string_view version, std::string_view local_time, long pid, std::string_view host,
              const SessionSettings& settings, const link::LinkStatus& link_before) noexcept;
  void pumped(std::int64_t t_ms, const std::vector<input::InputEvent>& events) noexcept;
  void request(run::Request request) noexcept;
  /// After a job-control stop: the loop's next pump is its end.
  void paused() { after_pause_ = true; }
  void reloaded(const run::ReloadOutcome& outcome, const SessionSettings* settings) noexcept;
  void input_end(std::int64_t t_ms) noexcept;
  /// A tick's report: its gate trip, the machine's transitions (a
  /// transition record for each that changed the state, a stop or reset
  /// record for each stop press and reset), the state, layer and link when
  /// they changed, and its frame when it changed.
  void observe(const run::TickReport& report) noexcept;
  /// A record the command adds to the loop's (the trainer's course and score: payload::course, payload::score).
  void add(std::string payload) noexcept {
    record([&] { return std::move(payload); });
  }
  /// The run's last record.
  void end(std::string_view why) noexcept;
  /// A record the caller could not make (its settings could not be read).
  void drop() noexcept {
    if (writer_ != nullptr) writer_->drop();
  }

  [[nodiscard]] std::uint64_t frames_sent() const { return frames_sent_; }
  /// The dropped records the writer has not been told of yet go in a record of their own.
  [[nodiscard]] std::uint64_t dropped() const { return writer_ == nullptr ? 0 : writer_->dropped(); }

 private:
  /// One record, its payload made by make: whatever that throws is a record
  /// dropped, and what the recorder keeps of the loop goes on.
  template <class Make>
  void record(Make&& make) noexcept {
    try {
      sink_(make());
    } catch (...) {
      drop();
    }
  }
  /// A method's whole body (its bookkeeping too): what it throws is a record dropped.
  template <class Body>
  void guarded(Body&& body) noexcept {
    try {
      body();
    } catch (...) {
      drop();
    }
  }

  SessionWriter* writer_ = nullptr;  ///< null: not writing (a replay's)
  PayloadSink sink_;
  int format_ = kSessionFormat;
  std::int64_t t_ms_ = 0;  ///< the last pump's time: the tick's
  bool after_pause_ = false;
  bool input_ended_ = false;
  bool stop_recorded_ = false;
  bool first_ = true;
  // What the last records said, for those written only on a change.
  run::OpState state_ = run::OpState::kNoLink;
  std::string layer_;
  link::LinkState link_state_ = link::LinkState::kConnecting;
  bool link_motion_ = true;
  std::string link_detail_;
  protocol::DataBytes data_{};
  link::SendResult result_ = link::SendResult::kSent;
  bool sent_ = true;
  std::int64_t last_tick_ = -1;
  std::int64_t last_t_ms_ = 0;
  std::int64_t frame_t_ms_ = 0;  ///< the last frame record's time
  std::uint64_t frames_sent_ = 0;
};

}  // namespace andros::record
