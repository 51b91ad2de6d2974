#!/usr/bin/env bash
# The README's test command: installs what is missing, checks the format
# (.clang-format), builds, runs every test: the suite, the same suite again
# under AddressSanitizer + UndefinedBehaviorSanitizer (build-asan/, clang,
# which holds the libFuzzer targets too), the Debian package (built by
# scripts/package.sh, then checked by tests/package/test_package.sh), the
# package's service under systemd in a throwaway container
# (tests/service/test_systemd.sh), clang-tidy over src/ (scripts/lint.sh)
# and each fuzz target briefly (scripts/fuzz.sh). The sanitizer build, the
# package (its objects from ccache: the plain build compiled them with its
# flags) and clang-tidy run in the background from the end of the plain
# build, niced, in the time the plain tests leave the cores idle; the
# sanitizer build is waited for before the sanitizer tests, the others at
# the end. The fuzz targets run in the background from the end of their
# build, beside the sanitizer tests.
# With CI=true (.ci/run sets it) every build treats warnings as errors.
# ANDROS_QUICK=1 runs the plain suite only (a developer's inner loop).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
jobs=$(nproc)
summary=$(mktemp)
# Work in the background (below) ends with the script: each job is a process
# group of its own (setsid), ended whole.
declare -A bg_pid=() bg_log=()
trap 'rm -f "$summary" "$times_file"; for p in "${bg_pid[@]}"; do kill -TERM -- "-$p" 2>/dev/null || true; done' EXIT

# CPU seconds (user + system) of every process this script has waited for so
# far: `times` run by this shell itself (in a pipe or $(...) it would time a
# subshell), written to a file.
times_file=$(mktemp)
# cpu_seconds [FILE]: the user + system seconds of the last `times` line in FILE ($times_file).
cpu_seconds() {
  tail -1 "${1:-$times_file}" | awk '{ split($1, u, /[ms]/); split($2, s, /[ms]/); printf "%d", u[1] * 60 + u[2] + s[1] * 60 + s[2] }'
}

# phase NAME: starts a timed phase (the previous one ends); closing lists their
# times, wall clock and CPU (which says what a phase would take on more cores).
phases=()
phase() {
  local cpu
  times >"$times_file"
  cpu=$(cpu_seconds)
  [[ -n ${phase_name:-} ]] &&
    phases+=("$phase_name $((SECONDS - phase_start)) s (CPU $((cpu - phase_cpu)) s${phase_note:+; $phase_note})")
  phase_name=$1
  phase_note=
  phase_start=$SECONDS
  phase_cpu=$cpu
  [[ -z $1 ]] || echo "== $1"
}

# closing: the plain 'N passed, N failed' line over every ctest run so far.
closing() {
  phase ""
  local joined
  joined=$(printf '%s, ' "${phases[@]}")
  echo "phases: ${joined%, }; total $SECONDS s"
  local total=0 failed=0 f t
  while read -r f t; do
    total=$((total + t))
    failed=$((failed + f))
  done < <(sed -n 's/.*tests passed, \([0-9]*\) tests failed out of \([0-9]*\).*/\1 \2/p' "$summary")
  echo "tests: $((total - failed)) passed, $failed failed"
}

# ctest runs three times as many jobs as cores: a unit test takes two of them,
# a command-line test one (it mostly waits on the frame clock: the plain run's
# 60 of them wait some 180 s in all). tests/CMakeLists.txt sets the slots, and
# starts the longest command-line tests first. The plain suite beside two
# niced busy loops (the package and clang-tidy in the background), on the
# 2-core machine other builds shared: 4 jobs 96 and 157 s, 6 jobs 119 and
# 180 s, 8 jobs 116 and 175 s (within that noise of each other); 2 jobs 471 s
# against 191 s for 6. Fewer jobs leave the cores idle while the tests wait;
# more gain nothing, the longest command-line tests (30-45 s) being the
# floor. The background jobs are niced: the tests that compute go first.
ctest_jobs=$((3 * jobs))

