# `sessions`: per session its start, length, robot, frames, whether weapons
# fired (a weapon signal in a frame the link took while enabled), the stops
# and the resets by whom, the controllers and the link lost, and the verdict;
# the same as JSON lines. Crafted sessions (tests/data/sessions/drive.andros-session's first
# records, then records written here, the chain rehashed) check each field;
# one altered and one unreadable are listed, marked, never left out. None of
# them is the loop's own (replay makes other records): their WEAPONS and
# STOPS are marked unproven (?); tests/cli/test_replay_records.sh has proven ones.
source "$(dirname "$0")/lib.sh"
tool="$(dirname "$0")/session_tool.py"
dir=$TMP/rec
mkdir -p "$dir"

# craft NAME RECORDS...: the drive session's header, program, started and
# settings records, then RECORDS (payloads, without SEQ and hash), rehashed.
craft() {
  local out=$dir/$1.andros-session
  shift
  python3 - "$DATA/sessions/drive.andros-session" "$out" "$@" <<'PY'
import sys
head = [l.split(" ", 1)[1].rsplit(" ", 1)[0] for l in open(sys.argv[1]).read().split("\n")[:4]]
lines = [f"{i} {p} {'0' * 64}" for i, p in enumerate(head + sys.argv[3:])]
open(sys.argv[2], "w").write("\n".join(lines) + "\n")
PY
  python3 "$tool" rehash "$out" || fail "cannot rehash $out"
}
rest=0600182000908080000000010020CC02   # enabled, at rest (safety, drive_brake)
fire=0600182100908080000000010020CC02   # and weapon_1 (byte 3, bit 0)
shot=0000182800908080000000010020CC02   # shotgun (byte 3, bit 3), not enabled

# An incident: weapon_1 fired at 0.2 s; the operator stopped, the supervisor
# took the stop over and reset it, the frame gate stopped; each controller
# lost once (the operator's twice connected), the link lost twice.
craft 20240101-000000-1 \
  'link -1 connecting motion "not opened yet"' 'event 0 connect Op pad' 'event 0 supervisor connect Sup pad' \
  'state 0 not enabled' 'link 0 up motion ""' "frame 0 0 sent $rest gap=0" 'event 100 button leftshoulder 1' \
  'state 120 enabled' "frame 3 120 sent $rest gap=0" "frame 5 200 sent $fire gap=0" "frame 6 240 sent $rest gap=0" \
  'stop 240 operator "Op pad"' 'state 240 stopped' 'stop 280 supervisor "Sup pad"' 'reset 400 supervisor' \
  'state 400 not enabled' 'event 500 disconnect' 'event 600 connect Op pad' 'event 700 supervisor disconnect' \
  'link 800 connecting neutral-only "gone"' 'link 900 up motion ""' 'link 1000 connecting neutral-only "gone"' \
  'gate 1100 "a weapon bit without weapons"' 'stop 1100 gate ""' 'end 1200 tick 30 frames 31 "end of the input"'
# No fire: a weapon bit in a frame sent while not enabled, and in one the
# link refused (busy) while enabled; a supervisor absent from the start is
# no controller lost; neither the link before the first tick nor the link the
# bridge closed itself (detail "closed": a suspend, the end) is a link lost.
craft 20240102-000000-2 \
  'link -1 connecting motion "not opened yet"' 'event 0 connect Op pad' 'event 0 supervisor disconnect' \
  'state 0 not enabled' 'link 0 up motion ""' "frame 0 0 sent $shot gap=0" 'state 120 enabled' \
  "frame 3 120 busy $fire gap=0" "frame 4 160 sent $rest gap=0" 'link 180 connecting neutral-only "closed"' \
  'end 200 tick 5 frames 2 "end of the input"'
# Altered after it was written (a stop record removed, not rehashed): listed
# with what the records before the break say (not the end after it: FRAMES 1,
# tick 0's), marked NOT INTACT, and counted in the footnote.
craft 20240103-000000-3 \
  'link -1 connecting motion "not opened yet"' 'event 0 connect Op pad' 'state 0 not enabled' \
  'link 0 up motion ""' "frame 0 0 sent $rest gap=0" 'stop 40 operator "Op pad"' \
  'end 80 tick 2 frames 3 "end of the input"'
sed -i '/ stop 40 operator/d' "$dir/20240103-000000-3.andros-session"
# A session whose records cannot be read (a frame at a tick its time does not
# fall on): listed as unreadable, never left out.
craft 20240104-000000-4 'link -1 connecting motion ""' "frame 3 100 sent $rest gap=0"

