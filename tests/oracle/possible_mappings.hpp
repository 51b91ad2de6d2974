#pragma once
// What the oracle (safety_oracle.hpp) reads off the mappings a script may
// run: the initial one and every good file its reloads name. Permissive over
// all of them where it cannot know which one is in place: a stop button only
// when all have that one, a panic point and a timeout only when all have one
// (the most lenient of them), the deadmen of any (a press of any may
// enable), the deadmen of all (the stop's clearing waits for them), the
// arming inputs of any. The mapping in place (the last good one loaded) is
// known exactly: a reload sends neutral frames until it is in place.

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <utility>
#include <variant>
#include <vector>

#include "andros/mapping/model.hpp"

namespace andros::test {

struct PossibleMappings {
  std::optional<input::InputKey> estop;     ///< the stop button every possible mapping has
  std::optional<input::InputKey> sup_stop;  ///< the supervisor's stop button every possible mapping has
  std::optional<std::int64_t> timeout_ms;
  std::optional<int> panic;  ///< the raw trigger value of the panic point
  std::set<input::InputKey> deadmen;         ///< every possible mapping's
  std::set<input::InputKey> common_deadmen;  ///< the deadmen every possible mapping has (the stop's clearing)
  std::map<protocol::SignalId, std::set<input::InputKey>> arms;
  const mapping::Mapping* current = nullptr;  ///< the mapping in place once a reload is done
  bool known = true;  ///< false: a reload may have been cancelled by a later one, current is a guess

  void add(const mapping::Mapping& m) {
    const bool first = current == nullptr;
    current = &m;
    const std::optional<input::InputKey> e = m.estop ? std::optional(m.estop->key) : std::nullopt;
    estop = first || estop == e ? e : std::nullopt;
    const std::optional<input::InputKey> s = m.supervisor ? std::optional(m.supervisor->stop.key) : std::nullopt;
    sup_stop = first || sup_stop == s ? s : std::nullopt;
    const auto lenient = [first](auto& have, auto value) {
      if (!value || (!first && !have)) have.reset();
      else have = have && !first ? std::max(*have, *value) : *value;
    };
    lenient(timeout_ms, m.enable_timeout_ms);
    std::optional<int> p;
    if (m.deadman_panic) p = static_cast<int>(std::ceil(*m.deadman_panic * 32767.0));
    lenient(panic, p);
    std::set<input::InputKey> mine;
    if (m.deadman) mine.insert(m.deadman->key);
    if (first) common_deadmen = mine;
    else std::erase_if(common_deadmen, [&mine](input::InputKey k) { return !mine.contains(k); });
    if (m.deadman) deadmen.insert(m.deadman->key);
    const auto weapons = [this](const std::vector<mapping::Binding>& bindings) {
      for (const auto& b : bindings) {
        const auto* w = std::get_if<mapping::WeaponBinding>(&b.rule);
        if (w != nullptr && w->arm) arms[w->signal].insert(*w->arm);
      }
    };
    weapons(m.bindings);
    for (const auto& layer : m.layers) weapons(layer.bindings);
  }

  /// A reload: loaded, the mapping it brings (nullptr: none, or the same
  /// file again); pending, another reload not yet applied, which one without
  /// a mapping cancels (the mapping in place is then a guess). True when the
  /// stop buttons known changed.
  bool reload(const mapping::Mapping* loaded, bool pending) {
    const auto stops = std::pair(estop, sup_stop);
    if (loaded != nullptr) add(*loaded);
    known = loaded != nullptr || (known && !pending);
    return stops != std::pair(estop, sup_stop);
  }

  /// A weapon's arming input (of any possible mapping) held.
  template <typename Pads>
  [[nodiscard]] bool armed(protocol::SignalId id, const Pads& pads) const {
    const auto it = arms.find(id);
    return it != arms.end() &&
           std::any_of(it->second.begin(), it->second.end(), [&pads](input::InputKey k) { return pads.held(k); });
  }
};

}  // namespace andros::test
