#include "andros/input/pad_identity.hpp"

#include <algorithm>
#include <array>
#include <utility>

#include "andros/base/error.hpp"
#include "andros/base/text.hpp"

namespace andros::input {
namespace {

/// A field's value as one word: printable_text(), a space as \x20.
std::string word(std::string_view value) {
  std::string out;
  for (char c : printable_text(value)) {
    if (c == ' ') {
      out += "\\x20";
    } else {
      out += c;
    }
  }
  return out;
}

}  // namespace

bool PadIdentity::same_pad(const PadIdentity& other) const {
  if (!serial.empty() && !other.serial.empty()) return serial == other.serial && guid == other.guid;
  return serial == other.serial && guid == other.guid && name == other.name && path == other.path;
}

std::string PadIdentity::describe() const {
  std::string out = name.empty() ? "(no name)" : printable_text(name);
  std::string rest;
  for (const auto& [label, value] : std::array<std::pair<const char*, const std::string*>, 3>{
           {{"path", &path}, {"serial", &serial}, {"guid", &guid}}}) {
    if (value->empty()) continue;
    rest += (rest.empty() ? "" : ", ") + std::string(label) + ' ' + printable_text(*value);
  }
  return rest.empty() ? out : out + " (" + rest + ")";
}

std::string PadIdentity::fields() const {
  std::string out;
  for (const auto& [label, value] : std::array<std::pair<const char*, const std::string*>, 3>{
           {{"path", &path}, {"serial", &serial}, {"guid", &guid}}}) {
    if (value->empty()) continue;
    out += (out.empty() ? "" : " ") + std::string(label) + '=' + word(*value);
  }
  return out;
}

PadId PadRegistry::id_of(const PadIdentity& pad) {
  if (pad.empty()) return kNoPad;
  for (const auto& [id, known] : pads_) {
    if (known.same_pad(pad)) return id;
  }
  pads_.emplace_back(++next_, pad);
  return next_;
}

const PadIdentity& PadRegistry::identity(PadId id) const {
  static const PadIdentity kNone;
  for (const auto& [known_id, known] : pads_) {
    if (known_id == id) return known;
  }
  return kNone;
}

void PadRegistry::keep(std::initializer_list<PadId> ids) {
  std::erase_if(pads_,
                [&ids](const auto& entry) { return std::find(ids.begin(), ids.end(), entry.first) == ids.end(); });
}

bool parse_pad_fields(std::string_view text, PadIdentity& id) {
  PadIdentity out;
  out.name = id.name;
  while (!text.empty()) {
    const auto space = text.find(' ');
    const std::string_view field = text.substr(0, space);
    text = space == std::string_view::npos ? std::string_view{} : text.substr(space + 1);
    if (field.empty()) continue;
    const auto eq = field.find('=');
    if (eq == std::string_view::npos) return false;
    const auto label = field.substr(0, eq);
    std::string* value = label == "path"     ? &out.path
                         : label == "serial" ? &out.serial
                         : label == "guid"   ? &out.guid
                                             : nullptr;
    if (value == nullptr || !value->empty()) return false;
    try {
      *value = unescape_text(field.substr(eq + 1), SourcePos{});
    } catch (const InputError&) {
      return false;
    }
    if (value->empty()) return false;
  }
  id = std::move(out);
  return true;
}

}  // namespace andros::input
