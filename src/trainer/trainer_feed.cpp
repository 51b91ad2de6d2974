#include "andros/trainer/trainer_feed.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

#include "andros/base/clock.hpp"
#include "andros/trainer/course_view.hpp"
#include "andros/trainer/trainer_replay.hpp"
#include "andros/view/session_motion.hpp"

namespace andros::trainer {
namespace {

using nlohmann::json;

/// Millimetres and hundredths of a degree are all the page draws; shorter lines.
std::string_view camera_name(vehicle::Camera c) {
  switch (c) {
    case vehicle::Camera::kNone: return "none";
    case vehicle::Camera::kFrontDrive: return "front drive";
    case vehicle::Camera::kGripper: return "gripper";
    case vehicle::Camera::kPtz: return "PTZ";
    case vehicle::Camera::kRearDrive: return "rear drive";
  }
  return "none";
}

json pose_json(const vehicle::Pose& p) { return {{"x", r3(p.x)}, {"y", r3(p.y)}, {"heading", r3(p.heading)}}; }

json stream_json(const vehicle::VehicleModel& model, const LoopFacts& facts) {
  const auto& s = model.state();
  const auto& a = s.arm;
  const auto& c = s.cameras;
  json fired = json::object();
  json held = json::array();
  for (std::size_t i = 0; i < vehicle::kWeaponCount; ++i) {
    fired[std::string(vehicle::weapon_name(i))] = s.fired[i];
    if (s.fire_bits[i]) held.push_back(vehicle::weapon_name(i));
  }
  json axes = json::object();
  for (const auto& [name, value] : facts.pad.axes) axes[name] = value;
  return {
      {"tick", facts.tick},
      {"t_ms", facts.t_ms},
      // The frames the vehicle decoded: the number of the frame this object is for.
      {"frame", s.frames + s.ignored},
      // Microseconds: the arrival times measure the loop's punctuality (bench/trainer_clients.py).
      {"time", std::round(static_cast<double>(s.time_ns - s.start_ns) / 1e3) / 1e6},
      {"state", facts.state},
      {"state_name", facts.state_name},
      {"layer", facts.layer},
      {"robot", model.figures().robot},
      {"pose", pose_json(s.pose)},
      {"speed", r3(s.speed)},
      {"turn_rate", r3(s.turn_rate)},
      {"flippers", {{"front", r3(s.front_flipper)}, {"rear", r3(s.rear_flipper)}}},
      {"arm",
       {{"torso", r3(a.torso)},
        {"shoulder", r3(a.shoulder)},
        {"elbow", r3(a.elbow)},
        {"wrist", r3(a.wrist)},
        {"wrist_extension", r3(a.wrist_extension)}}},
      {"gripper", {{"opening", r3(a.gripper_opening)}, {"rotation", r3(a.gripper_rotation)}}},
      {"cameras",
       {{"main", camera_name(c.main)},
        {"inset", camera_name(c.inset)},
        {"pan", r3(c.pan)},
        {"tilt", r3(c.tilt)},
        {"zoom", r3(c.zoom)},
        {"focus", r3(c.focus)},
        {"iris", r3(c.iris)},
        {"extender", r3(c.extender)}}},
      {"light", r3(s.light)},
      {"laser", s.laser},
      {"fired", fired},
      {"fire_held", held},
      {"tool_on", s.tool_on},
      {"enable_key", s.enable_key},
      {"safety", s.safety},
      {"drive", s.drive},
      {"watchdog", s.watchdog},
      {"frames", s.frames},
      {"ignored", s.ignored},
      {"pad",
       {{"frame", facts.pad.frame},
        {"connected", facts.pad.connected},
        {"name", facts.pad.name},
        {"buttons", facts.pad.buttons},
        {"axes", axes}}},
      {"course", course_state_json(model)},
      {"score", facts.score.empty() ? json(nullptr) : json::parse(facts.score)},
  };
}

/// The pad's inputs into `out` (its lists' room kept).
void read_pad(const input::InputState& input, const input::DeviceLayout* layout, PadInputs& out) {
  using input::InputKey;
  using input::InputKind;
  const auto& pad = input.operator_pad();
  out.connected = pad.connected();
  out.name = pad.name();
  out.buttons.clear();
  out.axes.clear();
  const auto hold = [&](InputKey key, std::string name) {
    if (pad.button(key).down) out.buttons.push_back(std::move(name));
  };
  const auto hat = [&](int h) {
    for (int d = 0; d < 4; ++d) {
      const InputKey key{InputKind::kHat, static_cast<std::uint16_t>(h * 4 + d)};
      hold(key, input::input_name(key));
    }
  };
  if (layout != nullptr && !layout->game_controller) {
    for (const auto& key : layout->buttons) hold(key, "button " + input::input_name(key));
    for (int h = 0; h < layout->hats; ++h) hat(h);
    for (const auto& key : layout->axes) out.axes.emplace_back("axis " + input::input_name(key), pad.axis(key));
    return;
  }
  for (std::size_t i = 0; i < input::kPadButtonNames.size(); ++i) {
    hold(InputKey{InputKind::kPadButton, static_cast<std::uint16_t>(i)}, std::string(input::kPadButtonNames[i]));
  }
  if (layout != nullptr) {
    for (const int h : layout->free_hats) hat(h);
  }
  for (std::size_t i = 0; i < input::kPadAxisNames.size(); ++i) {
    out.axes.emplace_back(input::kPadAxisNames[i],
                          pad.axis(InputKey{InputKind::kPadAxis, static_cast<std::uint16_t>(i)}));
  }
}

}  // namespace

std::string stream_object(const vehicle::VehicleModel& model, const LoopFacts& facts) {
  // Replacement characters for bytes that are not UTF-8 (a pad's name is hostile text).
  return stream_json(model, facts).dump(-1, ' ', false, json::error_handler_t::replace);
}

void TrainerFeed::queue_tick(std::int64_t t_ms, const protocol::DataBytes& data, bool delivered) {
  const auto head = queue_head_.load(std::memory_order_relaxed);
  if (head - queue_tail_.load(std::memory_order_acquire) == kQueueTicks) {
    lost_.fetch_add(1, std::memory_order_relaxed);
    return;
  }
  queue_[head % kQueueTicks] = Tick{t_ms, data, delivered, monotonic_ns()};
  queue_head_.store(head + 1, std::memory_order_release);
}

bool TrainerFeed::take_ticks() {
  auto tail = queue_tail_.load(std::memory_order_relaxed);
  const auto head = queue_head_.load(std::memory_order_acquire);
  if (tail == head) return false;
  const std::lock_guard lock(model_mutex_);
  for (; tail != head; ++tail) {
    const auto& t = queue_[tail % kQueueTicks];
    view::feed_tick(model_, t.t_ms, t.data, t.delivered);
    if (first_handed_ns_ < 0) first_handed_ns_ = t.handed_ns;
    handed_ns_ = t.handed_ns;
    // A frame taken: its own pad; none: the pad read for the next one is the newest the vehicle may show.
    take_pads(model_.state().frames + model_.state().ignored + (t.delivered ? 0 : 1));
    publish_locked();
    queue_tail_.store(tail + 1, std::memory_order_release);
  }
  return true;
}

void TrainerFeed::advance(std::int64_t now_ns) {
  const std::lock_guard lock(model_mutex_);
  model_.advance(now_ns);
  take_pads(model_.state().frames + model_.state().ignored + 1);
  publish_locked();
}

void TrainerFeed::take_pads(std::uint64_t frame) {
  const auto written = pads_written_.load(std::memory_order_acquire);
  auto read = pads_read_.load(std::memory_order_relaxed);
  // Swapped, not copied: the slot's lists keep their room for the loop's next pad.
  for (; read != written && pads_[read % kPadRing].frame <= frame; ++read) std::swap(pad_, pads_[read % kPadRing]);
  pads_read_.store(read, std::memory_order_release);
}

void TrainerFeed::republish() {
  const std::lock_guard lock(model_mutex_);
  publish_locked();
}

std::string TrainerFeed::summary() const {
  const std::lock_guard lock(model_mutex_);
  return trail_summary(model_);
}

void TrainerFeed::publish_locked() {
  LoopFacts facts;
  {
    const std::lock_guard lock(facts_mutex_);
    facts = facts_;
  }
  facts.pad = pad_;
  auto object = stream_json(model_, facts);
  // Seconds since the first tick's hand-over, to the microsecond: the loop's
  // punctuality as the page sees it (bench/trainer_clients.py).
  object["sent"] =
      handed_ns_ < 0 ? json(nullptr) : json(std::round(static_cast<double>(handed_ns_ - first_handed_ns_) / 1e3) / 1e6);
  latest_ = object.dump(-1, ' ', false, json::error_handler_t::replace);
  hub_.publish(latest_);
}

void TrainerFeed::observe(LoopFacts facts) {
  if (facts.sent) ++sent_;
  std::unique_lock lock(facts_mutex_, std::try_to_lock);
  if (lock.owns_lock()) facts_ = std::move(facts);
}

void TrainerFeed::observe_pad(const input::InputState& input, const input::DeviceLayout* layout) {
  const auto written = pads_written_.load(std::memory_order_relaxed);
  if (written - pads_read_.load(std::memory_order_acquire) == kPadRing) return;  // full: never wait
  auto& slot = pads_[written % kPadRing];
  read_pad(input, layout, slot);
  slot.frame = sent_ + 1;
  pads_written_.store(written + 1, std::memory_order_release);
}

void WatchedInput::pump(input::TickInput& input, std::int64_t now_ms) {
  inner_.pump(input, now_ms);
  const auto& state = input.state();
  const auto& pad = state.operator_pad();
  if (pad.connection() != layout_connection_) {
    layout_connection_ = pad.connection();
    layout_ = inner_.device();
  }
  feed_.observe_pad(state, pad.connected() && layout_ ? &*layout_ : nullptr);
}

std::string TrainerFeed::state_with_trail() const {
  const std::lock_guard lock(model_mutex_);
  if (latest_.empty()) return "{}";
  auto out = json::parse(latest_);
  json trail = json::array();
  for (const auto& p : model_.trail()) trail.push_back({r3(p.x), r3(p.y)});
  out["trail"] = std::move(trail);
  const auto& f = model_.figures();
  if (model_.course()) out["course_map"] = course_map_json(*model_.course());
  out["figures"] = {{"length", f.length_m.value},       {"width", f.width_m.value},     {"height", f.height_m.value},
                    {"upper_arm", f.upper_arm_m.value}, {"forearm", f.forearm_m.value}, {"flipper", f.flipper_m.value}};
  return out.dump(-1, ' ', false, json::error_handler_t::replace);
}

}  // namespace andros::trainer
