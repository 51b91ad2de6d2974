#pragma once
/// A session's ticks and the vehicle's motion they make (docs/trainer.md,
/// "Replaying a session"): each tick the live loop ran, at its time on the
/// recorded rate, into the vehicle model the way the trainer feeds it live
/// (TrainerFeed::take_ticks): a frame the link took is a frame the vehicle
/// received, any other tick only moves the model's clock on (its watchdog).
/// Only the frame records are read: no link is opened, and neither this
/// machine's mappings nor anything else outside the session is read.

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "andros/protocol/decoder.hpp"
#include "andros/record/session.hpp"
#include "andros/vehicle/vehicle_model.hpp"

namespace andros::view {

/// Where a walk over a session's ticks starts: a frame record and a tick within it.
struct TickPlace {
  std::size_t record = 0;
  std::int64_t tick = -1;  ///< -1: the record's own tick
};

/// One tick the live loop ran: its number, its time, the frame record in effect.
using TickVisitor = std::function<bool(std::int64_t tick, std::int64_t t_ms, const record::FrameRecord& frame)>;

/// Calls visit for each tick the live loop ran, from `from` on, in order:
/// a frame record holds on every tick to the next record's (less the ticks it
/// skipped), the last to the end record's tick. visit returns false to stop.
void for_each_tick(const record::Session& session, const TickVisitor& visit, TickPlace from = {});

/// A frame the link took, as the vehicle decodes it: valid (the loop sends
/// only frames its gate passed), the data as sent.
protocol::DecodedFrame received_frame(const protocol::DataBytes& data);

/// One tick into the model: its frame when it reached the vehicle (sent),
/// else the model's clock to the tick's time.
void feed_tick(vehicle::VehicleModel& model, std::int64_t t_ms, const protocol::DataBytes& data, bool delivered);

/// A point of the trail, and the time the model added it.
struct TimedPoint {
  std::int64_t t_ms = 0;
  double x = 0;
  double y = 0;
};

/// A session's motion, integrated once: the model at the end, the whole
/// trail with times, and snapshots of the model (at most kSnapshots, at
/// least kSnapshotTicks apart) from which at() seeks. at(t) is the model
/// fed every tick at or before t, bit for bit whether reached from the start
/// or from a snapshot (a copy of the whole model).
class SessionMotion {
 public:
  static constexpr std::size_t kSnapshots = 64;
  static constexpr std::int64_t kSnapshotTicks = 250;

  /// On `course` (a trainer run's recorded course, read by the caller) or on open ground.
  SessionMotion(const record::Session& session, const vehicle::RobotFigures& figures,
                const std::optional<vehicle::Course>& course = std::nullopt);

  /// The model after every tick at or before t_ms; *tick: the last of them (-1: none).
  [[nodiscard]] vehicle::VehicleModel at(std::int64_t t_ms, std::int64_t* tick = nullptr) const;
  /// The model after every tick.
  [[nodiscard]] const vehicle::VehicleModel& end() const { return end_; }
  /// Every point the trail took (the first: the start), in time order.
  [[nodiscard]] const std::vector<TimedPoint>& trail() const { return trail_; }
  /// The last tick's time (0 for a session without ticks).
  [[nodiscard]] std::int64_t length_ms() const { return length_ms_; }

 private:
  struct Snapshot {
    TickPlace place;  ///< the first tick not fed yet
    std::int64_t t_ms = 0;
    vehicle::VehicleModel model;
  };
  const record::Session& session_;
  std::vector<Snapshot> snapshots_;
  vehicle::VehicleModel start_;  ///< before any tick
  vehicle::VehicleModel end_;
  std::vector<TimedPoint> trail_;
  std::int64_t length_ms_ = 0;
};

}  // namespace andros::view
