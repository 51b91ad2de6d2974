// How much of a sweep (the fault simulation, the random property scripts, the
// exhaustive walk of the operating state) a build runs. The plain suite runs
// each whole, on every run. Under AddressSanitizer (the sanitizer build:
// clang, ASan + UBSan, the tests' own code at -O0) the same sweeps check what
// the sanitizers check, memory and undefined behaviour along the paths the
// code takes, and a part of each does that where it still reaches what the
// sweep's own coverage checks ask for (each sweep checks that its scripts
// reached motion, weapons, a stop...): a whole sweep there costs five to
// fifteen times its plain time. This header decides it for all three: the
// simulation's scripts, the properties' and the exhaustive walk's depth.
#pragma once

namespace andros::test {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kSanitizedSweep = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kSanitizedSweep = true;
#else
inline constexpr bool kSanitizedSweep = false;
#endif
#else
inline constexpr bool kSanitizedSweep = false;
#endif

/// A sweep's size: `whole` in the plain build, `sanitized` under the sanitizers.
constexpr int sweep_size(int whole, int sanitized) { return kSanitizedSweep ? sanitized : whole; }

}  // namespace andros::test
