#include "session_lines.hpp"

#include <algorithm>
#include <limits>

#include "andros/base/text.hpp"
#include "andros/record/session.hpp"

namespace andros::record {
namespace {

constexpr std::size_t kHashDigits = 64;

/// A session has no size limit of its own (rotation keeps the folder's); a line has.
constexpr TextLimits kSessionLimits{"session", std::numeric_limits<std::size_t>::max(), kMaxSessionLine};

bool only_nul(std::string_view text) { return text.find_first_not_of('\0') == std::string_view::npos; }

}  // namespace

bool split_record(std::string_view line, std::string_view& payload, std::string_view& hash) {
  if (line.size() < kHashDigits + 2 || line[line.size() - kHashDigits - 1] != ' ') return false;
  payload = line.substr(0, line.size() - kHashDigits - 1);
  hash = line.substr(line.size() - kHashDigits);
  return std::all_of(hash.begin(), hash.end(), [](char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'); });
}

std::optional<std::uint64_t> seq_of(std::string_view payload) {
  const auto space = payload.find(' ');
  const auto value = to_integer(payload.substr(0, space));
  if (!value || *value < 0) return std::nullopt;
  return static_cast<std::uint64_t>(*value);
}

namespace {

/// The path, once require_session_file() has refused what is not a regular file.
const std::filesystem::path& refused_unless_regular(const std::filesystem::path& path) {
  require_session_file(path);
  return path;
}

}  // namespace

SessionLines::SessionLines(const std::filesystem::path& path)
    : text_(TextReader::open_regular(refused_unless_regular(path).string(), kSessionLimits)) {}

std::optional<std::string_view> SessionLines::next() { return text_.next_line(); }

std::optional<std::uint64_t> SessionLines::nul_tail(std::string_view line) {
  if (line.empty() || !only_nul(line)) return std::nullopt;
  std::uint64_t bytes = line.size();
  while (const auto more = text_.next_line()) {
    if (!only_nul(*more)) return std::nullopt;
    bytes += more->size();
  }
  return bytes;
}

}  // namespace andros::record
