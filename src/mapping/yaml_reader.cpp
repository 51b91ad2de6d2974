#include "yaml_reader.hpp"

#include <charconv>
#include <cmath>
#include <optional>
#include <set>
#include <sstream>
#include <vector>

#include <yaml-cpp/eventhandler.h>

#include "andros/base/text.hpp"
#include "andros/base/text_file.hpp"

namespace andros::mapping::yaml {
namespace {

std::string join(std::initializer_list<std::string_view> words) {
  std::string out;
  for (const auto w : words) {
    if (!out.empty()) out += ", ";
    out += w;
  }
  return out;
}

std::string catalogue_names() {
  std::string out;
  for (const auto& s : protocol::kSignals) {
    if (!out.empty()) out += ' ';
    out += s.name;
  }
  return out;
}

// Walks the document as the loader will, each alias as a copy of what it
// names, counting nodes as they are found so that the walk itself is bounded.
// Returns how many it found, at most budget.
std::size_t count_nodes(const Reader& r, std::string_view kind, const YAML::Node& root, std::size_t budget) {
  std::vector<YAML::Node> todo{root};
  std::size_t found = 1;
  while (!todo.empty()) {
    const YAML::Node node = todo.back();
    todo.pop_back();
    if (!node.IsMap() && !node.IsSequence()) continue;
    found += node.IsMap() ? 2 * node.size() : node.size();
    if (found > budget) {
      r.fail(node, "the " + std::string(kind) + " is too large: more than " + std::to_string(kMaxNodes) +
                       " YAML nodes in this file and the files it extends, counting each alias as a copy of what "
                       "it names (docs/mapping.md)");
    }
    for (const auto& child : node) {
      if (node.IsMap()) {
        todo.push_back(child.first);
        todo.push_back(child.second);
      } else {
        todo.push_back(child);
      }
    }
  }
  return found;
}

/// Where the first node of each document starts, read off the parser's events.
class DocumentStarts final : public YAML::EventHandler {
 public:
  std::vector<YAML::Mark> marks;

  void OnDocumentStart(const YAML::Mark& /*mark*/) override { in_new_document_ = true; }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& mark, YAML::anchor_t /*anchor*/) override { note(mark); }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t /*anchor*/) override { note(mark); }
  void OnScalar(const YAML::Mark& mark, const std::string& /*tag*/, YAML::anchor_t /*anchor*/,
                const std::string& /*value*/) override {
    note(mark);
  }
  void OnSequenceStart(const YAML::Mark& mark, const std::string& /*tag*/, YAML::anchor_t /*anchor*/,
                       YAML::EmitterStyle::value /*style*/) override {
    note(mark);
  }
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark& mark, const std::string& /*tag*/, YAML::anchor_t /*anchor*/,
                  YAML::EmitterStyle::value /*style*/) override {
    note(mark);
  }
  void OnMapEnd() override {}

 private:
  void note(const YAML::Mark& mark) {
    if (in_new_document_) marks.push_back(mark);
    in_new_document_ = false;
  }
  bool in_new_document_ = false;
};

/// Where a second document starts, if the text has one. At most two documents
/// are read: yaml-cpp 0.7's parser, given text it cannot take up (a lone ','),
/// reports an empty document there again and again without moving on, so
/// YAML::LoadAll never returns. Such text is a syntax error at that place.
std::optional<YAML::Mark> second_document(const std::string& text) {
  std::istringstream in(text);
  YAML::Parser parser(in);
  DocumentStarts starts;
  if (!parser.HandleNextDocument(starts) || !parser.HandleNextDocument(starts) || starts.marks.size() < 2) {
    return std::nullopt;
  }
  if (starts.marks[1].pos <= starts.marks[0].pos) {
    const auto at = static_cast<std::size_t>(starts.marks[1].pos);
    throw YAML::ParserException(starts.marks[1],
                                "unexpected " + (at < text.size() ? quote(text.substr(at, 1)) : "text"));
  }
  return starts.marks[1];
}

}  // namespace

YAML::Node Reader::load_document(std::size_t& budget) const {
  const std::string text = text_ != nullptr ? *text_ : read_text_file(file_, kMappingLimits);
  YAML::Node document;
  std::optional<YAML::Mark> second;
  try {
    document = YAML::Load(text);
    second = second_document(text);
  } catch (const YAML::ParserException& e) {
    throw InputError(SourcePos{file_, e.mark.line + 1, e.mark.column + 1}, "YAML syntax: " + e.msg);
  } catch (const YAML::Exception& e) {
    throw InputError(SourcePos{file_}, std::string("cannot read: ") + e.what());
  }
  if (second) {
    throw InputError(SourcePos{file_, second->line + 1, second->column + 1},
                     "a second YAML document ('---'): a " + std::string(kind_) + " file holds one");
  }
  budget -= count_nodes(*this, kind_, document, budget);
  return document;
}

SourcePos Reader::pos(const YAML::Node& node) const {
  const auto mark = node.Mark();
  if (mark.is_null()) return SourcePos{file_};
  return SourcePos{file_, mark.line + 1, mark.column + 1};
}

void Reader::fail(const YAML::Node& node, const std::string& message) const { throw InputError(pos(node), message); }

void Reader::expect_map(const YAML::Node& node, std::string_view what) const {
  if (!node.IsMap()) fail(node, std::string(what) + " must be a map of 'key: value' lines");
}

void Reader::expect_list(const YAML::Node& node, std::string_view what) const {
  if (!node.IsSequence()) fail(node, std::string(what) + " must be a list");
}

