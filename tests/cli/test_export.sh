# `export` as an investigator reads it alone (docs/recording.md, "Export"):
# a real run the supervisor stopped with a tap shorter than a tick, and a
# crafted session with a reset and a stop button held while enabled; each
# read with the docs' own Python example.
source "$(dirname "$0")/lib.sh"
HERE=$(dirname "$0")
export XDG_CONFIG_HOME=$TMP/xdg
STATE=$XDG_STATE_HOME/andros-bridge
docs=$DATA/../../docs/recording.md

# The docs' example: its code, and the output it shows.
python3 - "$docs" "$TMP/example.py" "$TMP/example.out" <<'PY'
import sys
text = open(sys.argv[1]).read()
open(sys.argv[2], "w").write(text.split("<!-- export reading example")[1].split("```python\n")[1].split("```")[0])
open(sys.argv[3], "w").write(text.split("<!-- export reading output -->")[1].split("```\n")[1].split("```")[0])
PY

# 1. A real run: the deadman, then the supervisor's stop tapped between two
# frames, then a shutdown request (SIGINT's). No reset: the gesture is not
# what this run is about.
printf 'robot: HD1\nextends: %s\nestop: guide\nsupervisor: {stop: guide}\n' "$DATA/mappings/core.yaml" >"$TMP/sup.yaml"
cat >"$TMP/stop.events" <<'E'
0    connect     Op pad
0    supervisor  connect Sup pad
40   button      leftshoulder 1
121  supervisor  button guide 1
122  supervisor  button guide 0
400  stop
E
run_cmd python3 "$HERE/pty_harness.py" "$TMP/cap" -- "$BIN" run --mapping "$TMP/sup.yaml" --port {PTY} --input "$TMP/stop.events"
[[ $code -eq 0 ]] || fail "run exited $code: $(cat "$TMP/err")"
session=$(ls "$STATE"/*.andros-session)
expect_exit 0 "$BIN" export "$session" --output "$TMP/run.csv"
python3 - "$TMP/run.csv" "$session" "$HERE" <<'PY' || fail "the run's export: see above"
import csv, sys
sys.path.insert(0, sys.argv[3])
import session_lib
rows = list(csv.DictReader(open(sys.argv[1], newline="", encoding="utf-8")))
header = set(rows[0])
want = {"stopped_by", "stop_pad", "reset_by", "reset_pad", "shutdown_requested", "operator_deadman", "operator_estop",
        "operator_reset", "supervisor_stop", "supervisor_reset", "supervisor_consent"}
assert want <= header, want - header
assert "stop" not in header, "the shutdown request is still a 'stop' column"
# The stop record says when the supervisor stopped; its tick's row says so, and holds it to the end.
stop_t = [int(text.split()[0]) for kind, text in session_lib.records(sys.argv[2]) if kind == "stop"]
assert len(stop_t) == 1, stop_t
at = next(i for i, r in enumerate(rows) if round(float(r["t"]) * 1000) == stop_t[0])
assert all(r["stopped_by"] == "" and r["stop_pad"] == "" for r in rows[:at]), rows[:at]
assert all(r["stopped_by"] == "supervisor" and r["stop_pad"] == "Sup pad" for r in rows[at:]), rows[at]
assert all(r["reset_by"] == "" and r["reset_pad"] == "" for r in rows)
# The tap, shorter than a tick, is a 1 on that row and only there.
assert [r["supervisor_stop"] for r in rows] == ["0"] * at + ["1"] + ["0"] * (len(rows) - at - 1), \
    [r["supervisor_stop"] for r in rows]
assert rows[at]["state"] == "stopped" and rows[at - 1]["state"] == "enabled", (rows[at - 1], rows[at])
assert all(r["operator_deadman"] == "1" for r in rows if r["state"] == "enabled")
assert all(r["operator_estop"] == "0" for r in rows)
# The mapping has no reset keys: the columns are there, empty.
assert all(r["operator_reset"] == "" and r["supervisor_reset"] == "" for r in rows)
# The shutdown request: 1 on the last rows (shutting down), 0 before.
flags = [r["shutdown_requested"] for r in rows]
assert flags[-1] == "1" and flags == sorted(flags), flags
assert all((r["state"] == "stopping") == (r["shutdown_requested"] == "1") for r in rows)
PY
run_cmd python3 "$TMP/example.py" "$TMP/run.csv"
[[ $code -eq 0 ]] || fail "the docs' example on the run's export exited $code: $(cat "$TMP/err")"
grep -Eqx '[0-9]+\.[0-9]{3} s: stopped by the supervisor \(Sup pad\)' "$TMP/out" && [[ $(wc -l <"$TMP/out") -eq 2 ]] ||
  fail "the docs' example on the run's export: $(cat "$TMP/out")"
grep -qx "ticks the supervisor held its stop while enabled: none" "$TMP/out" || fail "held while enabled: $(cat "$TMP/out")"

# craft OUT RECORDS...: the run's first four records (header, program,
# started, settings: its mapping), then RECORDS (payloads), rehashed.
craft() {
  local out=$1
  shift
  python3 - "$session" "$out" "$@" <<'PY'
import sys
head = [l.split(" ", 1)[1].rsplit(" ", 1)[0] for l in open(sys.argv[1]).read().split("\n")[:4]]
assert [p.split()[0] for p in head] == ["andros-session", "program", "started", "settings"], head
lines = [f"{i} {p} {'0' * 64}" for i, p in enumerate(head + sys.argv[3:])]
open(sys.argv[2], "w").write("\n".join(lines) + "\n")
PY
  python3 "$HERE/session_tool.py" rehash "$out" || fail "cannot rehash $out"
}

# 2. Crafted records: the supervisor stopped at 0.16 s and reset at 2.4 s;
# the operator enabled again at 2.52 s while the supervisor still held its
# stop button (to 2.6 s), then stopped with its own. The docs' example
# prints what the docs show.
rest=0000182000908080000000010020CC02
enabled=0600182000908080000000010020CC02
incident=('link -1 connecting motion "not opened yet"' 'event 0 connect Op pad' 'event 0 supervisor connect Sup pad'
  'state 0 not enabled' 'link 0 up motion ""' "frame 0 0 sent $rest gap=0" 'event 100 button leftshoulder 1'
  'state 120 enabled' "frame 3 120 sent $enabled gap=0" 'event 150 supervisor button guide 1'
  'stop 160 supervisor "Sup pad"' 'state 160 stopped' "frame 4 160 sent $rest gap=0"
  'event 170 supervisor button guide 0' 'event 300 button leftshoulder 0' 'event 400 supervisor button guide 1'
  'reset 2400 supervisor' 'state 2400 not enabled' 'event 2500 button leftshoulder 1' 'state 2520 enabled'
  "frame 63 2520 sent $enabled gap=0" 'event 2600 supervisor button guide 0' 'event 2700 button guide 1'
  'stop 2720 operator "Op pad"' 'state 2720 stopped' "frame 68 2720 sent $rest gap=0"
  'end 2800 tick 70 frames 71 "end of the input"')
craft "$TMP/crafted.andros-session" "${incident[@]}"
expect_exit 0 "$BIN" verify "$TMP/crafted.andros-session"
expect_exit 0 "$BIN" export "$TMP/crafted.andros-session" --output "$TMP/crafted.csv"
run_cmd python3 "$TMP/example.py" "$TMP/crafted.csv"
[[ $code -eq 0 && $(cat "$TMP/out") == "$(cat "$TMP/example.out")" ]] ||
  fail "the docs' example prints what the docs do not show: $(cat "$TMP/out" "$TMP/err")"
# The rows the output stands on: who reset, until the enable; each input on
# the rows it was held into.
python3 - "$TMP/crafted.csv" <<'PY' || fail "the crafted session's export: see above"
import csv, sys
rows = {r["tick"]: r for r in csv.DictReader(open(sys.argv[1], newline="", encoding="utf-8"))}
assert [rows[k]["reset_by"] for k in ("59", "60", "62", "63")] == ["", "supervisor", "supervisor", ""]
assert rows["59"]["stopped_by"] == "supervisor" and rows["60"]["stopped_by"] == ""
got = [rows[k]["supervisor_stop"] for k in ("3", "4", "5", "6", "10", "65", "66")]
assert got == ["0", "1", "1", "0", "1", "1", "0"], got
got = [rows[k]["operator_deadman"] for k in ("2", "3", "8", "9", "63")]
assert got == ["0", "1", "1", "0", "1"], got
assert rows["68"]["operator_estop"] == "1" and rows["68"]["stopped_by"] == "operator"
PY

# 3. Names from outside: a controller's name and a layer's that a
# spreadsheet would run as formulas, with a comma, quotes, a newline and
# terminal escapes, are text on one line each, never a formula.
hostile=("${incident[@]}")
hostile[10]='stop 160 supervisor "=HYPERLINK(\"http://x\",\"a,b\")\n"'
hostile[4]='layer 0 "@SUM(1+1)\u001b]0;x\u0007"'
craft "$TMP/hostile.andros-session" "${hostile[@]}"
expect_exit 0 "$BIN" export "$TMP/hostile.andros-session" --output "$TMP/hostile.csv"
python3 - "$TMP/hostile.csv" <<'PY' || fail "the hostile names' export: see above"
import csv, sys
raw = open(sys.argv[1], "rb").read()
raw.decode("utf-8")  # valid UTF-8 throughout
rows = list(csv.DictReader(open(sys.argv[1], newline="", encoding="utf-8")))
assert len(rows) == 71 and raw.count(b"\n") == 72, (len(rows), raw.count(b"\n"))  # a header, a line a row
assert rows[4]["stop_pad"] == "'=HYPERLINK(\"http://x\",\"a,b\")\\n", rows[4]["stop_pad"]
assert rows[0]["layer"] == "'@SUM(1+1)\\x1B]0;x\\x07", rows[0]["layer"]
for r in rows:
    for v in r.values():
        assert v[:1] not in ("=", "+", "-", "@", "\t", "\r"), v
PY
finish
