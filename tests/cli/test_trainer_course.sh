# `trainer --course` end to end (docs/trainer.md, "Courses", "The score"): the
# shipped basic course completed by its script, the score on the terminal; the
# session keeps the course and the score in its chain, and `sessions` shows
# them, the replay giving the same score (for a run with a contact, a stop and
# an input not at rest too); a bad course file and a name not found refused in
# one line, exit 2.
source "$(dirname "$0")/lib.sh"
export XDG_CONFIG_HOME=$TMP/xdg
COURSES=$DATA/../../courses
free_port() { python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])'; }

expect_exit 0 "$BIN" trainer --help
grep -q -- "--course NAME|FILE" "$TMP/out" || fail "trainer --help has no --course: $(cat "$TMP/out")"

expect_exit 0 "$BIN" trainer --course basic --input "$COURSES/basic.events" --exit-at-end --listen "127.0.0.1:$(free_port)"
grep -q "^course basic: completed$" "$TMP/out" || fail "basic not completed: $(cat "$TMP/out") $(tail -5 "$TMP/err")"
grep -q "^  gates: 2/2$" "$TMP/out" || fail "gates: $(cat "$TMP/out")"
grep -q "^  contacts: 0$" "$TMP/out" || fail "contacts: $(cat "$TMP/out")"
ended() { grep -o "ended at .*SHA-256 [0-9a-f]*" "$1" | tail -1; }
ended "$TMP/err" >"$TMP/live.ended"

expect_exit 0 "$BIN" trainer --course basic --input "$DATA/trainer/course_bump.events" --exit-at-end \
  --listen "127.0.0.1:$(free_port)"
grep -q "^course basic: not finished: not in the finish$" "$TMP/out" || fail "bump: $(cat "$TMP/out")"
grep -q "^  contacts: 1$" "$TMP/out" || fail "bump's contact: $(cat "$TMP/out")"
grep -q "^  stops: 1; 8.0 s operator (stop button)$" "$TMP/out" || fail "bump's stop: $(cat "$TMP/out")"
grep -q "^  enabled with inputs not at rest: 1$" "$TMP/out" || fail "bump's input not at rest: $(cat "$TMP/out")"
ended "$TMP/err" >>"$TMP/live.ended"

# The sessions: the course's text and the score in records verify covers; sessions shows them, proven by replay.
for s in "$XDG_STATE_HOME"/andros-bridge/*.andros-session; do
  expect_exit 0 "$BIN" verify "$s"
  grep -q "^intact" "$TMP/out" || fail "verify: $(cat "$TMP/out")"
  grep -q '^[0-9]* course {"name":"basic","path":".*basic.yaml","sha256":"' "$s" || fail "no course record in $s"
  grep -q '^[0-9]* score [0-9]* {' "$s" || fail "no score record in $s"
  # Replayed as motion, on the course's recorded text (walls and all, the bump's contact too): the live trail.
  expect_exit 0 "$BIN" trainer --session "$s" --exit-at-end
  ended "$TMP/err" >>"$TMP/replay.ended"
done
[[ $(sort "$TMP/live.ended") == "$(sort "$TMP/replay.ended")" ]] ||
  fail "a course run replayed is not its live trail: live $(cat "$TMP/live.ended"), replayed $(cat "$TMP/replay.ended")"
expect_exit 0 "$BIN" sessions --format jsonl
python3 - "$TMP/out" "$COURSES/basic.yaml" <<'PY' || fail "sessions: $(cat "$TMP/out")"
import json, sys
rows = [json.loads(l) for l in open(sys.argv[1])]
assert len(rows) == 2, rows
results = sorted(r["score"]["result"] for r in rows)
assert results == ["completed", "not finished: not in the finish"], results
for r in rows:
    assert r["course"] == "basic" and r["score_proven"] is True, r
PY
expect_exit 0 "$BIN" sessions
grep -q "trainer, course basic: completed, .* s, gates 2/2, contacts 0, .*; the replay gives the same score" "$TMP/out" ||
  fail "sessions' table: $(cat "$TMP/out")"

# A course file with an error: its line and column, one line, exit 2; a name not found.
printf 'course: x\nground: {x: [-5, 5], y: [-5, 5]}\nstart: {at: [0, 0]}\ngatez: []\n' >"$TMP/bad.yaml"
expect_exit 2 "$BIN" trainer --course "$TMP/bad.yaml" --input "$COURSES/basic.events" --exit-at-end
expect_one_line_stderr
expect_stderr_matches "bad.yaml:4:1: error: unknown key 'gatez' in a course"
expect_exit 2 "$BIN" trainer --course nosuch --input "$COURSES/basic.events" --exit-at-end
expect_one_line_stderr
expect_stderr_matches "^--course: error: no course 'nosuch'"
finish
