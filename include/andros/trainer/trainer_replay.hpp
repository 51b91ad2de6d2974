#pragma once
/// A recorded session replayed as motion on the trainer's page
/// (docs/trainer.md, "Replaying a session"): its frames integrated once by
/// the vehicle model (view::SessionMotion), the state lane read from its
/// records, and the object at any time for the page's play, pause, speed
/// and seek. Nothing outside the session is read.

#include <cstdint>
#include <optional>
#include <string>

#include "andros/record/session.hpp"
#include "andros/vehicle/vehicle_model.hpp"
#include "andros/view/plot.hpp"
#include "andros/view/session_motion.hpp"

namespace andros::trainer {

/// A trainer run's course as its session recorded it (its text, never the
/// file), or none. Throws InputError for a text that is not a course.
std::optional<vehicle::Course> recorded_course(const record::Session& session);

/// The model's trail and pose, to the bit: "ended at x, y, heading; trail N
/// points, SHA-256 ..." (the live trainer's and a replay's are compared by it).
std::string trail_summary(const vehicle::VehicleModel& model);

class SessionReplay {
 public:
  /// session: read as verify reads it (the caller says what was left out, in note).
  SessionReplay(record::Session session, std::string note);
  SessionReplay(const SessionReplay&) = delete;  // its motion refers to its session
  SessionReplay& operator=(const SessionReplay&) = delete;

  /// GET /replay: the session's length, its name and note, the whole
  /// trail with times, the state lane (runs in the plot's colours), the
  /// robot's figures.
  [[nodiscard]] std::string replay_json() const;
  /// GET /state?t=SECONDS: the stream's object at t_ms (every tick at or before it fed).
  [[nodiscard]] std::string state_at(std::int64_t t_ms) const;
  /// GET /state: the object at the end, with the trail (as the live trainer's /state).
  [[nodiscard]] std::string end_state() const;
  [[nodiscard]] const view::SessionMotion& motion() const { return motion_; }

 private:
  /// The sample in effect at t_ms (the first before the first).
  [[nodiscard]] const view::PlotSample* sample_at(std::int64_t t_ms) const;
  [[nodiscard]] std::string object(const vehicle::VehicleModel& model, std::int64_t tick, std::int64_t t_ms) const;

  record::Session session_;
  std::string note_;
  view::SessionMotion motion_;
  std::vector<view::PlotSample> samples_;
};

}  // namespace andros::trainer
