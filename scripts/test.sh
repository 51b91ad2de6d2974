#!/usr/bin/env bash
# The README's test command: installs what is missing, then runs its phases
# (scripts/test.mk, with make -j): the format check (.clang-format); the build
# and every test; the same suite again under AddressSanitizer +
# UndefinedBehaviorSanitizer (build-asan/, clang, which holds the libFuzzer
# targets too); the Debian package (scripts/package.sh) and its check
# (tests/package/test_package.sh); the package's service under systemd in a
# throwaway container (tests/service/test_systemd.sh); clang-tidy over src/
# (scripts/lint.sh --tidy); each fuzz target briefly (scripts/fuzz.sh).
# It ends with each phase's times and the tests passed and failed.
# With CI=true (.ci/run sets it) every build treats warnings as errors.
# ANDROS_QUICK=1 builds and runs the plain suite only (a developer's inner loop).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
# Everything installed before any phase starts (two apt-gets at once would
# fight over dpkg's lock): scripts/setup.sh's own list is what the build needs;
# the full run also adds clang and its libFuzzer, clang-format and clang-tidy, what
# the package's build and check use (debhelper, lintian, systemd-analyze) and
# systemd-nspawn (systemd-container).
# Both add Debian's headless Chromium, its driver and Selenium for the
# trainer's real-browser test (tests/trainer/test_browser.py): the tests need
# them, `scripts/run.sh` does not.
browser=(chromium chromium-driver python3-selenium)
if [[ ${ANDROS_QUICK:-} == 1 ]]; then
  goal=quick
  scripts/setup.sh "${browser[@]}"
else
  goal=all
  scripts/setup.sh "${browser[@]}" clang libclang-rt-14-dev clang-format clang-tidy dpkg-dev debhelper fakeroot \
    lintian systemd systemd-container
fi
rm -rf "$build/phases"
export ANDROS_TEST_T0=$EPOCHSECONDS
# A session of its own: a failing phase ends the whole run (scripts/phase.sh).
setsid --wait make --no-print-directory -f scripts/test.mk -j BUILD="$build" "$goal" ||
  { echo "test command: FAILED (the failed phase's output is above)"; exit 1; }
