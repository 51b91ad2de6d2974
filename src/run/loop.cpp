#include "andros/run/loop.hpp"

namespace andros::run {

ShutdownReport run_loop(const LoopParts& parts) {
  Bridge bridge(parts.clock, parts.input, parts.frames, parts.link, parts.options);
  bridge.run(parts.control, [&parts](const TickReport& r) {
    for (const auto& observe : parts.observers) observe(r);
  });
  return bridge.shutdown_report();
}

}  // namespace andros::run
