#pragma once
// What the oracle (safety_oracle.hpp) reads off the mappings a script may
// run: the initial one and every good file its reloads name. Permissive over
// all of them where a rule reads them so: the supervisor's stop button (its
// presses counted) only when all have that one, a panic point and a timeout only when all have one
// (the most lenient of them), the deadmen of any (a press of any may
// enable), the deadmen of all (a release of one makes the tick neutral), the
// arming inputs of any. The mapping in force is known exactly: a reload's is
// in force once its neutral frames are out (the caller says when), a reload
// of the same file while another is under way (or waits for a resume) keeps
// the one in force, a bad one cancels a good one not yet in force, and one
// asked for while suspended waits for the resume (the last one asked).

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
  std::optional<input::InputKey> sup_stop;  ///< the supervisor's stop button every possible mapping has
  std::optional<std::int64_t> timeout_ms;
  std::optional<int> panic;                  ///< the raw trigger value of the panic point
  std::set<input::InputKey> deadmen;         ///< every possible mapping's
  std::set<input::InputKey> common_deadmen;  ///< the deadmen every possible mapping has (a release's neutral tick)
  std::map<protocol::SignalId, std::set<input::InputKey>> arms;
  const mapping::Mapping* current = nullptr;  ///< the mapping in force
  const mapping::Mapping* pending = nullptr;  ///< a reload's, in force once the reload is done
  /// The last reload asked for while suspended, answered after the resume.
  struct Queued {
    bool any = false;
    const mapping::Mapping* loaded = nullptr;
    bool same_file = false;
  } queued;

  void add(const mapping::Mapping& m) {
    const bool first = current == nullptr;
    if (first) current = &m;
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

  /// A reload: loaded, the mapping it brings (nullptr: none, a bad file or
  /// the same file again, same_file); queue, asked for while suspended.
  void reload(const mapping::Mapping* loaded, bool same_file, bool queue) {
    if (loaded != nullptr) add(*loaded);
    if (queue) queued = {true, loaded, same_file};
    else pending = loaded != nullptr ? loaded : same_file ? current : nullptr;
  }
  /// The resume: the reload asked for while suspended begins (the same file: the one in force then).
  void resumed() {
    const Queued q = std::exchange(queued, Queued{});
    if (q.any) pending = q.loaded != nullptr ? q.loaded : q.same_file ? current : nullptr;
  }
  /// The reload done: its mapping in force. True when there was one (read
  /// afresh, even the same file: a new engine).
  bool take_up() {
    if (pending == nullptr) return false;
    current = std::exchange(pending, nullptr);
    return true;
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
