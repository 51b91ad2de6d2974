#pragma once
/// The trainer's middle: the vehicle model fed the frames the simulated
/// vehicle decodes, on its thread, and one JSON object per frame handed to
/// the web clients (docs/trainer.md, "The stream"). The run loop only hands
/// over what it knows at each tick (observe), and never waits to do so.

#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "andros/input/device_layout.hpp"
#include "andros/input/input_source.hpp"
#include "andros/protocol/decoder.hpp"
#include "andros/trainer/stream_hub.hpp"
#include "andros/vehicle/vehicle_model.hpp"

namespace andros::trainer {

/// The operator's pad as the loop read it at a tick.
struct PadInputs {
  bool connected = false;
  std::string name;
  /// The buttons held: a game controller's by name ("leftshoulder", "dpup"),
  /// a plain joystick's by number ("button 3"), hat directions ("hat0up").
  std::vector<std::string> buttons;
  /// Each axis and its value: a game controller's by name ("lefty"), a plain joystick's by number ("axis 2").
  std::vector<std::pair<std::string, std::int16_t>> axes;
};

/// What the loop knows at a tick, for the page.
struct LoopFacts {
  std::int64_t tick = -1;
  std::int64_t t_ms = 0;
  std::string state;       ///< in the status view's words ("ENABLED", "STOPPED: ...")
  std::string state_name;  ///< the state's own name ("enabled", "stopped")
  std::string layer;       ///< the mapping layer in use, "" for the base
  PadInputs pad;
};

/// The object the stream carries for a frame (one line of JSON).
std::string stream_object(const vehicle::VehicleModel& model, const LoopFacts& facts);

class TrainerFeed {
 public:
  TrainerFeed(const vehicle::RobotFigures& figures, StreamHub& hub) : model_(figures), hub_(hub) {}

  /// A frame the simulated vehicle decoded at now_ns (its thread): into the
  /// model, then its object to the clients.
  void on_frame(const protocol::DecodedFrame& frame, std::int64_t now_ns);
  /// The model advanced to now_ns with no frame (the watchdog), its object published.
  void advance(std::int64_t now_ns);
  /// The same when no frame has come for quiet_ns: while the loop sends
  /// none (a link down, a suspend), the page still sees the vehicle's
  /// watchdog stop it.
  void advance_if_quiet(std::int64_t now_ns, std::int64_t quiet_ns);
  /// The loop's facts after a tick (the loop's thread), the pad taken from
  /// observe_pad() (facts.pad is replaced). Never waits: while
  /// the vehicle's thread reads them, this tick's are left out.
  void observe(LoopFacts facts);
  /// The pad as the loop pumped it (the loop's thread); observe() carries
  /// it. With the open device's layout, a plain joystick's inputs are its
  /// numbered ones; without (an event script), a game controller's.
  void observe_pad(const input::InputState& input, const input::DeviceLayout* layout);
  /// For GET /state: the latest object, with the trail so far.
  [[nodiscard]] std::string state_with_trail() const;

 private:
  void publish_locked();

  mutable std::mutex model_mutex_;  ///< the vehicle's thread and the server's
  vehicle::VehicleModel model_;
  std::string latest_;
  std::mutex facts_mutex_;  ///< the loop's hand-off: try_lock only on its side
  LoopFacts facts_;
  PadInputs pad_;  ///< the loop's own, until observe() hands it over
  StreamHub& hub_;
};

/// The loop's input, passed through; after each pump the pad goes to the feed.
class WatchedInput : public input::InputSource {
 public:
  WatchedInput(input::InputSource& inner, TrainerFeed& feed) : inner_(inner), feed_(feed) {}

  void pump(input::TickInput& input, std::int64_t now_ms) override;
  [[nodiscard]] bool finished(std::int64_t now_ms) const override { return inner_.finished(now_ms); }
  [[nodiscard]] bool supervised() const override { return inner_.supervised(); }
  void feedback(const input::FeedbackPattern& pattern) override { inner_.feedback(pattern); }
  [[nodiscard]] std::optional<input::DeviceLayout> device() const override { return inner_.device(); }
  [[nodiscard]] std::string refusal() const override { return inner_.refusal(); }

 private:
  input::InputSource& inner_;
  TrainerFeed& feed_;
  /// The open device's inputs, asked again only when a controller connects.
  std::optional<input::DeviceLayout> layout_;
  std::uint32_t layout_connection_ = 0;
};

}  // namespace andros::trainer
