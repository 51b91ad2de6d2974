# `inputs` as a process, off a terminal: no controller is attached here (SDL's
# virtual devices live in one process; tests/input/sdl drives the tester with one).
source "$(dirname "$0")/lib.sh"
export SDL_VIDEODRIVER=dummy

expect_exit 0 "$BIN" inputs --help
grep -q -- "--controller-db" "$TMP/out" || fail "inputs --help does not list --controller-db"

expect_exit 2 "$BIN" inputs --controller 300
expect_one_line_stderr
expect_stderr_matches "^--controller: error: controller index 300"
expect_exit 2 "$BIN" inputs --robot nosuch
expect_stderr_matches "unknown robot"
expect_exit 2 "$BIN" inputs --robot hd1 --mapping "$DATA/mappings/core.yaml"
expect_stderr_matches "^--mapping: error: give --robot or --mapping, not both"
expect_exit 2 "$BIN" inputs --controller-db "$TMP/missing.txt"
expect_stderr_matches "^$TMP/missing.txt: error: cannot read the controller database"

# Off a terminal: a header of two comment lines, then one line per change
# (none here); SIGINT, SIGTERM and SIGHUP end it with exit 0.
for sig in INT TERM HUP; do
  out=$TMP/inputs_$sig.txt
  "$BIN" inputs --mapping "$DATA/mappings/core.yaml" --controller "no such pad" >"$out" 2>"$TMP/err" &
  pid=$!
  for _ in $(seq 600); do [[ $(wc -l <"$out") -ge 2 ]] && break; sleep 0.05; done  # bounded: 30 s (a ceiling: ASan on a loaded machine)
  # Out line by line while it runs (the signal goes once it is, past the start-up).
  [[ $(wc -l <"$out") -ge 2 ]] || fail "SIG$sig: the header is not out while it runs: $(cat "$out")"
  kill -"$sig" "$pid"
  wait "$pid"
  code=$?
  [[ $code -eq 0 ]] || fail "inputs exited $code on SIG$sig; stderr: $(cat "$TMP/err")"
  [[ $(sed -n 1p "$out") == "# a controller named like 'no such pad'" ]] || fail "SIG$sig: first line: $(cat "$out")"
  grep -q "^# deadzones and thresholds of $DATA/mappings/core.yaml$" "$out" || fail "SIG$sig: no mapping line: $(cat "$out")"
  [[ $(wc -l <"$out") -eq 2 ]] || fail "SIG$sig: lines beyond the header with no controller: $(cat "$out")"
done

finish
