# `controllers` and `record` as processes. No controller is attached here (SDL's
# virtual devices live in one process; tests/sdl covers the recording itself).
source "$(dirname "$0")/lib.sh"
export SDL_VIDEODRIVER=dummy

expect_exit 0 "$BIN" controllers --help
expect_exit 0 "$BIN" controllers --json
expect_exit 0 "$BIN" controllers

expect_exit 2 "$BIN" controllers --controller-db "$TMP/missing.txt"
expect_one_line_stderr
expect_stderr_matches "^$TMP/missing.txt: error: cannot read the controller database: No such file or directory"

printf '# mine\nnot a mapping\n' >"$TMP/bad.txt"
expect_exit 2 "$BIN" record --controller-db "$TMP/bad.txt" --output "$TMP/never.txt"
expect_stderr_matches "^$TMP/bad.txt:2:1: error: bad SDL mapping"
[[ ! -e $TMP/never.txt ]] || fail "record created its output despite bad input"

expect_exit 2 "$BIN" record --controller 300
expect_stderr_matches "^--controller: error: controller index 300"
expect_exit 2 "$BIN" record --rate 0

# --supervisor: a second controller, never the operator's, named where it was set.
expect_exit 2 "$BIN" record --supervisor 300
expect_one_line_stderr
expect_stderr_matches "^--supervisor: error: controller index 300 is out of range 0..255"
expect_exit 2 "$BIN" record --controller 1 --supervisor 1 --output "$TMP/never.txt"
expect_one_line_stderr
expect_stderr_matches "^--supervisor: error: the supervisor's controller is controller 1, the operator's too \(--controller\): name another one"
[[ ! -e $TMP/never.txt ]] || fail "record created its output despite bad input"
printf 'supervisor = xbox\n' >"$TMP/sup.conf"
expect_exit 2 "$BIN" run --config "$TMP/sup.conf" --controller XBOX
expect_stderr_matches "^$TMP/sup.conf:1:14: error: the supervisor's controller is a controller named like 'xbox', the operator's too"
expect_exit 2 "$BIN" run --supervisor ""
expect_stderr_matches "^--supervisor: error: empty value"

# SIGTERM and SIGINT end a recording with `T end` and exit 0.
for sig in TERM INT; do
  out=$TMP/rec_$sig.txt
  "$BIN" record --output "$out" 2>"$TMP/err" &
  pid=$!
  for _ in $(seq 600); do [[ -s $out ]] && break; sleep 0.05; done  # bounded: 30 s (a ceiling: ASan on a loaded machine)
  kill -"$sig" "$pid"
  wait "$pid"
  code=$?
  [[ $code -eq 0 ]] || fail "record exited $code on SIG$sig; stderr: $(cat "$TMP/err")"
  grep -q '^# andros-bridge .* record, started ' "$out" || fail "no header in $(cat "$out")"
  grep -Eq '^[0-9]+ +end$' "$out" || fail "SIG$sig: no end line in $(cat "$out")"
done

# With an event script as the input, the script's own supervisor lines count: --supervisor is not read, and says so.
printf '0 connect\n40 end\n' >"$TMP/short.events"
expect_exit 0 "$BIN" run --supervisor 1 --input "$TMP/short.events"
expect_stderr_matches "warning: supervisor 1 not read: the event script $TMP/short.events is the input"
# A mapping's supervisor: buttons with no supervisor's controller to read them.
expect_exit 0 "$BIN" run --mapping "$DATA/mappings/supervisor.yaml" --input "$TMP/short.events"
expect_stderr_matches "warning: the mapping's supervisor: buttons have no controller to read \(no --supervisor\)"
printf '0 connect\n0 supervisor connect\n40 end\n' >"$TMP/both.events"
expect_exit 0 "$BIN" run --mapping "$DATA/mappings/supervisor.yaml" --input "$TMP/both.events"
grep -q "buttons have no controller" "$TMP/err" && fail "warned with a script that has a supervisor: $(cat "$TMP/err")"
grep -q "supervisor's controller: controller" "$TMP/err" || fail "the supervisor's controller not logged: $(cat "$TMP/err")"

# A supervisor named but not attached: the recording says so at 0, so that replay keeps it.
out=$TMP/rec_sup.txt
"$BIN" record --supervisor 'no such pad' --output "$out" 2>"$TMP/err" &
pid=$!
for _ in $(seq 600); do grep -q 'supervisor disconnect' "$out" 2>/dev/null && break; sleep 0.05; done  # bounded: 30 s (a ceiling: ASan on a loaded machine)
# Written at 0 and flushed then: a recording killed at any time keeps it (and the SIGINT goes once it is there).
grep -q 'supervisor disconnect' "$out" || fail "record --supervisor: no 'supervisor disconnect' in the file while it records: $(cat "$out")"
kill -INT "$pid"
wait "$pid" || fail "record --supervisor exited $?; stderr: $(cat "$TMP/err")"
grep -q "^# supervisor: a controller named like 'no such pad'$" "$out" || fail "no supervisor in the header: $(cat "$out")"
grep -Eq '^0 +supervisor disconnect$' "$out" || fail "no '0 supervisor disconnect' in $(cat "$out")"

finish
