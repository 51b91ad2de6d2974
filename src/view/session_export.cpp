#include "andros/view/session_export.hpp"

#include <spdlog/fmt/fmt.h>

#include <nlohmann/json.hpp>
#include <string>

#include "andros/protocol/signals.hpp"
#include "andros/timing/rate.hpp"

namespace andros::view {
namespace {

/// A CSV field, quoted when it must be (RFC 4180).
std::string csv(std::string_view text) {
  if (text.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(text);
  std::string out = "\"";
  for (const char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

/// What is in effect at each tick: the records with a time, taken in order.
class Cursor {
 public:
  explicit Cursor(const record::Session& s) : s_(s) {}
  void at(std::int64_t t) {
    while (state_at_ < s_.states.size() && s_.states[state_at_].t_ms <= t) state = s_.states[state_at_++].state;
    while (layer_at_ < s_.layers.size() && s_.layers[layer_at_].t_ms <= t) layer = s_.layers[layer_at_++].text;
    while (request_at_ < s_.requests.size() && s_.requests[request_at_].t_ms <= t) {
      if (s_.requests[request_at_++].text == "stop") stop_requested_ = true;
    }
  }
  [[nodiscard]] std::string_view stop() const {
    return stop_requested_ && state == run::OpState::kStopping ? "requested" : "";
  }
  run::OpState state = run::OpState::kNoLink;
  std::string layer;

 private:
  const record::Session& s_;
  std::size_t state_at_ = 0;
  std::size_t layer_at_ = 0;
  std::size_t request_at_ = 0;
  bool stop_requested_ = false;
};

}  // namespace

ExportFormat parse_export_format(std::string_view text, const SourcePos& pos) {
  if (text == "csv") return ExportFormat::kCsv;
  if (text == "jsonl") return ExportFormat::kJsonl;
  throw InputError(pos, "expected csv or jsonl, got " + quote(text));
}

void export_session(const record::Session& s, ExportFormat format, std::ostream& out) {
  const timing::FrameClock clock(s.settings.rate_millihertz);
  if (format == ExportFormat::kCsv) {
    out << "t,tick,state,stop,layer,link";
    for (const auto& sig : protocol::kSignals) out << ',' << sig.name;
    out << '\n';
  }
  Cursor cursor(s);
  const std::int64_t last = s.end ? s.end->last_tick : (s.frames.empty() ? -1 : s.frames.back().tick);
  for (std::size_t i = 0; i < s.frames.size(); ++i) {
    const auto& f = s.frames[i];
    const auto values = protocol::read_signals(f.data);
    // The record holds on every tick to the next record's (less the ticks it skipped).
    const std::int64_t through = i + 1 < s.frames.size() ? s.frames[i + 1].tick - s.frames[i + 1].gap - 1 : last;
    for (std::int64_t tick = f.tick; tick <= through; ++tick) {
      const std::int64_t t = clock.time_of(tick);
      cursor.at(t);
      const auto seconds = fmt::format("{}.{:03}", t / 1000, t % 1000);
      const auto state = run::to_string(cursor.state);
      if (format == ExportFormat::kCsv) {
        out << seconds << ',' << tick << ',' << state << ',' << cursor.stop() << ',' << csv(cursor.layer) << ','
            << record::result_name(f);
        for (std::size_t k = 0; k < protocol::kSignalCount; ++k) out << ',' << int{values.values[k]};
        out << '\n';
        continue;
      }
      nlohmann::ordered_json row{{"t", nlohmann::json::parse(seconds)},
                                 {"tick", tick},
                                 {"state", state},
                                 {"stop", cursor.stop()},
                                 {"layer", cursor.layer},
                                 {"link", record::result_name(f)}};
      for (std::size_t k = 0; k < protocol::kSignalCount; ++k)
        row[std::string(protocol::kSignals[k].name)] = values.values[k];
      out << row.dump() << '\n';
    }
  }
}

}  // namespace andros::view
