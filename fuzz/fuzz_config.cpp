// libFuzzer target: the configuration-file parser (docs/running.md, "The configuration file"). Any
// text either configures a run with values the bridge accepts, or is an
// InputError naming the file and a line inside the text.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "andros/base/error.hpp"
#include "andros/cli/config.hpp"
#include "andros/protocol/robots.hpp"
#include "andros/timing/rate.hpp"
#include "fuzz_check.hpp"

using andros::fuzz::check;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  andros::TextReader in(text, "fuzz.conf", andros::kConfigLimits);
  andros::cli::Settings config;
  try {
    andros::cli::parse_config(in, config);
  } catch (const andros::InputError& e) {
    check(e.pos().file == "fuzz.conf" || e.pos().file == "--rate");
    check(e.pos().file != "fuzz.conf" || e.pos().line >= 1);
    return 0;
  }
  check(andros::protocol::canonical_robot(config.robot).value_or("") == config.robot);
  bool known_baud = false;
  for (const int b : andros::cli::kBauds) known_baud = known_baud || b == config.baud;
  check(known_baud);
  check(!config.port.empty() && !config.input.empty());
  try {
    // Merged with the flags' defaults: either a rate the link carries or an
    // error at the line that set it.
    andros::timing::check_rate_fits(config.rate, config.baud);
    const auto millihertz = config.rate.millihertz;
    check(millihertz >= andros::timing::kMillihertzPerHz &&
          millihertz * andros::timing::kBitsPerFrame <=
              static_cast<std::int64_t>(config.baud) * andros::timing::kMillihertzPerHz);
  } catch (const andros::InputError& e) {
    check(e.pos().file == "fuzz.conf" && e.pos().line >= 1);
  }
  return 0;
}