expect_exit 0 "$BIN" sessions --record-dir "$dir"
cp "$TMP/out" "$TMP/table"
row() { grep -F "$dir/$1.andros-session" "$TMP/table"; }
header='^START +LENGTH +ROBOT +FRAMES +WEAPONS +STOPS +RESETS +CONTROLLERS LOST +LINK LOST +VERIFY +FILE$'
sed -n 2p "$TMP/table" | grep -Eq "$header" || fail "the table's header: $(sed -n 2p "$TMP/table")"
row 20240101-000000-1 | grep -Eq \
  "^2026-11-26 08:33:39 +0:00:01 +HD1 +31 +FIRED\? +3 \(op 1, sup 1, gate 1\)\? +1 \(sup 1\) +2 \(op 1, sup 1\) +2 +intact +$dir/" ||
  fail "the incident's row: $(row 20240101-000000-1)"
row 20240102-000000-2 | grep -Eq "^2026-11-26 08:33:39 +0:00:00 +HD1 +2 +no\? +0\? +0 +0 +0 +intact " ||
  fail "the quiet session's row: $(row 20240102-000000-2)"
row 20240103-000000-3 | grep -Eq " HD1 +1 +no\? +0\? +0 +0 +0 +NOT INTACT +$dir/" ||
  fail "the altered session's row: $(row 20240103-000000-3)"
row 20240104-000000-4 | grep -Eq '^\? +\? +\? +\? +\? +\? +\? +\? +\? +unreadable ' ||
  fail "the unreadable session's row: $(row 20240104-000000-4)"
grep -q "^2 of 4 sessions NOT INTACT or unreadable: what the table shows of them is what their records say, not evidence" \
  "$TMP/table" || fail "no footnote for the sessions not to be trusted: $(cat "$TMP/table")"
grep -q "^3 of 4 sessions with WEAPONS and STOPS marked ?: what their records say, not proven by replay" "$TMP/table" ||
  fail "no footnote for the sessions not proven: $(cat "$TMP/table")"

# --format jsonl: an object a session, the documented fields.
expect_exit 0 "$BIN" sessions --record-dir "$dir" --format jsonl
python3 - "$TMP/out" "$dir" <<'PY' || fail "sessions --format jsonl: $(cat "$TMP/out")"
import json, sys
rows = [json.loads(l) for l in open(sys.argv[1])]
assert len(rows) == 4, rows
d = sys.argv[2]
want = [
    {"file": f"{d}/20240101-000000-1.andros-session", "verify": "intact", "intact": True, "problem": "",
     "readable": True, "start": "2026-11-26T08:33:39+0000", "length_s": 1.2, "robot": "HD1", "frames_sent": 31,
     "supervised": False, "weapons_fired": True, "weapons": ["weapon_1"], "first_fire_s": 0.2,
     "stops": {"operator": 1, "supervisor": 1, "gate": 1}, "resets": {"operator": 0, "supervisor": 1},
     "controllers_lost": {"operator": 1, "supervisor": 1}, "links_lost": 2, "dropped": 0},
    {"file": f"{d}/20240102-000000-2.andros-session", "verify": "intact", "intact": True, "problem": "",
     "readable": True, "start": "2026-11-26T08:33:39+0000", "length_s": 0.2, "robot": "HD1", "frames_sent": 2,
     "supervised": False, "weapons_fired": False, "weapons": [], "first_fire_s": None,
     "stops": {"operator": 0, "supervisor": 0, "gate": 0}, "resets": {"operator": 0, "supervisor": 0},
     "controllers_lost": {"operator": 0, "supervisor": 0}, "links_lost": 0, "dropped": 0},
]
for got, w in zip(rows, want):
    assert got.pop("proven") is False and got.pop("unproven").startswith("tick 0 (0 ms, line "), got
    assert got == w, (got, w)
assert rows[2]["proven"] is False and rows[2]["unproven"] == "not intact", rows[2]
assert rows[2]["verify"] == "NOT INTACT" and rows[2]["intact"] is False, rows[2]
assert rows[2]["problem"].startswith("record 9 removed"), rows[2]
assert rows[2]["readable"] is True and rows[2]["stops"]["operator"] == 0, rows[2]
assert rows[3] == {"file": f"{d}/20240104-000000-4.andros-session", "verify": "unreadable", "intact": True,
                   "problem": rows[3]["problem"], "readable": False}, rows[3]
assert "tick 3 falls at 120 ms" in rows[3]["problem"], rows[3]
PY
# An empty folder: nothing in JSON lines, the sentence in a table.
mkdir -p "$TMP/none"
expect_exit 0 "$BIN" sessions --record-dir "$TMP/none" --format jsonl
expect_stdout ""
expect_exit 2 "$BIN" sessions --record-dir "$dir" --format csv
expect_stderr_matches "^--format: error: expected table or jsonl, got 'csv'"
expect_exit 0 "$BIN" sessions --help
grep -q "NOT INTACT" "$TMP/out" || fail "--help does not say how a session that is not intact is listed"

finish
