#pragma once
/// Links for the loop's faults and for replay: a decorator that an event
/// script's `link down`, `link up` and `link taken` hold down, and a sink
/// that hands each frame sent to a function (replay's output).

#include <functional>
#include <string>

#include "andros/link/link.hpp"

namespace andros::link {

/// Forwards to a link, except while held down by a fault: then nothing is
/// sent (kDown), and the state and detail say why. Stalled (a TCP server
/// that stopped reading: TcpLink::far_end_reading), it forwards the frames but
/// does not allow motion, held down or not, until the server is seen reading.
class FaultLink final : public Link {
 public:
  explicit FaultLink(Link& inner) : inner_(inner) {}

  enum class Fault : std::uint8_t { kNone, kDown, kTaken };
  void set_fault(Fault fault) { fault_ = fault; }
  [[nodiscard]] Fault fault() const { return fault_; }
  void set_stalled(bool stalled) { stalled_ = stalled; }

  SendResult send(const protocol::Frame& frame, std::int64_t now_ns) override;
  bool drain_and_close(int timeout_ms) override { return inner_.drain_and_close(timeout_ms); }
  [[nodiscard]] LinkState state() const override {
    return fault_ == Fault::kNone ? inner_.state() : LinkState::kConnecting;
  }
  [[nodiscard]] const std::string& name() const override { return inner_.name(); }
  [[nodiscard]] const std::string& detail() const override;
  [[nodiscard]] const LinkCounters& counters() const override;
  [[nodiscard]] bool far_end_reading() const override { return !stalled_ && inner_.far_end_reading(); }

 private:
  Link& inner_;
  Fault fault_ = Fault::kNone;
  bool stalled_ = false;
  std::uint64_t down_ = 0;  ///< ticks held down here
  mutable LinkCounters merged_;
};

/// A link that is always there: every frame goes to `deliver` (replay's
/// output). Closing it makes it connecting; the next send reopens it.
class SinkLink final : public Link {
 public:
  using Deliver = std::function<void(std::int64_t now_ns, const protocol::Frame& frame)>;
  explicit SinkLink(Deliver deliver, std::string name = "replay output")
      : deliver_(std::move(deliver)), name_(std::move(name)) {}

  SendResult send(const protocol::Frame& frame, std::int64_t now_ns) override;
  bool drain_and_close(int timeout_ms) override;
  [[nodiscard]] LinkState state() const override { return state_; }
  [[nodiscard]] const std::string& name() const override { return name_; }
  [[nodiscard]] const std::string& detail() const override { return detail_; }
  [[nodiscard]] const LinkCounters& counters() const override { return counters_; }

 private:
  Deliver deliver_;
  std::string name_;
  std::string detail_;
  LinkState state_ = LinkState::kUp;
  LinkCounters counters_;
};

}  // namespace andros::link
