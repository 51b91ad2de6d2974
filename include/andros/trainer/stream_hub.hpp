#pragma once
/// The hand-off between the simulated vehicle and the trainer's web clients:
/// one message per frame, published without ever waiting, each client with a
/// bounded queue of its own. A client that falls a whole queue behind (slow,
/// stalled, gone) is dropped; nobody waits for it.

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace andros::trainer {

struct HubLimits {
  std::size_t max_clients = 16;   ///< event streams at once; one more is refused
  std::size_t queue_frames = 50;  ///< a client's queue: 2 s of frames at 25 Hz
};

struct HubCounters {
  std::uint64_t published = 0;
  std::uint64_t delayed = 0;  ///< messages held for the next publish: a client's thread held the lock
  std::uint64_t dropped = 0;  ///< clients dropped for a full queue
  std::uint64_t refused = 0;  ///< clients refused: max_clients already
  std::size_t clients = 0;    ///< clients now
};

using Message = std::shared_ptr<const std::string>;

class StreamHub;

/// One client's place in the hub; leaving it (the destructor) frees the place.
class Subscription {
 public:
  Subscription(const Subscription&) = delete;
  Subscription& operator=(const Subscription&) = delete;
  ~Subscription();

  /// The messages queued since the last call, waiting up to timeout for one;
  /// empty on a timeout; nullopt once the client must end (dropped, the hub closed).
  std::optional<std::vector<Message>> next(std::chrono::milliseconds timeout);

 private:
  friend class StreamHub;
  Subscription(StreamHub& hub, std::uint64_t id) : hub_(hub), id_(id) {}
  StreamHub& hub_;
  std::uint64_t id_;
};

class StreamHub {
 public:
  explicit StreamHub(HubLimits limits = {}) : limits_(limits) {}

  /// Hands a message to every client's queue and keeps it as the latest.
  /// Never waits: when a client's thread holds the hub this instant, the
  /// message is held and handed over with the next one. From one thread.
  void publish(std::string message);
  /// A new client, with the latest message queued first; nullptr when there
  /// are max_clients already.
  std::unique_ptr<Subscription> subscribe();
  /// The latest message ("" before the first).
  [[nodiscard]] std::string latest() const;
  /// Ends every client's stream (next() gives nullopt) and refuses new ones.
  void close();
  [[nodiscard]] HubCounters counters() const;
  [[nodiscard]] const HubLimits& limits() const { return limits_; }

 private:
  friend class Subscription;
  struct Client {
    std::uint64_t id = 0;
    std::deque<Message> queue;
    bool dropped = false;
  };
  void deliver(const Message& message);  ///< under the lock
  Client* find(std::uint64_t id);        ///< under the lock
  void leave(std::uint64_t id);

  HubLimits limits_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::vector<Client> clients_;
  Message latest_;
  bool closed_ = false;
  std::uint64_t next_id_ = 1;
  HubCounters counters_;
  std::atomic<std::uint64_t> delayed_{0};
  std::vector<Message> held_;  ///< the publisher's own: messages not yet handed over
};

}  // namespace andros::trainer