# background NAME CMD...: runs CMD niced (the builds and tests in front get
# the cores first), its output in $build/NAME.log; await NAME waits for it as
# a phase of its own, says how long it ran and its CPU, and prints its output
# (a failure ends the script). The job is started from the subshell of $(...),
# which ends at once, so that it is not this script's child: bash adds a child's CPU to
# `times` when the child ends, which would count a job's CPU in whatever phase
# was running then; the job's own shell times it instead. setsid: a session
# and process group of its own, which the EXIT trap ends whole.
# NICE (10 unless given) orders the background jobs among themselves: the
# sanitizer build, which the sanitizer tests wait for, before clang-tidy,
# which nothing waits for until the end.
background() {
  local name=$1 log="$build/$1.log" nice=10
  shift
  [[ $1 == [0-9]* ]] && { nice=$1; shift; }
  bg_log[$name]=$log
  rm -f "$log.done" "$log.times"
  bg_pid[$name]=$(setsid bash -c 'start=$SECONDS; status=0; nice -n "$1" "${@:2}" || status=$?; times >"$0.times"
                                  echo "$status $((SECONDS - start))" >"$0.done"; exit $status' "$log" "$nice" "$@" \
                    </dev/null >"$log" 2>&1 & echo $!)
}
await() {
  local name=$1 log=${bg_log[$1]} status ran cpu
  # Not a child to wait for: its .done file says it ended, and how.
  until [[ -s $log.done ]]; do
    if ! kill -0 "${bg_pid[$name]}" 2>/dev/null && [[ ! -s $log.done ]]; then
      cat "$log"
      echo "$name: FAILED (it ended without saying how: killed?; its output above, and in $log)"
      exit 1
    fi
    sleep 1
  done
  unset "bg_pid[$name]"
  cat "$log"
  read -r status ran <"$log.done"
  cpu=$(cpu_seconds "$log.times")
  phase_note="ran $ran s in the background, CPU $cpu s"
  echo "($name: $phase_note)"
  ((status == 0)) || { echo "$name: FAILED (exit $status; its output above, and in $log)"; exit 1; }
}

# The Debian package, built (its whole log in $build/package-build.log) and checked.
package_and_check() {
  scripts/package.sh >"$build/package-build.log" 2>&1 ||
    { tail -40 "$build/package-build.log"; echo "package: the build FAILED (its log: $build/package-build.log)"; return 1; }
  tail -1 "$build/package-build.log"
  tests/package/test_package.sh dist/andros-bridge_*.deb
}
export -f package_and_check

# One sanitizer tree for the suite and the fuzz targets: clang, ASan + UBSan,
# libFuzzer's coverage (ANDROS_FUZZ) in every file, -O1 -g1 (OSS-Fuzz's
# flags: what the sanitizers and the fuzzer find does not need -O2). src/ is
# compiled once for both, not once by gcc for the suite and again by clang
# for the fuzzers (CPU 324 s + 116 s before, 328 s then, on 2 cores). A tree
# an older test command configured with gcc is made again.
build_asan() {
  grep -qs '^CMAKE_CXX_COMPILER:[A-Z]*=.*clang' "$build-asan/CMakeCache.txt" || rm -rf "$build-asan"
  CXX=clang++ BUILD_DIR="$build-asan" BUILD_FLAGS=cmake scripts/build.sh -DANDROS_SANITIZE=ON -DANDROS_FUZZ=ON \
    -DANDROS_BUILD_BENCH=OFF -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG"
}
export -f build_asan
export build

quick=${ANDROS_QUICK:-}
# Everything the test command needs, installed before anything runs in the
# background (two apt-gets at once would fight over dpkg's lock): clang and
# its libFuzzer for the fuzz targets, clang-format and clang-tidy for the gates,
# what the package's build and check use (debian/control's Build-Depends are
# scripts/setup.sh's list and debhelper; lintian; systemd-analyze), and
# systemd-nspawn (systemd-container) for the service's container
# (scripts/setup.sh's own list is what the build needs: scripts/run.sh's too).
if [[ $quick == 1 ]]; then
  scripts/setup.sh
else
  scripts/setup.sh clang libclang-rt-14-dev clang-format clang-tidy dpkg-dev debhelper fakeroot lintian systemd \
    systemd-container
fi
if [[ $quick != 1 ]]; then
  phase "format (scripts/lint.sh --format)"
  scripts/lint.sh --format
fi
phase "build ($build)"
scripts/build.sh
if [[ $quick != 1 ]]; then
  # clang-tidy's cache (scripts/lint_tidy.py, kept between runs on the same
  # machine as ccache's is) makes a run over unchanged files take seconds.
  # The sanitizer build begins here too, beside the plain tests (which leave
  # the cores idle while they wait on the frame clock), and is waited for
  # before the sanitizer tests: niced less than the other two, which it goes
  # before; clang-tidy, awaited last, takes what the others leave.
  background build-asan 5 bash -c build_asan
  background package bash -c package_and_check
  background clang-tidy 19 scripts/lint.sh --tidy
fi
phase "test ($build)"
ctest --test-dir "$build" --output-on-failure --parallel "$ctest_jobs" --timeout 300 | tee -a "$summary"
if [[ $quick == 1 ]]; then closing; exit 0; fi

phase "build under ASan + UBSan, and the fuzz targets ($build-asan, clang -O1, the tests' own code -O0; begun after the plain build)"
await build-asan
# Each fuzz target for ANDROS_FUZZ_SECONDS (10) of its own, two at a time,
# beside the sanitizer tests and the service's container, niced below them: a
# fuzz run is bounded by its time, not its work, and takes what the tests
# leave idle while they wait on the frame clock (its executions, printed at
# the end, say how much that was).
background fuzz 19 env FUZZ_BUILD_DIR="$build-asan" scripts/fuzz.sh "${ANDROS_FUZZ_SECONDS:-10}"
phase "test under ASan + UBSan ($build-asan)"
# Four jobs a core here: nothing builds beside these tests (the fuzzers, niced,
# take only what they leave), whose GoogleTest cases take two slots each and,
# with six, held four of them for most of the phase while the command-line
# tests, which mostly wait, queued behind them in the other two (a quiet run:
# 97 s with 6, 80 s with 8; the longest test 64 s).
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir "$build-asan" --output-on-failure --parallel "$((4 * jobs))" --timeout 600 | tee -a "$summary"

phase "Debian package: build and check (scripts/package.sh, tests/package/test_package.sh; begun after the plain build)"
await package
# The package's service under a real systemd: a throwaway container, booted
# here, not in the background (its bridge is real-time: a niced container
# would judge the host's load, not the service).
phase "the service under systemd (tests/service/test_systemd.sh: a systemd-nspawn container)"
tests/service/test_systemd.sh dist/andros-bridge_*.deb
phase "clang-tidy (scripts/lint.sh --tidy, begun after the plain build)"
await clang-tidy
phase "fuzz: each target briefly (scripts/fuzz.sh, the targets of $build-asan; begun after their build)"
await fuzz
closing
