#include "record_check.hpp"

#include <nlohmann/json.hpp>

#include "andros/base/text.hpp"

namespace andros::record {
namespace {

/// A record's text in a difference: one line, its bytes shown (a layer's or a pad's name may be any).
std::string shown(std::string_view payload) { return "'" + printable_line(payload) + "'"; }

}  // namespace

std::size_t RecordCheck::count(Kind kind) const {
  switch (kind) {
    case kRequest: return s_.requests.size();
    case kGate: return s_.gate_trips.size();
    case kState: return s_.states.size();
    case kTransition: return s_.transitions.size();
    case kStop: return s_.stops.size();
    case kLayer: return s_.layers.size();
    case kFrame: return s_.frames.size();
    case kKinds: break;
  }
  return 0;
}

RecordCheck::Recorded RecordCheck::recorded(Kind kind, std::size_t i) const {
  switch (kind) {
    case kRequest: {
      const auto& r = s_.requests[i];
      return {payload::request(r.t_ms, parse_request(r.text).value_or(run::Request::kNone)), r.t_ms, r.line};
    }
    case kGate:
      return {payload::gate(s_.gate_trips[i].t_ms, s_.gate_trips[i].text), s_.gate_trips[i].t_ms,
              s_.gate_trips[i].line};
    case kState: return {payload::state(s_.states[i].t_ms, s_.states[i].state), s_.states[i].t_ms, s_.states[i].line};
    case kTransition: {
      const auto& r = s_.transitions[i];
      return {payload::transition(r.t_ms, r.transition), r.t_ms, r.line};
    }
    case kStop: {
      const auto& r = s_.stops[i];
      return {r.reset ? payload::reset(r.t_ms, r.by, r.pad) : payload::stop(r.t_ms, r.by, r.pad, r.again), r.t_ms,
              r.line};
    }
    case kLayer: return {payload::layer(s_.layers[i].t_ms, s_.layers[i].text), s_.layers[i].t_ms, s_.layers[i].line};
    case kFrame: return {payload::frame(s_.frames[i]), s_.frames[i].t_ms, s_.frames[i].line};
    case kKinds: break;
  }
  return {};
}

bool RecordCheck::same_old_stop(const StopRecord& old, std::string_view made) {
  const std::string head = (old.reset ? payload::reset(old.t_ms, old.by, {}) : payload::stop(old.t_ms, old.by, {}));
  const auto pad_at = head.find(" {");
  if (made.substr(0, pad_at + 1) != std::string_view(head).substr(0, pad_at + 1)) return false;
  if (old.reset) return true;  // an earlier reset held no name
  const auto pad = nlohmann::json::parse(made.substr(pad_at + 1), nullptr, false);
  return pad.is_object() && pad.value("name", std::string()) == printable_text(old.name);
}

std::uint64_t RecordCheck::matched() const {
  std::uint64_t n = 0;
  for (const auto i : next_) n += i;
  return n;
}

void RecordCheck::differ(std::string what) {
  if (difference_.empty()) difference_ = std::move(what);
}

void RecordCheck::made(std::string_view payload) {
  if (!difference_.empty()) return;
  const auto word = payload.substr(0, payload.find(' '));
  Kind kind = kKinds;
  if (word == "request") kind = kRequest;
  else if (word == "gate") kind = kGate;
  else if (word == "state") kind = kState;
  else if (word == "transition") kind = kTransition;
  else if (word == "stop" || word == "reset") kind = kStop;
  else if (word == "layer") kind = kLayer;
  else if (word == "frame") kind = kFrame;
  if (kind == kKinds) return;  // an input's record: what the replay was given
  const std::size_t i = next_[kind];
  if (i >= count(kind)) {
    differ("the replay makes " + shown(payload) + " after line " + std::to_string(last_line_) +
           ", the session holds no such record");
    return;
  }
  const Recorded r = recorded(kind, i);
  const bool same = r.text == payload || (kind == kStop && !s_.stops[i].has_pad && same_old_stop(s_.stops[i], payload));
  if (!same) {
    differ("line " + std::to_string(r.line) + ": recorded " + shown(r.text) + ", the replay makes " + shown(payload));
  } else if (r.line <= last_line_) {
    differ("line " + std::to_string(r.line) + ": " + shown(r.text) +
           " is out of its place: the loop writes it after line " + std::to_string(last_line_));
  } else {
    last_line_ = r.line;
    ++next_[kind];
  }
}

void RecordCheck::finish() {
  if (!difference_.empty()) return;
  // The live run's last tick with a frame record: a session cut off may hold records of ticks after it.
  const std::int64_t replayed_ms = s_.end || s_.frames.empty() ? -1 : s_.frames.back().t_ms;
  const Recorded* first = nullptr;
  Recorded left;
  for (int k = 0; k < kKinds; ++k) {
    const auto kind = static_cast<Kind>(k);
    for (std::size_t i = next_[kind]; i < count(kind); ++i) {
      Recorded r = recorded(kind, i);
      if (!s_.end && r.t_ms > replayed_ms) {
        ++unproven_;
        if (first_unproven_line_ == 0 || r.line < first_unproven_line_) first_unproven_line_ = r.line;
      } else if (first == nullptr || r.line < left.line) {
        left = std::move(r);
        first = &left;
      }
    }
  }
  if (first != nullptr) {
    differ("line " + std::to_string(left.line) + ": recorded " + shown(left.text) +
           ", the replay makes no such record");
  }
}

}  // namespace andros::record
