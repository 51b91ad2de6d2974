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
#include "andros/run/bridge.hpp"
#include "andros/run/session.hpp"

namespace andros::run {

/// Where the writer thread puts the chained lines: a file, or a test's sink
/// that stalls or fails.
class RecordSink {
 public:
  virtual ~RecordSink() = default;
  /// Writes all of text; false with error set when it could not.
  virtual bool write(std::string_view text, std::string& error) = 0;
  /// Makes what was written durable (called about once a second); false with error set.
  virtual bool sync(std::string& error) = 0;
};

/// A session file, created (never overwritten) with mode 0640.
class FileRecordSink final : public RecordSink {
 public:
  /// Throws RuntimeError when the file cannot be created.
  explicit FileRecordSink(const std::string& path);
  ~FileRecordSink() override;
  FileRecordSink(const FileRecordSink&) = delete;
  FileRecordSink& operator=(const FileRecordSink&) = delete;
  bool write(std::string_view text, std::string& error) override;
  bool sync(std::string& error) override;

 private:
  int fd_ = -1;
};

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
  /// Lets the thread write what is queued and end, waiting at most timeout_ms
  /// for a stalled disk (then it is left behind, and what it held is lost).
  /// True when everything queued was written.
  bool close(int timeout_ms);

  /// Records the full queue refused.
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
/// report (a frame record only when something changed).
class Recorder {
 public:
  explicit Recorder(SessionWriter& writer) : writer_(writer) {}

  /// Before the loop starts: the session's header.
  void header(std::string_view version, std::string_view local_time, long pid, std::string_view host,
              const SessionSettings& settings, const link::LinkStatus& link_before);
  void pumped(std::int64_t t_ms, const std::vector<input::InputEvent>& events);
  void request(Request request);
  /// After a job-control stop: the loop's next pump is its end.
  void paused() { after_pause_ = true; }
  void reloaded(const ReloadOutcome& outcome, const SessionSettings* settings);
  void input_end(std::int64_t t_ms);
  void observe(const TickReport& report);
  /// The run's last record.
  void end(std::string_view why);

  [[nodiscard]] std::uint64_t frames_sent() const { return frames_sent_; }
  /// The dropped records the writer has not been told of yet go in a record of their own.
  [[nodiscard]] std::uint64_t dropped() const { return writer_.dropped(); }

 private:
  void push(std::string payload) { writer_.push(std::move(payload)); }

  SessionWriter& writer_;
  std::int64_t t_ms_ = 0;  ///< the last pump's time: the tick's
  bool after_pause_ = false;
  bool input_ended_ = false;
  bool first_ = true;
  // What the last report said, for the records written only on a change.
  OpState state_ = OpState::kNoLink;
  std::optional<StopBy> stopped_by_;  ///< as the last report said
  std::optional<StopBy> reset_by_;
  std::string layer_;
  link::LinkState link_state_ = link::LinkState::kConnecting;
  bool link_motion_ = true;
  std::string link_detail_;
  protocol::DataBytes data_{};
  link::SendResult result_ = link::SendResult::kSent;
  bool sent_ = true;
  std::int64_t last_tick_ = -1;
  std::int64_t last_t_ms_ = 0;
  std::uint64_t frames_sent_ = 0;
};

/// The input as the loop sees it, with every event it applies recorded.
class RecordingInput final : public input::InputSource {
 public:
  RecordingInput(input::InputSource& inner, Recorder& recorder) : inner_(inner), recorder_(recorder) {}
  void pump(input::InputState& state, std::int64_t now_ms) override;
  [[nodiscard]] bool finished(std::int64_t now_ms) const override;
  void feedback(const input::FeedbackPattern& pattern) override { inner_.feedback(pattern); }
  // Everything else the loop and the screen ask of the input is the inner source's.
  [[nodiscard]] bool supervised() const override { return inner_.supervised(); }
  [[nodiscard]] std::optional<input::DeviceLayout> device() const override { return inner_.device(); }

 private:
  input::InputSource& inner_;
  Recorder& recorder_;
};

/// The loop's controls with what they answer recorded: requests, the end of a
/// job-control stop, reload outcomes (with the settings they put in place:
/// settings() is asked after an ok one).
RunControl recorded_control(RunControl control, Recorder& recorder, std::function<SessionSettings()> settings);

}  // namespace andros::run
