#!/usr/bin/env bash
# Builds and runs the benchmarks and prints their tables: cadence,
# process cost, first frame, loss/SIGTERM/replug timing, the flight recorder's
# cost (with and without it), then the SDL input path's cost and latency with
# a virtual joystick, and the idle cost of `run` beside the floor (6 cases).
# Run it on an otherwise quiet machine; it takes about 5 minutes.
#   bench/run.sh [CADENCE_SECONDS] [COST_SECONDS]     (defaults 30 and 20)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
cmake -S . -B "$build" -DANDROS_BUILD_BENCH=ON >/dev/null
cmake --build "$build" --parallel "$(nproc)" --target andros-bridge andros_bench_cadence andros_bench_process \
  andros_bench_sdl_cost andros_bench_sdl_latency andros_bench_recorder andros_bench_idle_cost >/dev/null
"$build/bench/live/andros_bench_cadence" "${1:-30}" || true
echo
"$build/bench/live/andros_bench_process" "$build/src/andros-bridge" "${2:-20}"
echo
echo "| measure | result | target | |"
echo "|---|---|---|---|"
bench/steady_cost.py "$build/src/andros-bridge" "${2:-20}" --input sdl
bench/recorder_cost.py "$build/src/andros-bridge" "${2:-20}"
echo
"$build/bench/live/andros_bench_recorder"
echo
SDL_VIDEODRIVER=dummy "$build/bench/sdl/andros_bench_sdl_cost" "${2:-20}"
echo
SDL_VIDEODRIVER=dummy "$build/bench/sdl/andros_bench_sdl_latency" 500
echo
"$build/bench/live/andros_bench_idle_cost" "$build/src/andros-bridge" "${2:-20}" || true
