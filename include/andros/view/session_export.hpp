#pragma once
/// A session as a table (docs/recording.md, "Export"): one row per tick the
/// live loop ran, with one strictly increasing time column, so that a
/// spreadsheet or PlotJuggler reads it as it is.

#include <cstdint>
#include <ostream>
#include <string_view>

#include "andros/base/error.hpp"
#include "andros/record/session.hpp"

namespace andros::view {

enum class ExportFormat : std::uint8_t { kCsv, kJsonl };

/// "csv" or "jsonl"; InputError at pos otherwise.
ExportFormat parse_export_format(std::string_view text, const SourcePos& pos);

/// Writes the rows, as they are made (nothing a tick is held): the columns
/// `t` (seconds, 3 decimals), `tick`, `state`, `stop` (`requested` from a
/// stop request on, while the run stops), `layer`, `link` (sent, busy, down
/// or none: what became of the frame), then every signal of the frame by name.
/// CSV has a header row; JSONL a JSON object a line.
void export_session(const record::Session& session, ExportFormat format, std::ostream& out);

}  // namespace andros::view
