#include "andros/view/session_motion.hpp"

#include <algorithm>

#include "andros/timing/rate.hpp"

namespace andros::view {

void for_each_tick(const record::Session& s, const TickVisitor& visit, TickPlace from) {
  const timing::FrameClock clock(s.settings.rate_millihertz);
  const std::int64_t last = s.end ? s.end->last_tick : (s.frames.empty() ? -1 : s.frames.back().tick);
  for (std::size_t i = from.record; i < s.frames.size(); ++i) {
    const auto& f = s.frames[i];
    // The record holds on every tick to the next record's (less the ticks it skipped).
    const std::int64_t through = i + 1 < s.frames.size() ? s.frames[i + 1].tick - s.frames[i + 1].gap - 1 : last;
    const std::int64_t first = i == from.record && from.tick >= 0 ? from.tick : f.tick;
    for (std::int64_t tick = first; tick <= through; ++tick) {
      if (!visit(tick, clock.time_of(tick), f)) return;
    }
  }
}

protocol::DecodedFrame received_frame(const protocol::DataBytes& data) {
  protocol::DecodedFrame frame;
  frame.data = data;
  frame.checksum_ok = true;
  frame.valid = true;
  return frame;
}

void feed_tick(vehicle::VehicleModel& model, std::int64_t t_ms, const protocol::DataBytes& data, bool delivered) {
  constexpr std::int64_t kNsPerMs = 1'000'000;
  if (delivered) model.on_frame(received_frame(data), t_ms * kNsPerMs);
  else model.advance(t_ms * kNsPerMs);
}

SessionMotion::SessionMotion(const record::Session& session, const vehicle::RobotFigures& figures,
                             const std::optional<vehicle::Course>& course)
    : session_(session), start_(figures, course), end_(start_) {
  const std::int64_t every = std::max(kSnapshotTicks, session.live_ticks() / std::int64_t{kSnapshots} + 1);
  trail_.push_back({0, end_.trail().back().x, end_.trail().back().y});
  std::int64_t fed = 0;
  for_each_tick(session, [&](std::int64_t tick, std::int64_t t_ms, const record::FrameRecord& f) {
    if (fed % every == 0) {
      snapshots_.push_back({{static_cast<std::size_t>(&f - session.frames.data()), tick}, t_ms, end_});
    }
    ++fed;
    feed_tick(end_, t_ms, f.data, f.delivered());
    const auto& p = end_.trail().back();
    // A new point is one the trail did not end with (two in a row are kTrailStep apart).
    if (p.x != trail_.back().x || p.y != trail_.back().y) trail_.push_back({t_ms, p.x, p.y});
    length_ms_ = t_ms;
    return true;
  });
}

vehicle::VehicleModel SessionMotion::at(std::int64_t t_ms, std::int64_t* tick) const {
  if (tick != nullptr) *tick = -1;
  // The last snapshot at or before t (the first is the start, before any tick).
  const auto after = std::upper_bound(snapshots_.begin(), snapshots_.end(), t_ms,
                                      [](std::int64_t t, const Snapshot& s) { return t < s.t_ms; });
  if (after == snapshots_.begin()) return start_;
  const auto& from = *std::prev(after);
  auto model = from.model;
  for_each_tick(
      session_,
      [&](std::int64_t k, std::int64_t t, const record::FrameRecord& f) {
        if (t > t_ms) return false;
        feed_tick(model, t, f.data, f.delivered());
        if (tick != nullptr) *tick = k;
        return true;
      },
      from.place);
  return model;
}

}  // namespace andros::view
