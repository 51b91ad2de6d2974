#include "andros/view/session_export.hpp"

#include <spdlog/fmt/fmt.h>

#include <algorithm>
#include <array>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "andros/base/sink_text.hpp"
#include "andros/base/text.hpp"
#include "andros/protocol/signals.hpp"
#include "andros/vehicle/robot_figures.hpp"
#include "andros/view/held_inputs.hpp"
#include "andros/view/session_motion.hpp"
#include "record_cursor.hpp"

namespace andros::view {
namespace {

/// An input column: its name, the fact it gives, and whether the mapping has such an input.
struct InputColumn {
  std::string_view name;
  bool HeldInputs::*held;
  bool (*in_mapping)(const mapping::Mapping&);
};

constexpr std::array<InputColumn, 6> kInputColumns = {{
    {"operator_deadman", &HeldInputs::deadman, [](const mapping::Mapping& m) { return m.deadman.has_value(); }},
    {"operator_estop", &HeldInputs::operator_stop, [](const mapping::Mapping& m) { return m.estop.has_value(); }},
    {"operator_reset", &HeldInputs::operator_reset, [](const mapping::Mapping& m) { return !m.stop_reset.empty(); }},
    {"supervisor_stop", &HeldInputs::supervisor_stop,
     [](const mapping::Mapping& m) { return m.supervisor.has_value(); }},
    {"supervisor_reset", &HeldInputs::supervisor_reset,
     [](const mapping::Mapping& m) { return m.supervisor && !m.supervisor->reset.empty(); }},
    {"supervisor_consent", &HeldInputs::consent,
     [](const mapping::Mapping& m) { return m.supervisor && m.supervisor->weapons_consent; }},
}};

/// The columns before the input columns (after `t`).
constexpr std::array<std::string_view, 9> kRecordColumns = {
    "tick", "state", "stopped_by", "stop_pad", "reset_by", "reset_pad", "shutdown_requested", "layer", "link"};

/// A length or an angle, to the millimetre or the thousandth of a degree
/// (as the trainer's stream gives them): its text, the same in CSV and JSONL.
struct Millis {
  std::string text;
};

Millis millis(double v) {
  auto text = fmt::format("{:.3f}", v);
  if (text == "-0.000") text.erase(0, 1);  // a value that rounds to zero is 0, whatever its sign
  return {std::move(text)};
}

/// A cell after `t`: empty (JSON null), a number, a fixed-point number, or text.
using Cell = std::variant<std::monostate, std::int64_t, Millis, std::string>;

/// The vehicle model's columns (docs/trainer.md, "The vehicle model"), after the signals.
struct MotionColumn {
  std::string_view name;
  double (*value)(const vehicle::VehicleState&);
};

constexpr std::array<MotionColumn, 12> kMotionColumns = {{
    {"vehicle_x", [](const vehicle::VehicleState& s) { return s.pose.x; }},
    {"vehicle_y", [](const vehicle::VehicleState& s) { return s.pose.y; }},
    {"vehicle_heading", [](const vehicle::VehicleState& s) { return s.pose.heading; }},
    {"front_flipper", [](const vehicle::VehicleState& s) { return s.front_flipper; }},
    {"rear_flipper", [](const vehicle::VehicleState& s) { return s.rear_flipper; }},
    {"arm_torso", [](const vehicle::VehicleState& s) { return s.arm.torso; }},
    {"arm_shoulder", [](const vehicle::VehicleState& s) { return s.arm.shoulder; }},
    {"arm_elbow", [](const vehicle::VehicleState& s) { return s.arm.elbow; }},
    {"arm_wrist", [](const vehicle::VehicleState& s) { return s.arm.wrist; }},
    {"arm_wrist_extension", [](const vehicle::VehicleState& s) { return s.arm.wrist_extension; }},
    {"gripper_opening", [](const vehicle::VehicleState& s) { return s.arm.gripper_opening; }},
    {"gripper_rotation", [](const vehicle::VehicleState& s) { return s.arm.gripper_rotation; }},
}};

/// The pad of a stop or a reset record (PadIdentity::describe()); a session
/// of an earlier version recorded only a stop's controller name, and no pad.
std::string pad_text(const record::StopRecord* r) {
  if (r == nullptr) return "";
  auto pad = r->pad;
  if (pad.name.empty()) pad.name = r->name;
  return pad.empty() ? "" : pad.describe();
}

/// A shutdown asked for (SIGINT's or SIGTERM's request record, or an event
/// script's `stop`, which stands for one): from when; the largest time for none.
std::int64_t shutdown_from(const record::Session& s) {
  std::int64_t from = std::numeric_limits<std::int64_t>::max();
  for (const auto& r : s.requests) {
    if (r.text == "stop") from = std::min(from, r.t_ms);
  }
  for (const auto& e : s.events) {
    if (e.type == input::InputEvent::Type::kShutdown) from = std::min(from, e.t_ms);
  }
  return from;
}

/// The session's controller events read with the mapping in effect (the
/// recorded one, each ok reload's from its time), row by row: an input
/// held at any moment since the row before counts on this row, so that a
/// press shorter than a tick still shows.
class InputCursor {
 public:
  InputCursor(const record::Session& s, std::vector<mapping::ValidMapping> mappings)
      : s_(s), mappings_(std::move(mappings)) {}

