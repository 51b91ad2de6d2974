# `trainer --session` and export's model columns (docs/trainer.md,
# "Replaying a session"; docs/recording.md, "Export"): a live trainer run on
# a drive script, recorded, then its session replayed: the trail and the pose
# the same to the bit (the SHA-256 of every bit of both); the same after the
# mapping the run read is changed and then removed (a replay reads only the
# session); a forged session read only as far as its chain holds, and said
# so; a cut one read to its last whole record; export's pose at the end the
# replay's; run's settings refused with --session; the replay's page answers
# /replay and /motion, and refuses a bad time.
source "$(dirname "$0")/lib.sh"
export XDG_CONFIG_HOME=$TMP/xdg
STATE=$XDG_STATE_HOME/andros-bridge
DRIVE=$DATA/trainer/drive_course.events
free_port() { python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])'; }
# The digest a log line gives ("...ended at ...; trail N points, SHA-256 HEX").
ended() { grep -o "ended at .*SHA-256 [0-9a-f]*" "$1" | tail -1; }

# 1. Live: the trainer on the drive, recorded, with a copy of the shipped mapping.
cp -r "$DATA/../../mappings" "$TMP/maps"
run_cmd "$BIN" trainer --mapping "$TMP/maps/hd1.yaml" --listen "127.0.0.1:$(free_port)" --input "$DRIVE" --exit-at-end
[[ $code -eq 0 ]] || fail "the live trainer exited $code: $(cat "$TMP/err")"
live=$(ended "$TMP/err")
[[ -n $live ]] || fail "the live trainer said no end: $(cat "$TMP/err")"
session=$(ls "$STATE"/*.andros-session)

# 2. The session replayed: the same trail and pose, to the bit.
replayed() {
  run_cmd "$BIN" trainer --session "$session" --exit-at-end
  [[ $code -eq 0 ]] || fail "$1: the replay exited $code: $(cat "$TMP/err")"
  [[ $(ended "$TMP/err") == "$live" ]] || fail "$1: the replay's end is not the live run's:
live:   $live
replay: $(ended "$TMP/err")"
}
replayed "as recorded"
# The mappings changed (no longer valid), then removed: the replay reads the session alone.
for f in "$TMP"/maps/*.yaml; do sed -i 's/drive:/drive_x:/' "$f"; done
replayed "mapping changed"
rm -r "$TMP/maps"
replayed "mapping removed"
# By its bare name, as `sessions` prints it.
run_cmd "$BIN" trainer --session "$(basename "$session")" --exit-at-end
[[ $code -eq 0 && $(ended "$TMP/err") == "$live" ]] || fail "by its bare name: $(cat "$TMP/err")"

# 3. Export: the model's columns, the last row's pose the replay's end, in both formats.
expect_exit 0 "$BIN" export "$session" --output "$TMP/drive.csv"
expect_exit 0 "$BIN" export "$session" --format jsonl --output "$TMP/drive.jsonl"
python3 - "$TMP/drive.csv" "$TMP/drive.jsonl" "$live" <<'PY' || fail "export's model columns: see above"
import csv, json, re, sys
rows = list(csv.DictReader(open(sys.argv[1], newline="")))
objs = [json.loads(l) for l in open(sys.argv[2])]
cols = ["vehicle_x", "vehicle_y", "vehicle_heading", "front_flipper", "rear_flipper", "arm_torso", "arm_shoulder",
        "arm_elbow", "arm_wrist", "arm_wrist_extension", "gripper_opening", "gripper_rotation"]
assert all(c in rows[0] for c in cols), [c for c in cols if c not in rows[0]]
assert len(rows) == len(objs)
for r, o in zip(rows, objs):
    for c in cols:
        assert re.fullmatch(r"-?\d+\.\d{3}", r[c]), (c, r[c])
        assert isinstance(o[c], (int, float)) and abs(o[c] - float(r[c])) < 5e-4, (c, o[c], r[c])
x, y, h = (float(v) for v in re.match(r"ended at x (\S+) m, y (\S+) m, heading (\S+) deg", sys.argv[3]).groups())
last = rows[-1]
assert (float(last["vehicle_x"]), float(last["vehicle_y"]), float(last["vehicle_heading"])) == (x, y, h), (last, x, y, h)
# The drive goes forward and raises the front flippers (drive_course.events): the path beside the bits.
assert x > 5 and float(rows[0]["vehicle_x"]) == 0
assert max(float(r["front_flipper"]) for r in rows) > 0
# The pose moves only while the frame says drive.
moved = [i for i in range(1, len(rows)) if rows[i]["vehicle_x"] != rows[i - 1]["vehicle_x"]]
assert moved and all(rows[i - 1]["safety"] == "1" and rows[i - 1]["drive_brake"] == "1" for i in moved)
PY

# 4. Forged: a frame record's data changed in the middle. Read as verify
# reads it: the records before the break, said NOT INTACT; the motion then
# is export's (which reads the same records), not the whole run's.
python3 - "$session" "$TMP/forged.andros-session" <<'PY'
import sys
lines = open(sys.argv[1]).read().split("\n")
frames = [i for i, l in enumerate(lines) if l.split(" ")[1:2] == ["frame"]]
i = frames[len(frames) // 2]
parts = lines[i].split(" ")
parts[5] = parts[5][:-2] + ("00" if parts[5][-2:] != "00" else "01")
lines[i] = " ".join(parts)
open(sys.argv[2], "w").write("\n".join(lines))
PY
run_cmd "$BIN" trainer --session "$TMP/forged.andros-session" --exit-at-end
[[ $code -eq 0 ]] || fail "the forged session: exit $code: $(cat "$TMP/err")"
grep -q "NOT INTACT: .*records before it replayed, not evidence" "$TMP/err" || fail "forged, not said: $(cat "$TMP/err")"
forged=$(ended "$TMP/err")
[[ $forged != "$live" ]] || fail "the forged session replayed whole"
expect_exit 0 "$BIN" export "$TMP/forged.andros-session" --output "$TMP/forged.csv"
python3 - "$TMP/forged.csv" "$forged" <<'PY' || fail "the forged session's replay is not export's records"
import csv, re, sys
last = list(csv.DictReader(open(sys.argv[1], newline="")))[-1]
x, y = (float(v) for v in re.match(r"ended at x (\S+) m, y (\S+) m", sys.argv[2]).groups())
assert (float(last["vehicle_x"]), float(last["vehicle_y"])) == (x, y), (last["vehicle_x"], last["vehicle_y"], x, y)
PY
# Cut: the last line (the end record) cut in half. Its frames are all there: the same motion.
head -c -20 "$session" >"$TMP/cut.andros-session"
run_cmd "$BIN" trainer --session "$TMP/cut.andros-session" --exit-at-end
[[ $code -eq 0 ]] || fail "the cut session: exit $code: $(cat "$TMP/err")"
grep -q "cut short at line" "$TMP/err" || fail "cut, not said: $(cat "$TMP/err")"
[[ $(ended "$TMP/err") == "$live" ]] || fail "the cut session's frames moved otherwise: $(ended "$TMP/err")"
# Not a session: refused.
expect_exit 2 "$BIN" trainer --session "$DRIVE" --exit-at-end

# 5. Run's settings with --session: refused, one line.
expect_exit 2 "$BIN" trainer --session "$session" --mapping "$DATA/../../mappings/hd1.yaml" --exit-at-end
expect_one_line_stderr
expect_stderr_matches "^--mapping: error: not with --session"

# 6. The replay's page: /replay (the trail with times, the state lane in the
# plot's colours), /motion?t= (the object then), a bad time refused.
PORT=$(free_port)
"$BIN" trainer --session "$session" --listen "127.0.0.1:$PORT" >"$TMP/out" 2>"$TMP/err" &
pid=$!
python3 - "$PORT" "$live" >"$TMP/poll" 2>&1 <<'PY' || fail "the replay's page: $(cat "$TMP/poll")"
import json, re, sys, time, urllib.error, urllib.request
port = int(sys.argv[1])
def get(path):
    with urllib.request.urlopen(f"http://127.0.0.1:{port}{path}", timeout=5) as r:
        return json.loads(r.read())
deadline = time.monotonic() + 30
while True:
    try:
        rep = get("/replay")
        break
    except OSError:
        if time.monotonic() > deadline: raise
        time.sleep(0.1)
assert rep["replay"] and rep["length_ms"] > 10000 and rep["robot"] == "HD1", {k: rep[k] for k in ("length_ms", "robot")}
assert rep["trail"][0] == [0, 0, 0] and len(rep["trail"]) > 50
lane = rep["lane"]
names = [s["name"] for s in lane]
assert "enabled" in names, names
assert next(s for s in lane if s["name"] == "enabled")["colour"] == "#4caf50"  # the plot's green
assert all(a["from"] < b["from"] for a, b in zip(lane, lane[1:]))
end = get(f"/motion?t={rep['length_ms'] / 1000}")
x, y = (float(v) for v in re.match(r"ended at x (\S+) m, y (\S+) m", sys.argv[2]).groups())
assert (end["pose"]["x"], end["pose"]["y"]) == (x, y), (end["pose"], x, y)
start = get("/motion?t=0")
assert start["pose"] == {"x": 0, "y": 0, "heading": 0}, start["pose"]
assert get("/state")["pose"] == end["pose"]
for bad in ("-1", "x", "1e9", ""):
    try:
        get("/motion?t=" + bad)
        raise AssertionError("accepted t=" + bad)
    except urllib.error.HTTPError as e:
        assert e.code == 400, (bad, e.code)
print("ok")
PY
kill -INT $pid
wait $pid
code=$?
[[ $code -eq 0 ]] || fail "the replay's page ended $code: $(cat "$TMP/err")"
grep -q "trainer: the session's replay is at http://127.0.0.1:$PORT/ until Ctrl-C" "$TMP/err" ||
  fail "no address: $(cat "$TMP/err")"
finish
