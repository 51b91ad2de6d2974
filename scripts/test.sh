#!/usr/bin/env bash
# The README's test command: installs what is missing, checks the format
# (.clang-format), builds, runs every test: the suite (with clang-tidy over
# src/ beside it, scripts/lint.sh), the same suite again under AddressSanitizer
# + UndefinedBehaviorSanitizer (build-asan/), the Debian package (built by
# scripts/package.sh, then checked by tests/package/test_package.sh), and,
# where clang's libFuzzer is installed, each fuzz target briefly.
# With CI=true (.ci/run sets it) every build treats warnings as errors.
# ANDROS_QUICK=1 runs the plain suite only (a developer's inner loop).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
jobs=$(nproc)
summary=$(mktemp)
tidy_pid=
# clang-tidy runs in the background beside the tests: it ends with the script.
trap 'rm -f "$summary" "$times_file"; [[ -z $tidy_pid ]] || kill "$tidy_pid" 2>/dev/null || true' EXIT

# CPU seconds (user + system) of every process this script has waited for so
# far: `times` run by this shell itself (in a pipe or $(...) it would time a
# subshell), written to a file.
times_file=$(mktemp)
cpu_seconds() {
  tail -1 "$times_file" | awk '{ split($1, u, /[ms]/); split($2, s, /[ms]/); printf "%d", u[1] * 60 + u[2] + s[1] * 60 + s[2] }'
}

# phase NAME: starts a timed phase (the previous one ends); closing lists their
# times, wall clock and CPU (which says what a phase would take on more cores).
phases=()
phase() {
  local cpu
  times >"$times_file"
  cpu=$(cpu_seconds)
  [[ -n ${phase_name:-} ]] && phases+=("$phase_name $((SECONDS - phase_start)) s (CPU $((cpu - phase_cpu)) s)")
  phase_name=$1
  phase_start=$SECONDS
  phase_cpu=$cpu
  [[ -z $1 ]] || echo "== $1"
}

# closing: the plain 'N passed, N failed' line over every ctest run so far.
closing() {
  phase ""
  echo "phases: $(IFS=';'; echo "${phases[*]}" | sed 's/;/, /g'); total $SECONDS s"
  local total=0 failed=0 f t
  while read -r f t; do
    total=$((total + t))
    failed=$((failed + f))
  done < <(sed -n 's/.*tests passed, \([0-9]*\) tests failed out of \([0-9]*\).*/\1 \2/p' "$summary")
  echo "tests: $((total - failed)) passed, $failed failed"
}

# ctest runs three times as many jobs as cores: a unit test takes two of them
# (so that no more of them compute at once than there are cores), a
# command-line test one (it mostly waits on the frame clock: the plain run's
# 60 of them wait some 180 s in all). tests/CMakeLists.txt sets the slots, and
# starts the longest command-line tests first. Under the sanitizers, where every
# test computes more, twice as many jobs as cores.
ctest_jobs=$((3 * jobs))
asan_ctest_jobs=$((2 * jobs))

quick=${ANDROS_QUICK:-}
scripts/setup.sh
if [[ $quick != 1 ]]; then
  phase "format (scripts/lint.sh --format)"
  scripts/lint.sh --format
fi
phase "build ($build)"
scripts/build.sh
if [[ $quick != 1 ]]; then
  # clang-tidy beside the tests, which mostly wait on the frame clock; niced,
  # so that the tests get the cores first. Its cache (scripts/lint_tidy.py)
  # makes a run over unchanged files take seconds.
  tidy_log="$build/lint-tidy.log"
  nice -n 10 scripts/lint.sh --tidy >"$tidy_log" 2>&1 &
  tidy_pid=$!
fi
phase "test ($build)"
ctest --test-dir "$build" --output-on-failure --parallel "$ctest_jobs" --timeout 300 | tee -a "$summary"
if [[ $quick == 1 ]]; then closing; exit 0; fi
phase "clang-tidy (scripts/lint.sh --tidy, begun beside the tests)"
tidy_status=0
wait "$tidy_pid" || tidy_status=$?
tidy_pid=
cat "$tidy_log"
((tidy_status == 0)) || exit 1

# -Og: what the sanitizers find does not need -O2's (or -O1's) time to compile:
# GCC instruments -Og code in 40% less time than -O1 code (4m30 of CPU for the
# tree, against 8m), and the tests run 1.5-2.5x slower, which ctest's jobs and
# the fault simulation's threads absorb.
phase "build under ASan + UBSan ($build-asan, -Og)"
BUILD_DIR="$build-asan" scripts/build.sh -DANDROS_SANITIZE=ON -DANDROS_BUILD_BENCH=OFF \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-Og -g1 -DNDEBUG"
phase "test under ASan + UBSan ($build-asan)"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir "$build-asan" --output-on-failure --parallel "$asan_ctest_jobs" --timeout 600 | tee -a "$summary"

phase "Debian package: build (scripts/package.sh)"
scripts/package.sh >"$build/package.log" 2>&1 || { tail -40 "$build/package.log"; exit 1; }
phase "Debian package: check (tests/package/test_package.sh)"
tests/package/test_package.sh dist/andros-bridge_*.deb

if command -v clang++ >/dev/null && dpkg-query -W -f='${Status}' libclang-rt-14-dev 2>/dev/null | grep -q "installed"; then
  phase "fuzz: build, then each target briefly"
  scripts/fuzz.sh "${ANDROS_FUZZ_SECONDS:-10}"
else
  echo "== fuzzing skipped: clang and libclang-rt-14-dev are not installed (scripts/fuzz.sh installs them)"
fi
closing
