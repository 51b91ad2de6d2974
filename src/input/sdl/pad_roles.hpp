#pragma once
// The operator's and the supervisor's controllers, and the rules that keep a
// role from ever taking the other's pad (docs/controllers.md, "Two
// controllers"): with a supervisor, a role is bound to the pad it connects
// first and takes back only that pad; it never takes a pad that may be the
// other's; and two pads of one model that SDL cannot tell apart (no serial,
// no port named) are refused, each time with one line naming both.

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "andros/input/input_state.hpp"
#include "controller_selection.hpp"
#include "pad_facts.hpp"
#include "sdl_device.hpp"

namespace andros::input {

/// One controller the source looks for and, once found, reads.
struct Slot {
  Slot(Pad p, ControllerSelection s) : pad(p), selection(std::move(s)) {}

  /// "controller 1", "the supervisor's controller (controller 1)": what the log says.
  [[nodiscard]] std::string describe() const;
  /// "the operator's controller", "the supervisor's controller".
  [[nodiscard]] std::string role() const;

  Pad pad;
  ControllerSelection selection;
  std::unique_ptr<SdlDevice> device;
  /// The pad this role is bound to (with a supervisor; not for a port named by
  /// its path, which is the binding itself): its model and serial.
  std::optional<PadFacts> bound;
  std::int64_t connect_t = -1;
  bool rescan = true;  // a device may have appeared: look for the chosen one
  bool waiting_logged = false;
  /// Why the last scan took no pad although one was wanted (PadRoles::may_take's words); "" once it has one.
  std::string refused;
};

class PadRoles {
 public:
  explicit PadRoles(PadReader reader) : reader_(std::move(reader)) {}

  /// Whether slot may open pad (one of attached, every device attached now);
  /// other: the other role, nullptr without a supervisor. A refusal the
  /// operator must hear of (a pad that may be the other role's) is logged,
  /// and said in refused in a few words for the screen's state line.
  bool may_take(const Slot& slot, const Slot* other, PadFacts& pad, std::vector<PadFacts>& attached,
                std::string& refused);
  /// Binds slot to pad, just opened (with a supervisor).
  void bind(Slot& slot, PadFacts pad) const;

  [[nodiscard]] const PadReader& reader() const { return reader_; }

 private:
  /// Whether a and b are surely two pads: models differ, both have serials
  /// and they differ, or a port named by either role holds one and not the other.
  bool told_apart(const Slot& slot, const Slot& other, PadFacts& a, PadFacts& b) const;
  /// The pad the slot's binding or selection names.
  bool wanted(const Slot& slot, PadFacts& pad) const;

  PadReader reader_;
  /// Models seen as two pads that could not be told apart, and that line:
  /// for the rest of the run no role takes a pad of such a model (but by its port).
  std::map<std::string, std::string> twins_;
};

}  // namespace andros::input
