#pragma once
/// The trainer's middle: the vehicle model fed the frames the simulated
/// vehicle decodes, on its thread, and one JSON object per frame handed to
/// the web clients (docs/trainer.md, "The stream"). The run loop only hands
/// over what it knows at each tick (observe), and never waits to do so.

#include <array>
#include <atomic>
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
  /// The frame the loop read it for: frames counted from 1 in the order the
  /// link took them (the tick's frame, or the next one sent when the link
  /// took none that tick).
  std::uint64_t frame = 0;
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
  bool sent = false;       ///< the link took the tick's frame
  PadInputs pad;
  std::string score;  ///< on a course: its score so far, a JSON object (course_score.hpp); "" without one
};

/// The object the stream carries for a frame (one line of JSON).
std::string stream_object(const vehicle::VehicleModel& model, const LoopFacts& facts);

class TrainerFeed {
 public:
  /// course: the ground the vehicle drives on (open ground without one).
  TrainerFeed(const vehicle::RobotFigures& figures, StreamHub& hub, std::optional<vehicle::Course> course = {})
      : model_(figures, std::move(course)), hub_(hub) {}

  /// A tick the loop ran (its thread, after the tick): the frame it offered,
  /// and whether the link took it, queued for the motion thread
  /// (take_ticks). Never waits: lock-free, and a full queue (the motion
  /// thread a whole queue behind) drops the tick, counted in lost_ticks().
  void queue_tick(std::int64_t t_ms, const protocol::DataBytes& data, bool delivered);
  /// The ticks queued, into the model as a session's replay feeds them
  /// (view::feed_tick: a frame the link took at its tick's time, else the
  /// clock moved on), each one's object published. From one thread (the
  /// motion thread). Returns whether there was any.
  bool take_ticks();
  /// The latest object published again, with the facts observe() last took (the model as it is).
  void republish();
  /// The model advanced to now_ns with no frame, its object published (a test's).
  void advance(std::int64_t now_ns);
  /// The loop's facts after a tick (the loop's thread); facts.pad is not
  /// read (observe_pad() hands the pad over). Never waits: while the
  /// motion thread reads them, this tick's are left out.
  void observe(LoopFacts facts);
  /// The pad as the loop pumped it (the loop's thread), before the tick's
  /// frame is sent: the object for the frame it was read for carries it. With
  /// the open device's layout, a plain joystick's inputs are its numbered
  /// ones; without (an event script), a game controller's. Never waits.
  void observe_pad(const input::InputState& input, const input::DeviceLayout* layout);
  /// For GET /state: the latest object, with the trail so far.
  [[nodiscard]] std::string state_with_trail() const;
  /// The model's trail and pose to the bit (trail_summary()).
  [[nodiscard]] std::string summary() const;
  /// Ticks the queue had no room for: the model then is not the session's.
  [[nodiscard]] std::uint64_t lost_ticks() const { return lost_.load(); }

 private:
  /// The pads read for frames up to `frame` taken from the ring, the last
  /// one kept for the objects (under model_mutex_).
  void take_pads(std::uint64_t frame);
  void publish_locked();

  /// A tick handed from the loop to the motion thread.
  struct Tick {
    std::int64_t t_ms = 0;
    protocol::DataBytes data{};
    bool delivered = false;
    std::int64_t handed_ns = 0;  ///< when the loop handed it over (monotonic): its punctuality
  };
  /// 40 s of ticks at 25 Hz: the motion thread takes them every tick or 100 ms.
  static constexpr std::size_t kQueueTicks = 1024;
  /// A frame's pad goes from the loop's thread to the motion thread through a
  /// ring with one writer and one reader and no lock: the pad read for frame
  /// N is in it before frame N is sent, so the object for frame N carries
  /// it whatever the threads' timing. Full (the motion thread 64 frames
  /// behind), a pad is left out, and the objects show the last one taken.
  static constexpr std::size_t kPadRing = 64;

  mutable std::mutex model_mutex_;  ///< the motion thread's and the server's
  vehicle::VehicleModel model_;
  std::string latest_;
  std::mutex facts_mutex_;  ///< the loop's hand-off: try_lock only on its side
  LoopFacts facts_;
  PadInputs pad_;                      ///< the pad the objects show (under model_mutex_)
  std::int64_t first_handed_ns_ = -1;  ///< the first tick's hand-over (under model_mutex_)
  std::int64_t handed_ns_ = -1;        ///< the latest tick's taken (under model_mutex_)
  std::uint64_t sent_ = 0;             ///< the loop's own: frames the link took
  std::array<PadInputs, kPadRing> pads_;
  std::atomic<std::uint64_t> pads_written_{0};  ///< by the loop's thread
  std::atomic<std::uint64_t> pads_read_{0};     ///< by the motion thread (under model_mutex_)
  StreamHub& hub_;
  // One producer (the loop), one consumer (the motion thread): each index written by one side only.
  std::array<Tick, kQueueTicks> queue_{};
  std::atomic<std::size_t> queue_head_{0};  ///< the next to write (the loop's)
  std::atomic<std::size_t> queue_tail_{0};  ///< the next to read (the motion thread's)
  std::atomic<std::uint64_t> lost_{0};
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
