#!/usr/bin/env bash
# Builds and runs the live bridge's benchmarks and prints their tables
# (issue 4). Run it on an otherwise quiet machine; it takes about 75 s.
#   bench/run.sh [CADENCE_SECONDS] [COST_SECONDS]     (defaults 30 and 20)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
cmake -S . -B "$build" -DANDROS_BUILD_BENCH=ON >/dev/null
cmake --build "$build" --parallel "$(nproc)" --target andros-bridge andros_bench_cadence andros_bench_process >/dev/null
"$build/bench/live/andros_bench_cadence" "${1:-30}" || true
echo
"$build/bench/live/andros_bench_process" "$build/src/andros-bridge" "${2:-20}"
