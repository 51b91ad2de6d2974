#include "andros/timing/rate.hpp"

#include <charconv>
#include <cstdio>
#include <string>

namespace andros::timing {

std::int64_t parse_rate(std::string_view text, int baud, const SourcePos& pos) {
  const auto bad = [&](const std::string& why) { return InputError(pos, "rate " + quote(text) + " " + why); };
  const auto dot = text.find('.');
  const auto whole = text.substr(0, dot);
  const auto frac = dot == std::string_view::npos ? std::string_view{} : text.substr(dot + 1);
  std::int64_t hz = 0;
  std::int64_t milli = 0;
  const auto [p, ec] = std::from_chars(whole.data(), whole.data() + whole.size(), hz);
  // Digits only: from_chars would take a sign, and a huge negative rate
  // overflowed the millihertz product below (a fuzzer finding).
  const bool digits_ok = !whole.empty() && whole.find_first_not_of("0123456789") == std::string_view::npos &&
                         ec == std::errc() && p == whole.data() + whole.size() &&
                         (dot == std::string_view::npos || (!frac.empty() && frac.size() <= 3)) &&
                         frac.find_first_not_of("0123456789") == std::string_view::npos && hz < 1'000'000;
  if (!digits_ok) throw bad("is not a number of Hz (such as 25 or 12.5, at most 3 decimals)");
  for (std::size_t i = 0; i < 3; ++i) milli = milli * 10 + (i < frac.size() ? frac[i] - '0' : 0);
  const std::int64_t mhz = hz * 1000 + milli;
  if (mhz < 1000) throw bad("is below 1 Hz");
  // rate x 360 bits must fit in baud bits per second.
  const std::int64_t max_mhz = static_cast<std::int64_t>(baud) * 1000 / kBitsPerFrame;
  if (mhz > max_mhz) {
    char most[32];
    std::snprintf(most, sizeof most, "%lld.%03lld", static_cast<long long>(max_mhz / 1000),
                  static_cast<long long>(max_mhz % 1000));
    throw bad("does not fit the link: " + std::to_string(kBitsPerFrame) + "-bit frames at " + std::to_string(baud) +
              " baud allow at most " + most + " Hz");
  }
  return mhz;
}

}  // namespace andros::timing
