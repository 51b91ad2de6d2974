#pragma once
// Strict reading of YAML nodes for the mapping loader: every value checked for
// type and range, every error an InputError at the node's FILE:LINE:COL.

#include <yaml-cpp/yaml.h>

#include <initializer_list>
#include <string>
#include <string_view>

#include "andros/base/error.hpp"
#include "andros/input/input_state.hpp"
#include "andros/protocol/signals.hpp"

namespace andros::mapping::yaml {

/// The most YAML nodes a mapping may hold, with all the files it extends,
/// counting an alias as a copy of what it names: a few aliases can otherwise
/// stand for billions of nodes.
inline constexpr std::size_t kMaxNodes = 100'000;

class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}
  /// Reads text as the contents of file (which need not exist): `learn`
  /// checks what it is about to write under the name it will have.
  /// kind: what the file is, as its errors name it ("mapping"; the trainer's "course").
  Reader(std::string file, const std::string* text, std::string_view kind = "mapping")
      : file_(std::move(file)), text_(text), kind_(kind) {}

  /// The file's one YAML document (a null node for an empty file), its nodes
  /// taken from budget. A second document, or more nodes than budget holds,
  /// is an InputError.
  [[nodiscard]] YAML::Node load_document(std::size_t& budget) const;
  [[nodiscard]] SourcePos pos(const YAML::Node& node) const;
  [[noreturn]] void fail(const YAML::Node& node, const std::string& message) const;

  /// A mapping node whose keys are all in `allowed` and none repeated.
  void expect_keys(const YAML::Node& map, std::initializer_list<std::string_view> allowed, std::string_view what) const;
  void expect_map(const YAML::Node& node, std::string_view what) const;
  void expect_list(const YAML::Node& node, std::string_view what) const;

  [[nodiscard]] std::string text(const YAML::Node& node, std::string_view what) const;
  /// Decimal or 0x-prefixed hex, within [min, max].
  [[nodiscard]] long long integer(const YAML::Node& node, long long min, long long max, std::string_view what) const;
  /// A decimal number within [min, max] (max_open: strictly below max).
  [[nodiscard]] double number(const YAML::Node& node, double min, double max, bool max_open,
                              std::string_view what) const;
  [[nodiscard]] bool boolean(const YAML::Node& node, std::string_view what) const;

  [[nodiscard]] input::InputKey button(const YAML::Node& node) const;
  [[nodiscard]] input::InputKey axis(const YAML::Node& node) const;
  /// A button, or a trigger axis (held past half way): the deadman and `arm`.
  [[nodiscard]] input::InputKey button_or_trigger(const YAML::Node& node, std::string_view what) const;
  /// A signal a binding may name: a canonical name or a raw `byteN.B`
  /// address of one. Fixed bits, byte 15 and unknown names are errors.
  [[nodiscard]] protocol::SignalId signal(const YAML::Node& node) const;

 private:
  std::string file_;
  const std::string* text_ = nullptr;
  std::string_view kind_ = "mapping";
};

}  // namespace andros::mapping::yaml
