// The chain, record by record (andros/record/session.hpp): verify's half of
// the one reading, read_checked_session (session_read.cpp).
#include <string>

#include "andros/base/error.hpp"
#include "andros/base/text.hpp"
#include "andros/record/session.hpp"
#include "session_lines.hpp"

namespace andros::record {
namespace {

std::string chained_hash(const Sha256Digest& prev, std::string_view payload) {
  Sha256 sha;
  return to_hex(sha.update(prev).update(payload).finish());
}

Sha256Digest parse_digest(std::string_view hex) {
  Sha256Digest d{};
  for (std::size_t i = 0; i < d.size(); ++i) {
    d[i] = static_cast<std::uint8_t>(hex_value(hex[2 * i]) << 4 | hex_value(hex[2 * i + 1]));
  }
  return d;
}

/// The line of the record with this SEQ after line `after`, or 0.
int find_seq(const std::filesystem::path& path, std::uint64_t seq, int after) {
  SessionLines lines(path);
  while (const auto line = lines.next()) {
    std::string_view payload;
    std::string_view hash;
    if (lines.line_no() > after && split_record(*line, payload, hash) && seq_of(payload) == seq) return lines.line_no();
  }
  return 0;
}

std::string records_text(std::uint64_t from, std::uint64_t to) {
  return from == to ? "record " + std::to_string(from) : "records " + std::to_string(from) + ".." + std::to_string(to);
}

/// The first problem of one line, "" when it is the record `want` chained to prev.
std::string line_problem(const std::filesystem::path& path, std::string_view line, int at, std::uint64_t want,
                         const Sha256Digest& prev) {
  std::string_view payload;
  std::string_view hash;
  if (!split_record(line, payload, hash) || !seq_of(payload)) {
    return "record " + std::to_string(want) + " (line " + std::to_string(at) + ") altered: not a record line";
  }
  if (want == 0 && !is_session_start(line)) return "not a session: its first line is not '0 andros-session ...'";
  const std::uint64_t seq = *seq_of(payload);
  if (seq > want) {
    // Either the records before it were removed, or they come later: moved.
    if (const int later = find_seq(path, want, at); later != 0) {
      return "record " + std::to_string(want) + " reordered: found at line " + std::to_string(later) +
             ", after record " + std::to_string(seq) + " (line " + std::to_string(at) + ")";
    }
    return records_text(want, seq - 1) + " removed (before line " + std::to_string(at) + ")";
  }
  if (seq < want) {
    return "record " + std::to_string(seq) + " reordered: found at line " + std::to_string(at) + ", after record " +
           std::to_string(want - 1);
  }
  if (chained_hash(prev, payload) != hash) {
    return "record " + std::to_string(want) + " (line " + std::to_string(at) +
           ") altered: its content or hash no longer matches the chain";
  }
  return {};
}

}  // namespace

std::string ChainCheck::take(std::string_view line, int at) {
  if (auto problem = line_problem(path_, line, at, records_, prev_); !problem.empty()) return problem;
  const auto hash = line.substr(line.size() - 64);
  prev_ = parse_digest(hash);
  last_hash_ = std::string(hash);
  ++records_;
  const auto payload = line.substr(0, line.size() - 65);
  const auto kind_at = payload.find(' ');
  closed_ = kind_at != std::string_view::npos && payload.substr(kind_at + 1).starts_with("end ");
  return {};
}

VerifyResult verify_session(const std::filesystem::path& path) {
  return read_checked_session(path, Keep::kVerdict).verdict;
}

std::string cut_short_text(const VerifyResult& result) {
  return "cut short at line " + std::to_string(result.cut_short_line) +
         ": the run was cut off, power lost or disk full; the " + std::to_string(result.records) +
         " records before it are intact";
}

}  // namespace andros::record
