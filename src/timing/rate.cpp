#include "andros/timing/rate.hpp"

#include <cstdio>
#include <string>

#include "andros/base/text.hpp"

namespace andros::timing {
namespace {

InputError bad_rate(std::string_view text, const SourcePos& pos, const std::string& why) {
  return InputError(pos, "rate " + quote(text) + " " + why);
}

}  // namespace

Rate parse_rate(std::string_view text, const SourcePos& pos) {
  const auto dot = text.find('.');
  const auto whole = text.substr(0, dot);
  const auto frac = dot == std::string_view::npos ? std::string_view{} : text.substr(dot + 1);
  // Digits only: a sign would be taken, and a huge negative rate overflowed
  // the millihertz product below (a fuzzer finding).
  const auto hz = whole.find_first_not_of("0123456789") == std::string_view::npos ? to_integer(whole) : std::nullopt;
  const bool digits_ok = hz && (dot == std::string_view::npos || (!frac.empty() && frac.size() <= 3)) &&
                         frac.find_first_not_of("0123456789") == std::string_view::npos && *hz < 1'000'000;
  if (!digits_ok) throw bad_rate(text, pos, "is not a number of Hz (such as 25 or 12.5, at most 3 decimals)");
  std::int64_t milli = 0;
  for (std::size_t i = 0; i < 3; ++i) milli = milli * 10 + (i < frac.size() ? frac[i] - '0' : 0);
  const std::int64_t millihertz = *hz * kMillihertzPerHz + milli;
  if (millihertz < kMillihertzPerHz) throw bad_rate(text, pos, "is below 1 Hz");
  return Rate{millihertz, std::string(text), pos};
}

std::int64_t max_rate_millihertz(int baud) {
  return static_cast<std::int64_t>(baud) * kMillihertzPerHz / kBitsPerFrame;
}

void check_rate_fits(const Rate& rate, int baud) {
  const std::int64_t most_millihertz = max_rate_millihertz(baud);
  if (rate.millihertz <= most_millihertz) return;
  char most[32];
  std::snprintf(most, sizeof most, "%lld.%03lld", static_cast<long long>(most_millihertz / kMillihertzPerHz),
                static_cast<long long>(most_millihertz % kMillihertzPerHz));
  throw bad_rate(rate.text.empty() ? rate_text(rate.millihertz) : rate.text, rate.pos,
                 "does not fit the link: " + std::to_string(kBitsPerFrame) + "-bit frames at " + std::to_string(baud) +
                     " baud allow at most " + most + " Hz");
}

std::string rate_text(std::int64_t millihertz) {
  std::string text = std::to_string(millihertz / kMillihertzPerHz);
  if (millihertz % kMillihertzPerHz == 0) return text;
  char frac[8];
  std::snprintf(frac, sizeof frac, ".%03lld", static_cast<long long>(millihertz % kMillihertzPerHz));
  std::string_view digits(frac);
  while (digits.ends_with('0')) digits.remove_suffix(1);
  return text + std::string(digits);
}

}  // namespace andros::timing
