// libFuzzer target: the mapping loader (YAML text in). Any text is either a
// mapping that validates, and then runs in an Engine, or an InputError that
// names the file; nothing else may escape, crash or hang.
//
// The input may hold several files, each after a line `#file` (a YAML
// comment): they are written as 0.yaml, 1.yaml, ... and 0.yaml is loaded, so
// that `extends: 1.yaml` chains, cycles and too-deep chains are reachable.

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>

#include "andros/base/error.hpp"
#include "andros/mapping/engine.hpp"
#include "andros/mapping/loader.hpp"
#include "andros/run/drive_guard.hpp"
#include "fuzz_check.hpp"
#include "scratch_dir.hpp"

namespace {

constexpr std::string_view kFileSeparator = "\n#file\n";
constexpr int kMaxFiles = 24;  // more than an extends chain may hold

std::filesystem::path scratch_dir() {
  // A private folder, so `extends: x.yaml` finds only what the input makes.
  static const andros::fuzz::ScratchDir dir("mapping");
  return dir.path();
}

/// Writes the input's files (none left from the last input) and returns the first.
std::filesystem::path write_files(std::string_view text) {
  const auto dir = scratch_dir();
  for (int i = 0; i < kMaxFiles; ++i) std::filesystem::remove(dir / (std::to_string(i) + ".yaml"));
  for (int i = 0; i < kMaxFiles; ++i) {
    const auto cut = i + 1 < kMaxFiles ? text.find(kFileSeparator) : std::string_view::npos;
    std::ofstream out(dir / (std::to_string(i) + ".yaml"), std::ios::binary | std::ios::trunc);
    out.write(text.data(), static_cast<std::streamsize>(std::min(cut, text.size())));
    if (cut == std::string_view::npos) break;
    text.remove_prefix(cut + kFileSeparator.size());
  }
  return dir / "0.yaml";
}

}  // namespace

using andros::fuzz::check;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = write_files(std::string_view(reinterpret_cast<const char*>(data), size));
  std::optional<andros::mapping::ValidMapping> mapping;
  try {
    mapping = andros::mapping::validate(andros::mapping::load_mapping_file(file), false);
  } catch (const andros::InputError& e) {
    check(!e.pos().file.empty());
    return 0;
  }
  if (!(*mapping)->robot) return 0;
  andros::mapping::Engine engine(std::move(*mapping), andros::mapping::EngineOptions{});
  andros::run::DriveGuard guard(engine.mapping());
  andros::input::InputState input;
  andros::input::InputEvent connect;
  connect.type = andros::input::InputEvent::Type::kConnect;
  input.apply(connect);
  for (std::int64_t t = 0; t < 200; t += 40) {
    const bool motion = guard.facts(input, t, true).deadman == andros::mapping::DeadmanState::kFreshHold;
    guard.decided(motion, t);
    check(andros::protocol::validation_errors(engine.step(input, t, motion || t == 80).data).empty());
  }
  return 0;
}
