#pragma once
/// A session as a table (docs/recording.md, "Export"): one row per tick the
/// live loop ran, with one strictly increasing time column, so that a
/// spreadsheet or PlotJuggler reads it as it is, and an investigator reads
/// who stopped, who reset, and what the hands held, on each row.

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>

#include "andros/base/error.hpp"
#include "andros/record/session.hpp"
#include "andros/record/session_replay.hpp"
#include "andros/vehicle/course.hpp"

namespace andros::view {

enum class ExportFormat : std::uint8_t { kCsv, kJsonl };

/// "csv" or "jsonl"; InputError at pos otherwise.
ExportFormat parse_export_format(std::string_view text, const SourcePos& pos);

/// Writes the rows, as they are made (nothing a tick is held): `t` (seconds,
/// 3 decimals), `tick`, `state`; `stopped_by` and `stop_pad` (the stop
/// latched: whose, and the pad that pressed it), `reset_by` and `reset_pad`
/// (the last stop's reset, until the next stop or enabled), from the stop
/// and reset records; `shutdown_requested` (1 from a shutdown request on,
/// while the run shuts down); `layer`; `link` (sent, busy, down or none: what
/// became of the frame); the input columns, read from the events with the
/// mapping in effect (load makes it from the recorded files): 1 when the
/// input was held at any moment since the row before, empty (JSON null) when
/// the mapping has no such input; then every signal of the frame by name;
/// then where the vehicle model is after the tick (session_motion.hpp:
/// vehicle_x, vehicle_y, vehicle_heading, the flippers, the arm's joints,
/// the gripper), to 3 decimals.
/// Text from outside (a layer's name, a pad's) is printable_text(); in CSV,
/// every text cell is csv_cell() (base/sink_text.hpp): never a formula (a
/// leading apostrophe), quoted as RFC 4180 says. CSV has a header row; JSONL a JSON object a line. Returns why
/// the input columns are empty throughout (the recorded mapping cannot be
/// read), or "". The vehicle's columns are the model's on `course` (a
/// trainer run's recorded course, read by the caller) or on open ground.
std::string export_session(const record::Session& session, ExportFormat format, std::ostream& out,
                           const record::SourcesLoader& load = record::load_recorded_mapping,
                           const std::optional<vehicle::Course>& course = std::nullopt);

}  // namespace andros::view
