#!/usr/bin/env bash
# Fuzzes each libFuzzer target for a while: scripts/fuzz.sh [SECONDS] [TARGET...]
# (default 60 s each, every target; scripts/fuzz.sh --build [TARGET...]
# only builds them). Builds with clang into build-fuzz/ (or FUZZ_BUILD_DIR:
# a tree already configured with ANDROS_FUZZ=ON is used as it is), works
# on a scratch copy of fuzz/corpus/TARGET, and writes any crash into
# fuzz/crashes/TARGET/, where the replay test (ctest fuzz_replay.TARGET) keeps
# running it once it is fixed. Runs as many targets at once as there are
# cores, then prints executions and exec/s per target.
set -euo pipefail
cd "$(dirname "$0")/.."
build_only=0
if [[ ${1:-} == --build ]]; then
  build_only=1
  shift
else
  seconds=${1:-60}
  shift || true
fi
scripts/setup.sh clang libclang-rt-14-dev
build=${FUZZ_BUILD_DIR:-build-fuzz}
export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$PWD}
# A FUZZ_BUILD_DIR configured for fuzzing elsewhere (scripts/test.sh's
# sanitizer tree, which builds the targets with the suite) is used as it is.
if [[ -z ${FUZZ_BUILD_DIR:-} ]] || ! grep -qs '^ANDROS_FUZZ:BOOL=ON' "$build/CMakeCache.txt"; then
  # -O1 -g1: OSS-Fuzz's flags; line tables are all a finding's stack trace
  # needs. In CI (CI=true) warnings are errors, clang's as gcc's in the other builds.
  werror=OFF
  [[ ${CI:-} == true ]] && werror=ON
  CXX=clang++ cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
    -DANDROS_WERROR="$werror" -DANDROS_FUZZ=ON -DANDROS_BUILD_TESTS=OFF -DANDROS_BUILD_BENCH=OFF >/dev/null
fi
targets=("$@")
if ((${#targets[@]} == 0)); then
  mapfile -t targets < <(sed -n 's/^set(ANDROS_FUZZ_TARGETS \(.*\))$/\1/p' fuzz/CMakeLists.txt | tr ' ' '\n')
fi
cmake --build "$build" --parallel "$(nproc)" --target "${targets[@]/#/fuzz_}"
((build_only == 0)) || exit 0

# One target on each core at a time: each still gets its SECONDS of its own.
fuzz_one() {
  local t=$1 corpus="$build/corpus/$1" log="$build/fuzz_$1.log"
  mkdir -p "$corpus" "fuzz/crashes/$t"
  cp -n fuzz/corpus/"$t"/* "$corpus"/ 2>/dev/null || true
  # -timeout: an input that runs for ever is a finding (written as timeout-*), not a stuck run.
  if "$build/fuzz/fuzz_$t" -max_total_time="$seconds" -print_final_stats=1 -rss_limit_mb=2048 -timeout=10 \
      -artifact_prefix="fuzz/crashes/$t/" "$corpus" >"$log" 2>&1; then
    echo ok >"$log.result"
  else
    echo "FINDING (see $log and fuzz/crashes/$t/)" >"$log.result"
  fi
}
running=0
for t in "${targets[@]}"; do
  if ((running >= $(nproc))); then
    wait -n || true
    running=$((running - 1))
  fi
  fuzz_one "$t" &
  running=$((running + 1))
done
wait

status=0
printf '%-10s %10s %14s %10s %s\n' target seconds executions exec/s result
for t in "${targets[@]}"; do
  log="$build/fuzz_$t.log"
  result=$(cat "$log.result" 2>/dev/null || echo "FINDING (no result: see $log)")
  [[ $result == ok ]] || status=1
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  speed=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  printf '%-10s %10s %14s %10s %s\n' "$t" "$seconds" "${runs:-?}" "${speed:-?}" "$result"
done
exit $status
