# `replay` of a session proves every record the loop writes (docs/recording.md,
# "Replay a session"): a state, stop, reset, layer, gate, request or frame
# record altered, added, removed or moved, and re-hashed so that it verifies,
# is named by its line with what was recorded and what the replay makes;
# `sessions` marks WEAPONS and STOPS of such a session unproven. And the work
# bound of format 3: a session whose ticks stretch further than a minute
# after a frame record is refused before any tick is stepped.
source "$(dirname "$0")/lib.sh"
tool="$(dirname "$0")/session_tool.py"
drive="$DATA/sessions/drive.andros-session"
mkdir -p "$TMP/dir"

# edit NAME SED: the drive session with SED applied, renumbered and re-hashed (it verifies).
edit() {
  sed "$2" "$drive" >"$TMP/dir/$1.andros-session"
  python3 "$tool" renumber "$TMP/dir/$1.andros-session"
  expect_exit 0 "$BIN" verify "$TMP/dir/$1.andros-session"
}
# differs NAME TEXT: replay exits 1 naming TEXT.
differs() {
  expect_exit 1 "$BIN" replay "$TMP/dir/$1.andros-session"
  grep -qF -- "$2" "$TMP/out" || fail "replay of $1: $(cat "$TMP/out"), expected '$2'"
}

# The session as recorded: every frame and record made again.
expect_exit 0 "$BIN" replay "$drive"
grep -q "^24 frames identical; 10 records .* made again the same$" "$TMP/out" || fail "the drive: $(cat "$TMP/out")"

# A state changed (the issue's: 'enabled' to 'not enabled'), its frames untouched.
edit state 's/^11 state 120 enabled/11 state 120 not enabled/'
differs state "line 12: recorded 'state 120 not enabled', the replay makes 'state 120 enabled'"
# A stop added (a forged supervisor's stop): the replay makes none.
edit stop '/^16 frame/a 99 stop 600 supervisor {"guid":"","name":"boss","path":"","serial":""}'
differs stop "line 18: recorded 'stop 600 supervisor"
grep -qF "the replay makes no such record" "$TMP/out" || fail "a forged stop: $(cat "$TMP/out")"
# A state removed: the replay makes it, the session holds none.
edit gone '/^21 state 840 stopping/d'
differs gone "the replay makes 'state 840 stopping' after line 20, the session holds no such record"
# Two records of a tick swapped (each the same, in another order): the order is the loop's.
edit moved '19{h;d};20{G}'
differs moved "line 19: 'frame 18 720 sent"
grep -qF "is out of its place: the loop writes it after line 20" "$TMP/out" || fail "moved: $(cat "$TMP/out")"
# A layer renamed.
edit layer 's/^7 layer 0 ""/7 layer 0 "weapons"/'
differs layer "line 8: recorded 'layer 0 \"weapons\"', the replay makes 'layer 0 \"\"'"

# `sessions`: WEAPONS and STOPS of the sessions replay does not prove are marked ?.
cp "$drive" "$TMP/dir/"
expect_exit 0 "$BIN" sessions --record-dir "$TMP/dir" --format jsonl
python3 - "$TMP/out" <<'P' || fail "sessions jsonl: $(cat "$TMP/out")"
import json, sys
rows = {json.loads(l)["file"].rsplit("/", 1)[-1]: json.loads(l) for l in open(sys.argv[1])}
assert rows["drive.andros-session"]["proven"] is True, rows["drive.andros-session"]
for name in ("state", "stop", "gone", "moved", "layer"):
    r = rows[name + ".andros-session"]
    assert r["verify"] == "intact" and r["proven"] is False and "line" in r["unproven"], r
assert rows["stop.andros-session"]["stops"]["supervisor"] == 1
P
expect_exit 0 "$BIN" sessions --record-dir "$TMP/dir"
grep -E "drive\.andros-session$" "$TMP/out" | grep -qE " no  +0  " || fail "the drive's row: $(cat "$TMP/out")"
grep -E "stop\.andros-session$" "$TMP/out" | grep -qE " no\? +1 \(sup 1\)\? " || fail "the forged stop's row: $(cat "$TMP/out")"
grep -q "^5 of 6 sessions with WEAPONS and STOPS marked ?" "$TMP/out" || fail "no footnote: $(cat "$TMP/out")"

# Format 3: a frame record at least every 60 s; a crafted 10 kB session
# asking for 24 h at 320 Hz (27,648,000 ticks) is refused by every reader at once.
python3 "$tool" long "$drive" 24 320 3 "$TMP/long.andros-session"
for cmd in replay export plot; do
  expect_exit 2 "$BIN" $cmd "$TMP/long.andros-session"
  grep -qF "long.andros-session:10: error: tick 27647999 is 86399996 ms after the frame record it repeats (line 9)" "$TMP/err" ||
    fail "$cmd of a 24 h session of one record: $(head -c 300 "$TMP/err")"
done
# A format 2 session is read as before (its ticks bounded by 24 h).
python3 "$tool" long "$drive" 0.01 320 2 "$TMP/short2.andros-session"
expect_exit 0 "$BIN" export "$TMP/short2.andros-session"
[[ $(wc -l <"$TMP/out") -eq 11521 ]] || fail "export of 36 s at 320 Hz: $(wc -l <"$TMP/out") lines"

# `sessions` replays a format 2 session only within the same rule: the 24 h one is listed unproven, not replayed.
mkdir -p "$TMP/old"
python3 "$tool" long "$drive" 24 320 2 "$TMP/old/long2.andros-session"
expect_exit 0 "$BIN" sessions --record-dir "$TMP/old" --format jsonl
grep -qF '"proven":false' "$TMP/out" && grep -qF 'is 86399996 ms after the frame record it repeats (line 9)' "$TMP/out" ||
  fail "sessions of a format 2 session of 24 h at 320 Hz: $(cat "$TMP/out")"

exit $((failures > 0))
