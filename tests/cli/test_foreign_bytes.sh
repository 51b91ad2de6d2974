# Issue 34: text from outside that is not UTF-8 never ends a drive. Pads that
# name themselves with such bytes (USB descriptors may hold any), the
# supervisor's stop pressed, a reload to a mapping with a Latin-1 comment and
# an --input path that is not UTF-8: the run goes on to the end of its input,
# exit 0, and its session is intact, closed, counts the stop and replays.
# (The landed main exited 1 at the stop with json.exception.type_error.316, and
# a reload to such a mapping left the session unreadable.)
source "$(dirname "$0")/lib.sh"
cd "$TMP"
rec=$TMP/rec

printf 'robot: HD1\nextends: %s\n# caf\xe9 \xff: a Latin-1 comment\n' "$DATA/mappings/supervisor.yaml" >latin.yaml
input=$(printf 'drive-caf\xe9.events')
printf '%s\n' '0 connect pad\xFF' '0 supervisor connect boss\xC3 \x1B[2J' '40 button leftshoulder 1' \
  '100 axis lefty -20000' '600 supervisor button x 1' '700 supervisor button x 0' '800 axis lefty 0' \
  '820 button leftshoulder 0' '1000 reload latin.yaml' '1600 end' >"$input"

expect_exit 0 "$BIN" run --input "$input" --mapping "$DATA/mappings/supervisor.yaml" --supervisor boss \
  --port sim --record-dir "$rec"
grep -q 'stopped by the supervisor' "$TMP/err" || fail "the supervisor's stop is not in the log: $(head -c 600 "$TMP/err")"
grep -q 'reloaded (SIGHUP): mapping latin.yaml' "$TMP/err" || fail "the reload to latin.yaml is not in the log"
session=$(ls "$rec"/*.andros-session)
expect_exit 0 "$BIN" verify "$session"
grep -q '^closed' "$TMP/out" || fail "verify: $(cat "$TMP/out")"
expect_exit 0 "$BIN" sessions --record-dir "$rec" --format jsonl
grep -q '"stops":{"gate":0,"operator":0,"supervisor":1}' "$TMP/out" || fail "sessions: $(cat "$TMP/out")"
expect_exit 0 "$BIN" replay "$session"
grep -q 'identical' "$TMP/out" || fail "replay: $(cat "$TMP/out")"
# Recorded whole: the stop's pad, the reload's mapping text and the input path, escaped.
grep -q 'stop [0-9]* supervisor {"guid":"","name":"boss\\\\xC3 \\\\x1B\[2J"' "$session" ||
  fail "the stop's pad: $(grep ' stop ' "$session")"
grep -q 'caf\\\\xE9 \\\\xFF: a Latin-1 comment' "$session" || fail "the Latin-1 mapping's text is not recorded"
grep -q '"input":"drive-caf\\\\xE9.events"' "$session" || fail "the input path is not recorded"

exit $((failures > 0))
