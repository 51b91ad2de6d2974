// libFuzzer target: the mapping loader (YAML text in). Any text is either a
// mapping that validates, and then runs in an Engine, or an InputError that
// names the file; nothing else may escape, crash or hang.
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "andros/engine.hpp"
#include "andros/error.hpp"
#include "andros/mapping_loader.hpp"
#include "fuzz_check.hpp"

namespace {


std::filesystem::path scratch_file() {
  // A private folder, so `extends: x.yaml` finds only what the input makes.
  static const auto dir = [] {
    auto d = std::filesystem::temp_directory_path() / ("andros-fuzz-mapping-" + std::to_string(getpid()));
    std::filesystem::create_directories(d);
    return d;
  }();
  return dir / "fuzz.yaml";
}

}  // namespace

using andros::fuzz::check;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = scratch_file();
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  andros::Mapping mapping;
  try {
    mapping = andros::load_mapping_file(file);
    andros::validate(mapping, false);
  } catch (const andros::InputError& e) {
    check(!e.pos().file.empty());
    return 0;
  }
  if (!mapping.robot) return 0;
  andros::Engine engine(mapping, andros::EngineOptions{});
  andros::InputState input;
  andros::InputEvent connect;
  connect.type = andros::InputEvent::Type::kConnect;
  input.apply(connect);
  for (std::int64_t t = 0; t < 200; t += 40) check(andros::validation_errors(engine.step(input, t)).empty());
  return 0;
}
