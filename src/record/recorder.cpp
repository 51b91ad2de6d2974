#include "andros/record/recorder.hpp"

#include <chrono>
#include <functional>
#include <optional>
#include <utility>

namespace andros::record {

struct SessionWriter::Shared {
  explicit Shared(std::unique_ptr<RecordSink> s, std::size_t capacity) : sink(std::move(s)), ring(capacity) {}
  std::unique_ptr<RecordSink> sink;
  std::vector<std::string> ring;
  // Single producer (push), single consumer (the thread): head is the
  // producer's, tail the consumer's; a slot is the consumer's from tail to head.
  std::atomic<std::size_t> head{0};
  std::atomic<std::size_t> tail{0};
  std::atomic<std::uint64_t> dropped{0};  ///< refused by the full queue, and those below
  std::atomic<std::uint64_t> unmade{0};   ///< records whose text could not be made (drop())
  std::atomic<std::uint64_t> lost{0};
  std::atomic<std::uint64_t> written{0};
  /// 1 while the thread sleeps on an empty queue with nothing left to sync:
  /// the push that finds it so wakes it (the one system call on the loop's side).
  std::atomic<std::uint32_t> asleep{0};
  std::mutex mutex;
  std::condition_variable wake;
  std::condition_variable finished;
  bool closing = false;
  bool done = false;
  std::string error;
  std::string last_hash;
};

namespace {

/// How often the thread looks at the queue while records come or wait to be
/// synced; with none of either it sleeps until the next record.
constexpr auto kPollPeriod = std::chrono::milliseconds(250);
constexpr auto kSyncPeriod = std::chrono::seconds(1);
constexpr std::size_t kBatchBytes = std::size_t{64} * 1024;

}  // namespace

SessionWriter::SessionWriter(std::unique_ptr<RecordSink> sink, std::size_t capacity)
    : shared_(std::make_shared<Shared>(std::move(sink), capacity)), thread_(work, shared_) {}

SessionWriter::~SessionWriter() { close(1000); }

bool SessionWriter::push(std::string payload) {
  Shared& s = *shared_;
  const std::size_t head = s.head.load(std::memory_order_relaxed);
  // A record longer than a reader takes (SEQ, spaces and hash: at most 86 more) is dropped as a full queue's is.
  if (head - s.tail.load(std::memory_order_acquire) >= s.ring.size() || payload.size() > kMaxSessionLine - 86) {
    s.dropped.fetch_add(1, std::memory_order_relaxed);
    return false;
  }
  s.ring[head % s.ring.size()] = std::move(payload);
  s.head.store(head + 1, std::memory_order_seq_cst);
  // The first record after a quiet spell: the thread sleeps (it set asleep,
  // then found the queue empty; one of the two sees the other's store).
  if (s.asleep.load(std::memory_order_seq_cst) != 0 && s.asleep.exchange(0) != 0) s.asleep.notify_one();
  return true;
}

void SessionWriter::drop() {
  shared_->unmade.fetch_add(1, std::memory_order_relaxed);
  shared_->dropped.fetch_add(1, std::memory_order_relaxed);
}

void SessionWriter::work(const std::shared_ptr<Shared>& shared) {
  Shared& s = *shared;
  RecordChain chain;
  std::uint64_t reported_drops = 0;
  std::uint64_t reported_unmade = 0;
  std::uint64_t missing = 0;  // records dropped or lost since the last one written, not yet said
  std::string missing_why;    // why the last of them went missing
  bool stop_told = false;     // a `dropped` record has taken the closing room once, when recording stopped
  bool failed = false;        // a sync failed: nothing more is written
  auto last_sync = std::chrono::steady_clock::now();
  bool unsynced = false;  // written since the last sync
  std::vector<std::string> batch;
  std::size_t batch_bytes = 0;
  const auto fail = [&s](const std::string& error) {
    const std::lock_guard lock(s.mutex);
    if (s.error.empty()) s.error = error;
  };
  // Appends lines from the chain's present place; false (and the chain back
  // there) when the sink failed: it left the file at its last whole record.
  // closing: the session's last word, which may use the room kept for it.
  const auto put = [&](const std::function<std::string()>& lines, bool closing = false) {
    const auto seq = chain.records();
    const auto from = chain.last();
    std::string error;
    if (closing ? s.sink->write_closing(lines(), error) : s.sink->write(lines(), error)) {
      s.written.store(chain.records(), std::memory_order_relaxed);
      unsynced = true;
      return true;
    }
    fail(error);
    missing_why = error;
    chain.rewind(seq, from);
    return false;
  };
  // What went missing, said by a `dropped N "WHY"` record where it fits (never before the header).
  const auto tell = [&](bool closing = false) {
    if (missing != 0 && chain.records() != 0 &&
        put([&] { return chain.line(payload::dropped(missing, missing_why)); }, closing)) {
      missing = 0;
    }
  };
  // Whole records or none: a batch at once, else record by record as many as
  // fit, and a `dropped N` record for the rest, where they went missing. A
  // write that fails stops the batch's records but its `end`, which (after
  // the `dropped` record that says what is missing) takes the closing room.
  const auto write_batch = [&] {
    if (batch.empty() && missing == 0) return;
    if (failed) {
      s.lost.fetch_add(batch.size(), std::memory_order_relaxed);
    } else if (bool told = false; put([&] {
                 std::string text;
                 if (missing != 0 && chain.records() != 0) {
                   text = chain.line(payload::dropped(missing, missing_why));
                   told = true;
                 }
                 for (const auto& payload : batch) text += chain.line(payload);
                 return text;
               })) {
      if (told) missing = 0;
    } else {
      bool stopped = false;  // a record of this batch did not fit: those after it are not tried
      for (const auto& payload : batch) {
        const bool closing = payload.starts_with("end ");
        if (!stopped || closing) {
          tell(closing);
          if ((missing == 0 || chain.records() == 0) && put([&] { return chain.line(payload); }, closing)) continue;
        }
        stopped = true;
        s.lost.fetch_add(1, std::memory_order_relaxed);
        ++missing;
      }
      // Recording has stopped here (a full disk, a file-size limit): said at
      // once, in the closing room, so that a run killed later still shows why.
      if (stopped && !stop_told && chain.records() != 0) {
        stop_told = true;
        tell(true);
      }
    }
    batch.clear();
    batch_bytes = 0;
  };
  while (true) {
    const std::size_t head = s.head.load(std::memory_order_acquire);
    for (std::size_t tail = s.tail.load(std::memory_order_relaxed); tail != head; ++tail) {
      batch.push_back(std::move(s.ring[tail % s.ring.size()]));
      s.tail.store(tail + 1, std::memory_order_release);
      batch_bytes += batch.back().size();
      if (batch_bytes >= kBatchBytes) write_batch();
    }
    write_batch();
    // Records the full queue refused: said where they went missing.
    if (const auto drops = s.dropped.load(std::memory_order_relaxed); drops != reported_drops) {
      missing += drops - reported_drops;
      const auto unmade = s.unmade.load(std::memory_order_relaxed);
      missing_why = unmade != reported_unmade ? "a record's text could not be made"
                                              : "the queue was full: the disk did not keep up";
      reported_unmade = unmade;
      reported_drops = drops;
      write_batch();
    }
    if (unsynced && std::chrono::steady_clock::now() - last_sync >= kSyncPeriod) {
      std::string error;
      if (!s.sink->sync(error)) {
        failed = true;
        fail(error);
      }
      last_sync = std::chrono::steady_clock::now();
      unsynced = false;
    }
    std::unique_lock lock(s.mutex);
    const auto empty = [&s] { return s.head.load() == s.tail.load(std::memory_order_relaxed); };
    if (s.closing && empty()) break;
    if (!unsynced && !s.closing) {
      // Nothing to write or sync (a run at rest records nothing): sleep until
      // the next record or the close, rather than waking 4 times a second.
      // Set under the lock: a close after it finds it set and clears it.
      s.asleep.store(1);
      lock.unlock();
      if (empty()) s.asleep.wait(1);
      s.asleep.store(0);
      continue;
    }
    s.wake.wait_for(lock, kPollPeriod, [&s] { return s.closing; });
  }
  std::string error;
  if (!failed && !s.sink->sync(error)) failed = true;
  const std::lock_guard lock(s.mutex);
  if (failed && s.error.empty()) s.error = error;
  s.last_hash = to_hex(chain.last());
  s.done = true;
  s.finished.notify_all();
}

bool SessionWriter::close(int timeout_ms) {
  if (closed_) return shared_->done && dropped() == 0 && lost() == 0;
  closed_ = true;
  std::unique_lock lock(shared_->mutex);
  shared_->closing = true;
  shared_->wake.notify_all();
  shared_->asleep.store(0);
  shared_->asleep.notify_one();
  const bool done =
      shared_->finished.wait_for(lock, std::chrono::milliseconds(timeout_ms), [this] { return shared_->done; });
  lock.unlock();
  if (done) {
    thread_.join();
  } else {
    // A disk that does not answer must not hold the exit: what it holds is lost.
    const std::size_t queued = shared_->head.load() - shared_->tail.load();
    shared_->lost.fetch_add(queued, std::memory_order_relaxed);
    thread_.detach();
  }
  return done && dropped() == 0 && lost() == 0;
}

std::uint64_t SessionWriter::dropped() const { return shared_->dropped.load(std::memory_order_relaxed); }
std::uint64_t SessionWriter::lost() const { return shared_->lost.load(std::memory_order_relaxed); }
std::uint64_t SessionWriter::written() const { return shared_->written.load(std::memory_order_relaxed); }

std::string SessionWriter::error() const {
  const std::lock_guard lock(shared_->mutex);
  return shared_->error;
}

std::string SessionWriter::last_hash() const {
  const std::lock_guard lock(shared_->mutex);
  return shared_->last_hash;
}

void Recorder::header(std::string_view version, std::string_view local_time, long pid, std::string_view host,
                      const SessionSettings& settings, const link::LinkStatus& link_before) noexcept {
  guarded([&] {
    record([&] { return payload::header(); });
    record([&] { return payload::program(version); });
    record([&] { return payload::started(local_time, pid, host); });
    record([&] { return payload::settings(settings); });
    record([&] { return payload::link(-1, link_before); });
    link_state_ = link_before.state;
    link_motion_ = link_before.far_end_reading;
    link_detail_ = link_before.detail;
  });
}

void Recorder::pumped(std::int64_t t_ms, const std::vector<input::InputEvent>& events) noexcept {
  guarded([&] {
    t_ms_ = t_ms;
    if (after_pause_) {
      record([&] { return payload::pause(t_ms); });
      after_pause_ = false;
    }
    for (const auto& e : events) record([&] { return payload::event(e); });
  });
}

void Recorder::request(run::Request request) noexcept {
  guarded([&] {
    if (request == run::Request::kNone) return;
    // A stop asked once is answered on every tick after it until the run ends:
    // one record says it (one Ctrl-C, one `request stop`).
    if (request == run::Request::kShutdown && std::exchange(stop_recorded_, true)) return;
    record([&] { return payload::request(t_ms_, request); });
  });
}

void Recorder::reloaded(const run::ReloadOutcome& outcome, const SessionSettings* settings) noexcept {
  guarded([&] {
    if (outcome.ok && settings != nullptr) record([&] { return payload::settings(*settings); });
    record([&] { return payload::reload(t_ms_, outcome); });
  });
}

void Recorder::input_end(std::int64_t t_ms) noexcept {
  guarded([&] {
    if (input_ended_) return;
    input_ended_ = true;
    record([&] { return payload::input_end(t_ms); });
  });
}

void Recorder::observe(const run::TickReport& r) noexcept {
  guarded([&] {
    if (!r.gate_fault.empty()) record([&] { return payload::gate(r.t_ms, r.gate_fault); });
    if (format_ >= kTransitionFormat) {
      for (const auto& reported : r.transitions) {
        const auto& t = reported.transition;
        if (t.to != t.from) record([&] { return payload::transition(r.t_ms, t); });
      }
    }
    if (first_ || r.state != state_) {
      state_ = r.state;
      record([&] { return payload::state(r.t_ms, r.state); });
    }
    // Every stop press (one that latched, made the stop another's, or came
    // again while stopped) and every reset, once, with the pad that made it.
    const run::ReportedTransition* last_stop = nullptr;
    for (const auto& reported : r.transitions) {
      const auto& t = reported.transition;
      if (const auto by = run::stop_by(t.event)) {
        if (format_ >= kTransitionFormat) record([&] { return payload::stop(r.t_ms, *by, reported.pad, t.again); });
        last_stop = &reported;
      }
    }
    if (last_stop != nullptr && format_ < kTransitionFormat) {
      const auto& t = last_stop->transition;
      record([&] { return payload::stop(r.t_ms, *run::stop_by(t.event), last_stop->pad, t.again); });
    }
    for (const auto& reported : r.transitions) {
      const auto& t = reported.transition;
      if (t.event == run::OpEvent::kOperatorReset || t.event == run::OpEvent::kSupervisorReset) {
        const auto by = t.event == run::OpEvent::kSupervisorReset ? run::StopBy::kSupervisor : run::StopBy::kOperator;
        record([&] { return payload::reset(r.t_ms, by, reported.pad); });
      }
    }
    if (first_ || r.engine.layer != layer_) {
      layer_ = r.engine.layer;
      record([&] { return payload::layer(r.t_ms, layer_); });
    }
    if (r.link.state != link_state_ || r.link.far_end_reading != link_motion_ || r.link.detail != link_detail_) {
      link_state_ = r.link.state;
      link_motion_ = r.link.far_end_reading;
      link_detail_ = r.link.detail;
      record([&] { return payload::link(r.t_ms, r.link); });
    }
    const std::int64_t gap = r.tick - last_tick_ - 1;
    // Written again after a while unchanged, so that a reader can bound the ticks a record stands for.
    const bool due = format_ >= kSpacedFormat && r.t_ms - frame_t_ms_ >= kFrameRecordPeriodMs;
    if (first_ || gap != 0 || r.data != data_ || r.result != result_ || r.sent != sent_ || due) {
      frame_t_ms_ = r.t_ms;
      data_ = r.data;
      result_ = r.result;
      sent_ = r.sent;
      record([&] { return payload::frame(r, gap); });
    }
    if (r.delivered()) ++frames_sent_;
    last_tick_ = r.tick;
    last_t_ms_ = r.t_ms;
    first_ = false;
  });
}

void Recorder::end(std::string_view why) noexcept {
  guarded([&] { record([&] { return payload::end(last_t_ms_, last_tick_, frames_sent_, why); }); });
}

}  // namespace andros::record
