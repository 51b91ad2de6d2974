#!/usr/bin/env bash
# One phase of the test command (scripts/test.mk):
#   scripts/phase.sh DIR NAME NICE [--tail N] CMD...
# runs CMD at nice NICE, its output in DIR/NAME.log, printed when it ends (its
# last N lines only, with --tail, unless it failed), and its times in
# DIR/NAME.time: start and end (seconds since the run began, $ANDROS_TEST_T0),
# CPU seconds (user + system, its processes that it waited for) and exit status.
# A failure ends the whole run: every phase is in this process group
# (scripts/test.sh starts make in a session of its own).
#   scripts/phase.sh --summary DIR
# prints each phase's times and the tests passed and failed over DIR/test*.log.
set -uo pipefail
t0=${ANDROS_TEST_T0:-$EPOCHSECONDS}

if [[ $1 == --summary ]]; then
  dir=$2
  echo "== phases (seconds from the start; CPU is user + system):"
  sort -k2n "$dir"/*.time | while read -r name start end cpu _; do
    printf '  %-14s %4d-%4d s  wall %4d s  CPU %4d s\n' "$name" "$start" "$end" $((end - start)) "$cpu"
  done
  echo "total $((EPOCHSECONDS - t0)) s"
  sed -n 's/.*tests passed, \([0-9]*\) tests failed out of \([0-9]*\).*/\1 \2/p' "$dir"/test*.log |
    awk '{ failed += $1; total += $2 } END { printf "tests: %d passed, %d failed\n", total - failed, failed }'
  exit 0
fi

dir=$1 name=$2 nice=$3
shift 3
tail_lines=
[[ $1 == --tail ]] && { tail_lines=$2; shift 2; }
mkdir -p "$dir"
log=$dir/$name.log
start=$((EPOCHSECONDS - t0))
echo "== $name: started at $start s"
nice -n "$nice" "$@" </dev/null >"$log" 2>&1
status=$?
# The second line of `times`, run by this shell itself (in a pipe or $(...) it
# would time a subshell): the CPU of the processes this shell waited for.
times >"$log.times"
cpu=$(tail -1 "$log.times" | awk '{ split($1, u, /[ms]/); split($2, s, /[ms]/); printf "%d", u[1] * 60 + u[2] + s[1] * 60 + s[2] }')
end=$((EPOCHSECONDS - t0))
echo "$name $start $end $cpu $status" >"$dir/$name.time"
# One phase's output at a time, whole, however many end together.
{
  flock 9
  echo "== $name: ended at $end s (wall $((end - start)) s, CPU $cpu s)"
  if [[ -n $tail_lines && $status == 0 ]]; then tail -n "$tail_lines" "$log"; else cat "$log"; fi
  ((status == 0)) || echo "== $name: FAILED (exit $status; its output above, and in $log)"
} 9>"$dir/.print.lock"
if ((status != 0)); then
  kill -TERM 0
  exit "$status"
fi