  /// Reads on to t (the events and reloads at or before it): what was held since the last call.
  HeldInputs since_last(std::int64_t t) {
    since_ = now_;  // what was held at the row before is held into this row's time
    for (; event_at_ < s_.events.size() && s_.events[event_at_].t_ms <= t; ++event_at_) {
      const auto& e = s_.events[event_at_];
      use_reloads_to(e.t_ms);
      if (e.is_fault() || e.type == input::InputEvent::Type::kEnd) continue;
      input_.apply(e);
      read();
    }
    use_reloads_to(t);
    return since_;
  }
  /// The mapping in effect at the last call's time.
  [[nodiscard]] const mapping::Mapping& mapping() const { return *mappings_[in_effect_]; }

 private:
  void use_reloads_to(std::int64_t t) {
    for (; reload_at_ < s_.reloads.size() && s_.reloads[reload_at_].t_ms <= t; ++reload_at_) {
      if (!s_.reloads[reload_at_].settings) continue;
      ++in_effect_;
      read();
    }
  }
  void read() {
    now_ = held_inputs(input_, mapping());
    since_ |= now_;
  }

  const record::Session& s_;
  std::vector<mapping::ValidMapping> mappings_;
  std::size_t in_effect_ = 0;
  std::size_t event_at_ = 0;
  std::size_t reload_at_ = 0;
  input::InputState input_;
  HeldInputs now_;
  HeldInputs since_;
};

std::string_view stopper_text(const record::StopRecord* r) { return r ? record::stopper_word(r->by) : ""; }

}  // namespace

ExportFormat parse_export_format(std::string_view text, const SourcePos& pos) {
  if (text == "csv") return ExportFormat::kCsv;
  if (text == "jsonl") return ExportFormat::kJsonl;
  throw InputError(pos, "expected csv or jsonl, got " + quote(text));
}

std::string export_session(const record::Session& s, ExportFormat format, std::ostream& out,
                           const record::SourcesLoader& load, const std::optional<vehicle::Course>& course) {
  std::vector<std::string_view> names(kRecordColumns.begin(), kRecordColumns.end());
  for (const auto& c : kInputColumns) names.push_back(c.name);
  for (const auto& sig : protocol::kSignals) names.push_back(sig.name);
  for (const auto& c : kMotionColumns) names.push_back(c.name);
  if (format == ExportFormat::kCsv) {
    out << 't';
    for (const auto name : names) out << ',' << name;
    out << '\n';
  }
  std::optional<InputCursor> inputs;
  std::string why_no_inputs;
  try {
    inputs.emplace(s, record::recorded_mappings(s, load));
  } catch (const InputError& e) {
    why_no_inputs = std::string("the recorded mapping cannot be read: ") + e.what();
  }
  RecordCursor records(s);
  const std::int64_t shutdown = shutdown_from(s);
  std::vector<Cell> cells;
  // The vehicle's motion, fed tick by tick as the trainer feeds it (session_motion.hpp).
  vehicle::VehicleModel model(vehicle::figures_for(s.settings.robot), course);
  for_each_tick(s, [&](std::int64_t tick, std::int64_t t, const record::FrameRecord& f) {
    records.at(t);
    feed_tick(model, t, f.data, f.delivered());
    cells = {tick,
             std::string(run::to_string(records.state)),
             std::string(stopper_text(records.stop)),
             pad_text(records.stop),
             std::string(stopper_text(records.reset)),
             pad_text(records.reset),
             std::int64_t{t >= shutdown && records.state == run::OpState::kShuttingDown},
             printable_text(records.layer),
             std::string(record::result_name(f))};
    const auto since = inputs ? std::optional(inputs->since_last(t)) : std::nullopt;
    for (const auto& c : kInputColumns) {
      if (since && c.in_mapping(inputs->mapping())) cells.emplace_back(std::int64_t{(*since).*c.held});
      else cells.emplace_back();
    }
    const auto values = protocol::read_signals(f.data);
    for (std::size_t k = 0; k < protocol::kSignalCount; ++k) cells.emplace_back(std::int64_t{values.values[k]});
    for (const auto& c : kMotionColumns) cells.emplace_back(millis(c.value(model.state())));
    const auto seconds = fmt::format("{}.{:03}", t / 1000, t % 1000);
    if (format == ExportFormat::kCsv) {
      out << seconds;
      for (const auto& cell : cells) {
        out << ',';
        if (const auto* n = std::get_if<std::int64_t>(&cell)) out << *n;
        else if (const auto* m = std::get_if<Millis>(&cell)) out << m->text;
        else if (const auto* text = std::get_if<std::string>(&cell)) out << csv_cell(*text);
      }
      out << '\n';
      return true;
    }
    nlohmann::ordered_json row{{"t", nlohmann::json::parse(seconds)}};
    for (std::size_t k = 0; k < cells.size(); ++k) {
      auto& value = row[std::string(names[k])];
      if (const auto* n = std::get_if<std::int64_t>(&cells[k])) value = *n;
      else if (const auto* m = std::get_if<Millis>(&cells[k])) value = nlohmann::json::parse(m->text);
      else if (const auto* text = std::get_if<std::string>(&cells[k])) value = *text;
    }
    out << row.dump() << '\n';
    return true;
  });
  return why_no_inputs;
}

}  // namespace andros::view
