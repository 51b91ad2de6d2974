#pragma once
/// Which physical controller a pad is (docs/safety-states.md, "Whose stop"):
/// what SDL tells of the device (its path, serial, GUID, name), or a
/// script's `connect {path=... serial=... guid=...} NAME`. A stop is reset
/// only from the same physical pad that stopped, or by the supervisor.

#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace andros::input {

struct PadIdentity {
  std::string name;    ///< the controller's name (its descriptors)
  std::string path;    ///< the device path (/dev/input/event5); "" when unknown
  std::string serial;  ///< the serial number; "" where SDL gives none
  std::string guid;    ///< SDL's GUID, 32 hex digits; "" when unknown

  bool operator==(const PadIdentity&) const = default;

  /// Nothing known: no controller.
  [[nodiscard]] bool empty() const { return name.empty() && path.empty() && serial.empty() && guid.empty(); }
  /// The same physical controller, as far as can be told: with a serial on
  /// both, the same serial and GUID; without, the same GUID, name and path.
  /// A pad that cannot be told apart from another (no serial, a new path
  /// after a replug) is another pad: the safe answer (it may not reset).
  [[nodiscard]] bool same_pad(const PadIdentity& other) const;
  /// "NAME (path P, serial S, guid G)", what is known, escaped for a screen or log.
  [[nodiscard]] std::string describe() const;
  /// The identity's fields that are not the name, as a script writes them in
  /// braces: "path=P serial=S guid=G" (each only when known); "" for none.
  [[nodiscard]] std::string fields() const;
};

/// A physical pad as a small number (PadId), so that the operating state
/// keeps numbers, not names: the same pad (PadIdentity::same_pad) is given
/// the number it had while that number is kept. Only the pads kept (keep())
/// are remembered: a run that sees a million pads holds a handful.
using PadId = std::uint32_t;
inline constexpr PadId kNoPad = 0;

class PadRegistry {
 public:
  /// The pad's number: a kept one's when it is the same pad, else a new one; kNoPad for no pad.
  PadId id_of(const PadIdentity& pad);
  /// What is known of the pad (empty for kNoPad or one no longer kept).
  [[nodiscard]] const PadIdentity& identity(PadId id) const;
  /// Forgets every pad but these.
  void keep(std::initializer_list<PadId> ids);

 private:
  std::vector<std::pair<PadId, PadIdentity>> pads_;
  PadId next_ = kNoPad;
};

/// Reads fields() back into id (its name untouched); false: not such a text.
bool parse_pad_fields(std::string_view text, PadIdentity& id);

}  // namespace andros::input
