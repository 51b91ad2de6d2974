#pragma once
// The rest rule for drive and pivot, read off the mapping alone (not the
// engine's RestRule), shared by the property test and the engine fuzz target:
// when the binding that drives a centred byte changes (a layer), or the bridge
// becomes enabled (also with a new pad between two frames), the byte stays at
// centre until that binding's axis is seen inside its deadzone at a frame.

#include <string>
#include <variant>

#include "andros/mapping/model.hpp"

namespace andros::test {

/// The binding driving the centred byte `analog` in `layer` ("" = base): the
/// layer's own, else the base's unless a layer binding takes its axis.
inline const mapping::Binding* centre_driver(const mapping::Mapping& m, const std::string& layer,
                                             protocol::SignalId analog) {
  const auto drives = [&](const mapping::Binding& b) {
    const auto* a = std::get_if<mapping::AxisBinding>(&b.rule);
    return a != nullptr && a->analog == analog;
  };
  const mapping::Binding* base = nullptr;
  for (const auto& b : m.bindings) {
    if (drives(b)) base = &b;
  }
  for (const auto& l : m.layers) {
    if (l.name != layer) continue;
    for (const auto& b : l.bindings) {
      if (drives(b)) return &b;
      if (base == nullptr) continue;
      const auto axis = std::get<mapping::AxisBinding>(base->rule).axis;
      for (const auto& u : b.inputs) {
        if (u.key == axis) return nullptr;
      }
      if (b.arm && b.arm->key == axis) return nullptr;
    }
  }
  return base;
}

/// One centred byte, frame by frame.
class CentreWatch {
 public:
  /// Once per frame: must the byte be at centre now? `now` is the binding
  /// driving it (nullptr when not enabled), `restart` says the bridge became
  /// enabled or a new pad appeared since the last frame, `axis_value(key)`
  /// reads a raw axis.
  template <typename AxisValue>
  bool must_centre(const mapping::Binding* now, bool restart, const AxisValue& axis_value) {
    if (now == nullptr || restart || now != driver_) resting_ = false;
    driver_ = now;
    if (!resting_ && now != nullptr) {
      const auto& a = std::get<mapping::AxisBinding>(now->rule);
      const int v = axis_value(a.axis);
      const double x = v >= 0 ? v / 32767.0 : v / 32768.0;
      resting_ = (x < 0 ? -x : x) <= a.shape.deadzone;
    }
    return !resting_;
  }

 private:
  const mapping::Binding* driver_ = nullptr;
  bool resting_ = false;
};

}  // namespace andros::test
