// The plot's lanes (andros/view/plot.hpp): what the session or the script
// records is what the controllers did (their events) and what the link did;
// what the lanes show is read from it with the mapping in effect, the one
// the loop read it with: the deadman held (the deadman's own rule), a stop
// button, the consent or an arming input held (a button down, an axis past
// the mapping's default threshold: view/held_inputs.hpp, the export's
// reading too), a controller connected, the link up. The work is the
// events', never a tick's.
#include <algorithm>
#include <exception>
#include <variant>

#include "andros/base/error.hpp"
#include "andros/record/session_replay.hpp"
#include "andros/view/held_inputs.hpp"
#include "andros/view/plot.hpp"

namespace andros::view {
namespace {

constexpr std::size_t kLaneCount = 8;

/// The arming inputs of every weapon binding, in any layer.
std::vector<mapping::InputUse> arming_inputs(const mapping::Mapping& m) {
  std::vector<mapping::InputUse> out;
  for (const auto ref : mapping::all_bindings(m)) {
    const auto& b = mapping::binding_at(m, ref);
    if (std::holds_alternative<mapping::WeaponBinding>(b.rule) && b.arm) out.push_back(*b.arm);
  }
  return out;
}

/// The lanes that apply: a supervisor's only when one is configured, the
/// consent only when a mapping asks for it, arming only when one has weapons.
bool applies(LaneKind kind, const mapping::Mapping& m, bool supervised) {
  switch (kind) {
    case LaneKind::kSupervisorPad:
    case LaneKind::kSupervisorStop: return supervised;
    case LaneKind::kConsent: return supervised && m.supervisor && m.supervisor->weapons_consent;
    case LaneKind::kArming: return !arming_inputs(m).empty();
    case LaneKind::kOperatorStop: return m.estop.has_value();
    default: return true;
  }
}

}  // namespace

LaneBuilder::LaneBuilder(const mapping::Mapping& mapping, bool supervised)
    : mapping_(mapping), supervised_(supervised), lanes_(kLaneCount), on_(kLaneCount, false) {
  for (std::size_t i = 0; i < kLaneCount; ++i) lanes_[i].kind = static_cast<LaneKind>(i);
  set(LaneKind::kLink, 0, true);
}

void LaneBuilder::use_mapping(std::int64_t t_ms, const mapping::Mapping& mapping) {
  mapping_ = mapping;
  read_inputs(t_ms);
}

void LaneBuilder::event(const input::InputEvent& e) {
  if (e.is_fault() || e.type == input::InputEvent::Type::kEnd) return;
  input_.apply(e);
  read_inputs(e.t_ms);
}

void LaneBuilder::link(std::int64_t t_ms, bool up) {
  const std::int64_t t = std::max<std::int64_t>(t_ms, 0);
  if (t == 0) {
    // What the link was at the start: it replaces the assumption (up), and
    // whatever an earlier report at the start said.
    lanes_[static_cast<std::size_t>(LaneKind::kLink)].spans.clear();
    on_[static_cast<std::size_t>(LaneKind::kLink)] = false;
  }
  set(LaneKind::kLink, t, up);
}

void LaneBuilder::read_inputs(std::int64_t t) {
  const auto h = held_inputs(input_, mapping_);
  set(LaneKind::kOperatorPad, t, h.operator_pad);
  set(LaneKind::kSupervisorPad, t, h.supervisor_pad);
  set(LaneKind::kDeadman, t, h.deadman);
  set(LaneKind::kOperatorStop, t, h.operator_stop);
  set(LaneKind::kSupervisorStop, t, h.supervisor_stop);
  set(LaneKind::kConsent, t, h.consent);
  const auto arms = arming_inputs(mapping_);
  const auto& op = input_.operator_pad();
  set(LaneKind::kArming, t,
      std::any_of(arms.begin(), arms.end(), [&op](const mapping::InputUse& u) { return held(op, u); }));
}

void LaneBuilder::set(LaneKind kind, std::int64_t t_ms, bool on) {
  const auto i = static_cast<std::size_t>(kind);
  if (on_[i] == on) return;
  on_[i] = on;
  auto& spans = lanes_[i].spans;
  // A press and its release at the same time stay a span: a stop tapped
  // within a millisecond stopped the vehicle all the same.
  if (on) spans.push_back(PlotSpan{t_ms, -1});
  else spans.back().to_ms = t_ms;
}

std::vector<PlotLane> LaneBuilder::lanes() const {
  std::vector<PlotLane> out;
  for (const auto& lane : lanes_) {
    if (applies(lane.kind, mapping_, supervised_)) out.push_back(lane);
  }
  return out;
}

void add_lanes(PlotInput& in, const record::Session& session) {
  std::vector<mapping::ValidMapping> mappings;
  try {
    mappings = record::recorded_mappings(session);
  } catch (const InputError& e) {
    in.lanes_missing = std::string("the recorded mapping cannot be read: ") + e.what();
    return;
  }
  for (const auto& m : mappings) {
    for (auto& name : weapon_layers(*m)) {
      if (std::find(in.weapon_layers.begin(), in.weapon_layers.end(), name) == in.weapon_layers.end())
        in.weapon_layers.push_back(std::move(name));
    }
  }
  LaneBuilder lanes(*mappings.front(), session.settings.supervised);
  std::size_t reload = 0;
  std::size_t next_mapping = 1;
  for (const auto& e : session.events) {
    for (; reload < session.reloads.size() && session.reloads[reload].t_ms <= e.t_ms; ++reload) {
      if (session.reloads[reload].settings) lanes.use_mapping(session.reloads[reload].t_ms, *mappings[next_mapping++]);
    }
    lanes.event(e);
  }
  for (const auto& l : session.links) lanes.link(l.t_ms, l.state == link::LinkState::kUp);
  in.lanes = lanes.lanes();
}

std::vector<std::string> weapon_layers(const mapping::Mapping& m) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < m.layers.size(); ++i) {
    const auto refs = mapping::effective_bindings(m, static_cast<int>(i));
    if (std::any_of(refs.begin(), refs.end(), [&m](mapping::BindingRef r) {
          return std::holds_alternative<mapping::WeaponBinding>(mapping::binding_at(m, r).rule);
        })) {
      out.push_back(m.layers[i].name);
    }
  }
  return out;
}

}  // namespace andros::view
