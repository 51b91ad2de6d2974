#!/usr/bin/env bash
# Fuzzes each libFuzzer target for a while: scripts/fuzz.sh [SECONDS] [TARGET...]
# (default 60 s each, every target). Builds with clang into build-fuzz/, works
# on a scratch copy of fuzz/corpus/TARGET, and writes any crash into
# fuzz/crashes/TARGET/, where the replay test (ctest fuzz_replay.TARGET) keeps
# running it once it is fixed. Prints executions and exec/s per target.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
shift || true
scripts/setup.sh clang libclang-rt-14-dev
build=${FUZZ_BUILD_DIR:-build-fuzz}
CXX=clang++ cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DANDROS_FUZZ=ON \
  -DANDROS_BUILD_TESTS=OFF -DANDROS_BUILD_BENCH=OFF >/dev/null
targets=("$@")
if ((${#targets[@]} == 0)); then
  mapfile -t targets < <(sed -n 's/^set(ANDROS_FUZZ_TARGETS \(.*\))$/\1/p' fuzz/CMakeLists.txt | tr ' ' '\n')
fi
cmake --build "$build" --parallel "$(nproc)" --target "${targets[@]/#/fuzz_}"

status=0
printf '%-10s %10s %14s %10s %s\n' target seconds executions exec/s result
for t in "${targets[@]}"; do
  corpus="$build/corpus/$t"
  mkdir -p "$corpus" "fuzz/crashes/$t"
  cp -n fuzz/corpus/"$t"/* "$corpus"/ 2>/dev/null || true
  log="$build/fuzz_$t.log"
  # -timeout: an input that runs for ever is a finding (written as timeout-*), not a stuck run.
  if "$build/fuzz/fuzz_$t" -max_total_time="$seconds" -print_final_stats=1 -rss_limit_mb=2048 -timeout=10 \
      -artifact_prefix="fuzz/crashes/$t/" "$corpus" >"$log" 2>&1; then
    result=ok
  else
    result="FINDING (see $log and fuzz/crashes/$t/)"
    status=1
  fi
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  speed=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  printf '%-10s %10s %14s %10s %s\n' "$t" "$seconds" "${runs:-?}" "${speed:-?}" "$result"
done
exit $status
