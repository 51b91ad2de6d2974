#include "andros/trainer/stream_hub.hpp"

#include <algorithm>

namespace andros::trainer {

Subscription::~Subscription() { hub_.leave(id_); }

std::optional<std::vector<Message>> Subscription::next(std::chrono::milliseconds timeout) {
  std::unique_lock lock(hub_.mutex_);
  // Looked up again after each wake: other clients joining and leaving move the list.
  const auto ready = [&] {
    const auto* c = hub_.find(id_);
    return hub_.closed_ || c == nullptr || c->dropped || !c->queue.empty();
  };
  hub_.wake_.wait_for(lock, timeout, ready);
  auto* client = hub_.find(id_);
  if (hub_.closed_ || client == nullptr || client->dropped) return std::nullopt;
  std::vector<Message> out(client->queue.begin(), client->queue.end());
  client->queue.clear();
  return out;
}

void StreamHub::publish(std::string message) {
  held_.push_back(std::make_shared<const std::string>(std::move(message)));
  std::unique_lock lock(mutex_, std::try_to_lock);
  if (!lock.owns_lock()) {
    // A client's thread is taking its messages: never wait for it.
    delayed_.fetch_add(1, std::memory_order_relaxed);
    return;
  }
  for (const auto& m : held_) deliver(m);
  counters_.published += held_.size();
  held_.clear();
  lock.unlock();
  wake_.notify_all();
}

void StreamHub::deliver(const Message& message) {
  latest_ = message;
  for (auto& c : clients_) {
    if (c.dropped) continue;
    if (c.queue.size() >= limits_.queue_frames) {
      // A whole queue behind: slow or stalled. Dropped, never waited for.
      c.dropped = true;
      c.queue.clear();
      ++counters_.dropped;
      continue;
    }
    c.queue.push_back(message);
  }
}

std::unique_ptr<Subscription> StreamHub::subscribe() {
  const std::lock_guard lock(mutex_);
  const auto live = static_cast<std::size_t>(
      std::count_if(clients_.begin(), clients_.end(), [](const Client& c) { return !c.dropped; }));
  if (closed_ || live >= limits_.max_clients) {
    ++counters_.refused;
    return nullptr;
  }
  Client c;
  c.id = next_id_++;
  if (latest_) c.queue.push_back(latest_);
  clients_.push_back(std::move(c));
  return std::unique_ptr<Subscription>(new Subscription(*this, clients_.back().id));
}

void StreamHub::leave(std::uint64_t id) {
  const std::lock_guard lock(mutex_);
  std::erase_if(clients_, [id](const Client& c) { return c.id == id; });
}

StreamHub::Client* StreamHub::find(std::uint64_t id) {
  const auto it = std::find_if(clients_.begin(), clients_.end(), [id](const Client& c) { return c.id == id; });
  return it == clients_.end() ? nullptr : &*it;
}

std::string StreamHub::latest() const {
  const std::lock_guard lock(mutex_);
  return latest_ ? *latest_ : std::string();
}

void StreamHub::close() {
  {
    const std::lock_guard lock(mutex_);
    closed_ = true;
  }
  wake_.notify_all();
}

HubCounters StreamHub::counters() const {
  const std::lock_guard lock(mutex_);
  HubCounters c = counters_;
  c.delayed = delayed_.load(std::memory_order_relaxed);
  c.clients = static_cast<std::size_t>(
      std::count_if(clients_.begin(), clients_.end(), [](const Client& k) { return !k.dropped; }));
  return c;
}

}  // namespace andros::trainer