void Reader::expect_keys(const YAML::Node& map, std::initializer_list<std::string_view> allowed,
                         std::string_view what) const {
  expect_map(map, what);
  std::set<std::string> seen;
  for (const auto& kv : map) {
    const auto key = text(kv.first, "a key");
    bool known = false;
    for (const auto a : allowed) known = known || a == key;
    if (!known) {
      fail(kv.first, "unknown key " + quote(key) + " in " + std::string(what) + " (expected " + join(allowed) + ")");
    }
    if (!seen.insert(key).second) fail(kv.first, "key " + quote(key) + " given twice");
  }
}

std::string Reader::text(const YAML::Node& node, std::string_view what) const {
  if (!node.IsScalar()) fail(node, std::string(what) + " must be a single value");
  return node.Scalar();
}

long long Reader::integer(const YAML::Node& node, long long min, long long max, std::string_view what) const {
  const auto s = text(node, what);
  std::string_view digits = s;
  int base = 10;
  if (digits.size() > 2 && digits[0] == '0' && to_lower(digits[1]) == 'x') {
    digits.remove_prefix(2);
    base = 16;
  }
  const auto parsed = to_integer(digits, base);
  if (!parsed) fail(node, std::string(what) + " " + quote(s) + " is not a whole number");
  const long long value = *parsed;
  if (value < min || value > max) {
    fail(node, std::string(what) + " " + s + " is out of range " + std::to_string(min) + ".." + std::to_string(max));
  }
  return value;
}

double Reader::number(const YAML::Node& node, double min, double max, bool max_open, std::string_view what) const {
  const auto s = text(node, what);
  double value = 0;
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (s.empty() || ec != std::errc() || ptr != s.data() + s.size() || !std::isfinite(value)) {
    fail(node, std::string(what) + " " + quote(s) + " is not a number");
  }
  if (value < min || value > max || (max_open && value == max)) {
    char range[64];
    std::snprintf(range, sizeof range, "%g..%g%s", min, max, max_open ? " (excluded)" : "");
    fail(node, std::string(what) + " " + s + " is out of range " + range);
  }
  return value;
}

bool Reader::boolean(const YAML::Node& node, std::string_view what) const {
  const auto s = text(node, what);
  if (s == "true") return true;
  if (s == "false") return false;
  fail(node, std::string(what) + " must be true or false, not " + quote(s));
}

input::InputKey Reader::button(const YAML::Node& node) const {
  const auto name = text(node, "a button");
  const auto key = input::parse_button_name(name);
  if (!key) {
    fail(node, "unknown button " + quote(name) +
                   " (an SDL game-controller button such as a, leftshoulder, dpup; a joystick button "
                   "number; or a hat direction such as hat0up)");
  }
  return *key;
}

input::InputKey Reader::axis(const YAML::Node& node) const {
  const auto name = text(node, "an axis");
  const auto key = input::parse_axis_name(name);
  if (!key) {
    fail(node, "unknown axis " + quote(name) +
                   " (leftx, lefty, rightx, righty, lefttrigger, righttrigger, or a joystick axis number)");
  }
  return *key;
}

input::InputKey Reader::button_or_trigger(const YAML::Node& node, std::string_view what) const {
  const auto name = text(node, what);
  if (const auto key = input::parse_button_name(name)) return *key;
  if (name == "lefttrigger" || name == "righttrigger") return *input::parse_axis_name(name);
  fail(node, std::string(what) + " " + quote(name) + " is not a button or a trigger (lefttrigger, righttrigger)");
}

protocol::SignalId Reader::signal(const YAML::Node& node) const {
  const auto name = text(node, "a signal");
  if (const auto id = protocol::find_signal(name)) return *id;
  // A raw address as printed in the ICD: byteN.B for a bit, byteN for a byte.
  unsigned byte = 0;
  int bit = protocol::kWholeByte;
  if (name.starts_with("byte")) {
    std::string_view rest = std::string_view(name).substr(4);
    const auto dot = rest.find('.');
    const auto byte_text = rest.substr(0, dot);
    const auto byte_value = to_integer(byte_text);
    bool ok = byte_value && !byte_text.starts_with('-') && *byte_value < static_cast<long long>(protocol::kDataBytes);
    if (ok) byte = static_cast<unsigned>(*byte_value);
    if (ok && dot != std::string_view::npos) {
      const auto bit_text = rest.substr(dot + 1);
      const auto bit_value = to_integer(bit_text);
      ok = bit_text.size() == 1 && bit_value && *bit_value >= 0 && *bit_value <= 7;
      if (ok) bit = static_cast<int>(*bit_value);
    }
    if (ok) {
      if (byte == protocol::kTrailerByte) fail(node, "byte 15 is fixed at 0x02 by the protocol; it cannot be a target");
      if (bit != protocol::kWholeByte &&
          protocol::is_fixed_bit(static_cast<std::uint8_t>(byte), static_cast<std::uint8_t>(bit))) {
        fail(node, "byte " + std::to_string(byte) + " bit " + std::to_string(bit) +
                       " is a fixed validation bit; it cannot be a target");
      }
      for (std::size_t i = 0; i < protocol::kSignals.size(); ++i) {
        if (protocol::kSignals[i].byte == byte && protocol::kSignals[i].bit == bit)
          return static_cast<protocol::SignalId>(i);
      }
      fail(node, "'" + name + "' is a whole data byte of bit signals; name one bit (byte" + std::to_string(byte) +
                     ".0 .. byte" + std::to_string(byte) + ".7) or a signal");
    }
  }
  fail(node, "unknown signal " + quote(name) + " (expected one of: " + catalogue_names() + ")");
}

}  // namespace andros::mapping::yaml
