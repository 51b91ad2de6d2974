#include "session_summary.hpp"

#include <algorithm>
#include <utility>

#include "andros/protocol/signals.hpp"

namespace andros::cli {
namespace {

/// Weapon signals set in data, in frame order.
std::vector<std::string> weapons_in(const protocol::DataBytes& data) {
  std::vector<std::string> out;
  for (const auto& sig : protocol::kSignals) {
    if (sig.kind == protocol::SignalKind::kWeapon && (data[sig.byte] >> sig.bit & 1) != 0) out.emplace_back(sig.name);
  }
  return out;
}

void count_fires(const record::Session& s, SessionSummary& out) {
  std::size_t state_at = 0;
  run::OpState state = run::OpState::kNoLink;
  for (std::size_t i = 0; i < s.frames.size(); ++i) {
    const auto& f = s.frames[i];
    // The record holds to the next one (or the end): enabled at its tick, or from a state change within it.
    const std::int64_t until = i + 1 < s.frames.size() ? s.frames[i + 1].t_ms : (s.end ? s.end->t_ms + 1 : f.t_ms + 1);
    std::optional<std::int64_t> enabled_at;
    for (; state_at < s.states.size() && s.states[state_at].t_ms <= f.t_ms; ++state_at)
      state = s.states[state_at].state;
    if (state == run::OpState::kEnabled) enabled_at = f.t_ms;
    for (std::size_t k = state_at; !enabled_at && k < s.states.size() && s.states[k].t_ms < until; ++k) {
      if (s.states[k].state == run::OpState::kEnabled) enabled_at = s.states[k].t_ms;
    }
    if (!f.offered || f.result != link::SendResult::kSent || !enabled_at) continue;
    const auto fired = weapons_in(f.data);
    if (fired.empty()) continue;
    if (!out.first_fire_ms) out.first_fire_ms = *enabled_at;
    out.weapons_fired = true;
    for (const auto& w : fired) {
      if (std::find(out.weapons.begin(), out.weapons.end(), w) == out.weapons.end()) out.weapons.push_back(w);
    }
  }
  std::sort(out.weapons.begin(), out.weapons.end(), [](const std::string& a, const std::string& b) {
    return protocol::find_signal(a) < protocol::find_signal(b);
  });
}

}  // namespace

SessionSummary summarize_session(const record::Session& s) {
  SessionSummary out;
  count_fires(s, out);
  for (const auto& r : s.stops) {
    if (r.reset) ++out.resets[r.by == run::StopBy::kSupervisor ? 1 : 0];
    else if (!r.again) ++out.stops[static_cast<std::size_t>(r.by)];  // stops latched (or made the supervisor's)
  }
  std::array<bool, 2> connected{};
  for (const auto& e : s.events) {
    const auto pad = static_cast<std::size_t>(e.pad);
    if (e.type == input::InputEvent::Type::kConnect) connected[pad] = true;
    if (e.type == input::InputEvent::Type::kDisconnect && std::exchange(connected[pad], false))
      ++out.controllers_lost[pad];
  }
  bool up = false;
  for (const auto& l : s.links) {
    const bool now = l.state == link::LinkState::kUp;
    if (up && !now && l.detail != link::kClosedDetail) ++out.links_lost;
    up = now;
  }
  return out;
}

}  // namespace andros::cli
