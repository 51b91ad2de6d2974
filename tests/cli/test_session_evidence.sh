# Sessions an investigator can trust (docs/recording.md), tried as a hostile
# tester would: a session is data, never a path; rotation removes only its
# own closed sessions; a file-size limit never ends a drive. Crafted sessions
# are re-hashed (session_tool.py), so that verify finds them intact.
source "$(dirname "$0")/lib.sh"
HERE=$(dirname "$0")
LIVE=$DATA/live
export XDG_CONFIG_HOME=$TMP/xdg  # no user config file or mapping may change these runs
STATE=$XDG_STATE_HOME/andros-bridge
harness() { python3 "$HERE/pty_harness.py" "$@"; }
tool() { python3 "$HERE/session_tool.py" "$@"; }
frames_in() { "$BIN" frame decode "$1" 2>/dev/null | wc -l; }

run_cmd harness "$TMP/cap" -- "$BIN" run --robot hd1 --port {PTY} --input "$LIVE/drive.events"
[[ $code -eq 0 ]] || fail "run exited $code: $(cat "$TMP/err")"
session=$(ls "$STATE"/*.andros-session | tail -1)
expect_exit 0 "$BIN" replay "$session"
identical=$(cat "$TMP/out")
[[ $identical =~ ^[0-9]+\ frames\ identical\;\ [0-9]+\ records\ .*\ made\ again\ the\ same$ ]] || fail "replay of the session: $identical"

# 1. A recorded path is a label: `../` in it writes nothing anywhere.
cp "$session" "$TMP/dotdot.andros-session"
tool settings "$TMP/dotdot.andros-session" 's["files"][0]["path"] = "../../escaped/hd1.yaml"; s["mapping"] = "../../escaped/hd1.yaml"'
expect_exit 0 "$BIN" verify "$TMP/dotdot.andros-session"
mkdir -p "$TMP/a/b"
TMPDIR=$TMP/a/b expect_exit 0 "$BIN" replay "$TMP/dotdot.andros-session"
expect_stdout "$identical"
[[ ! -e $TMP/a/escaped ]] || fail "replay wrote the recorded mapping outside its folder: $(find "$TMP/a")"
[[ -z $(ls -A "$TMP/a/b") ]] || fail "replay left files: $(ls -A "$TMP/a/b")"

# 1. `extends: hd1` is the recorded hd1.yaml, never today's local one.
mkdir -p "$XDG_CONFIG_HOME/andros-bridge/mappings"
printf 'robot: HD1\nbindings: [ not what was recorded\n' >"$XDG_CONFIG_HOME/andros-bridge/mappings/hd1.yaml"
cp "$session" "$TMP/extends.andros-session"
tool settings "$TMP/extends.andros-session" '
mine = "robot: HD1\nextends: hd1\n"
s["files"].insert(0, {"path": "/home/op/.config/andros-bridge/mappings/mine.yaml", "text": mine,
                      "sha256": hashlib.sha256(mine.encode()).hexdigest()})
s["mapping"] = s["files"][0]["path"]'
expect_exit 0 "$BIN" replay "$TMP/extends.andros-session"
expect_stdout "$identical"
rm -r "$XDG_CONFIG_HOME/andros-bridge/mappings"

# 3. Rotation: only closed sessions of its own. A file named like a session
# that is not one, a link, and a session another bridge holds locked stay.
mkdir -p "$TMP/rot"
printf 'my notes\n' >"$TMP/rot/20200101-000000-1.andros-session"
{ printf '0 andros-session 2 %064d\n' 0; head -c 700000 /dev/zero; } >"$TMP/rot/20200102-000000-1.andros-session"
{ printf '0 andros-session 2 %064d\n' 0; head -c 700000 /dev/zero; } >"$TMP/rot/20200103-000000-1.andros-session"
cp "$session" "$TMP/elsewhere.andros-session"
ln -s "$TMP/elsewhere.andros-session" "$TMP/rot/20200104-000000-1.andros-session"
touch -d '40 days ago' "$TMP/rot"/2020010[1-3]-000000-1.andros-session
flock "$TMP/rot/20200103-000000-1.andros-session" sleep 60 &
holder=$!
for _ in $(seq 50); do  # until the holder has its lock
  flock -n "$TMP/rot/20200103-000000-1.andros-session" true || break
  sleep 0.1
done
run_cmd harness "$TMP/cap" -- "$BIN" run --record-dir "$TMP/rot" --record-max-mb 1 --port {PTY} --input "$LIVE/drive.events"
kill "$holder"
wait "$holder" 2>/dev/null
[[ $code -eq 0 ]] || fail "run with rotation exited $code"
[[ -e $TMP/rot/20200101-000000-1.andros-session ]] || fail "rotation removed a file that is not a session"
[[ ! -e $TMP/rot/20200102-000000-1.andros-session ]] || fail "rotation kept an old closed session"
[[ -e $TMP/rot/20200103-000000-1.andros-session ]] || fail "rotation removed a session another bridge holds"
[[ -L $TMP/rot/20200104-000000-1.andros-session && -e $TMP/elsewhere.andros-session ]] ||
  fail "rotation followed or removed a link"
expect_exit 0 "$BIN" sessions --dir "$TMP/rot"
grep -q "20200101-000000-1" "$TMP/out" && fail "sessions lists a file that is not a session: $(cat "$TMP/out")"

# 5. A file-size limit (`ulimit -f`) never ends a drive: the session's writes
# fail with EFBIG, the recorder drops and warns, the frames go on to the
# shutdown's neutral ones, and what was written is whole records.
run_cmd harness "$TMP/cap" -- bash -c 'ulimit -f 4 && exec "$@"' limited \
  "$BIN" run --record-dir "$TMP/limited" --port {PTY} --input "$LIVE/drive.events"
[[ $code -eq 0 ]] || fail "under ulimit -f the run exited $code: $(tail -3 "$TMP/err")"
expect_stderr_matches "recorder: records dropped \(File too large\).*driving goes on"
"$BIN" frame decode "$TMP/cap" 2>/dev/null | python3 "$HERE/check_frames.py" --bin "$BIN" --min 15 --driving \
  --neutral-tail 3 >"$TMP/check" || fail "under ulimit -f: $(cat "$TMP/check")"
limited=$(ls "$TMP/limited"/*.andros-session)
(($(stat -c %s "$limited") <= 4096)) || fail "the session grew past the limit"
[[ $(tail -c 1 "$limited" | od -An -c | tr -d ' ') == '\n' ]] || fail "the session ends in half a record"
# Its chain is whole; its settings did not fit, so its ticks cannot be read:
# verify says so, as sessions (unreadable) and replay do.
expect_exit 1 "$BIN" verify "$limited"
grep -q "^intact" "$TMP/out" || fail "verify of the limited session: $(cat "$TMP/out")"
grep -q "^unreadable: .*a tick before the settings" "$TMP/out" || fail "verify of the limited session: $(cat "$TMP/out")"

# 4. A session cut short (the disk full, power lost mid-record) is told from
# an altered one, listed with what was read, and plotted.
head -c -30 "$session" >"$TMP/cut.andros-session"
records=$(($(wc -l <"$TMP/cut.andros-session")))
expect_exit 0 "$BIN" verify "$TMP/cut.andros-session"
head -1 "$TMP/out" | grep -qx "cut short at line $((records + 1)): the run was cut off, power lost or disk full; the $records records before it are intact" ||
  fail "verify of a session cut short: $(cat "$TMP/out")"
grep -q "^not closed" "$TMP/out" || fail "verify: a session cut short is closed: $(cat "$TMP/out")"
mkdir -p "$TMP/cutdir"
cp "$TMP/cut.andros-session" "$TMP/cutdir/20240101-000000-1.andros-session"
expect_exit 0 "$BIN" sessions --record-dir "$TMP/cutdir"
# Its records after the last frame record (the stopping state) are not replayed: WEAPONS and STOPS unproven.
grep -Eq "HD1 +[0-9]+ +no\\? +0\\? +0 +0 +0 +intact, cut short +$TMP/cutdir/20240101-000000-1.andros-session" "$TMP/out" ||
  fail "sessions of a session cut short: $(cat "$TMP/out")"
expect_exit 0 "$BIN" plot "$TMP/cut.andros-session" --output "$TMP/cut.svg"
grep -q "cut short at line $((records + 1))" "$TMP/cut.svg" || fail "the plot does not say the session was cut short"
# Half a line in the middle is an alteration all the same.
python3 -c 'import sys; p=sys.argv[1]; l=open(p).read().split("\n"); l[5]=l[5][:20]; open(p,"w").write("\n".join(l))' "$TMP/cut.andros-session"
expect_exit 1 "$BIN" verify "$TMP/cut.andros-session"
expect_stdout "NOT INTACT: record 5 (line 6) altered: not a record line"

# 2. Bounded reading: an end tick edited to 1e11 (the chain made again) is an
# error at its line, for replay, plot and export alike; a 20 MB line is refused
# at 4 MiB.
python3 - "$session" "$TMP/far.andros-session" <<'PY'
import re, sys
lines = open(sys.argv[1]).read().split("\n")
lines = [re.sub(r" tick \d+ frames", " tick 100000000000 frames", l) if " end " in l else l for l in lines]
open(sys.argv[2], "w").write("\n".join(lines))
PY
tool rehash "$TMP/far.andros-session"
end_line=$(grep -n " end " "$TMP/far.andros-session" | cut -d: -f1)
# The chain is whole, but its records are not a session's: verify says so, as sessions does.
expect_exit 1 "$BIN" verify "$TMP/far.andros-session"
grep -q "^unreadable: .*far.andros-session:$end_line: error: tick 100000000000: not within a session" "$TMP/out" ||
  fail "verify of an end tick of 1e11: $(cat "$TMP/out")"
for cmd in replay plot export; do
  expect_exit 2 "$BIN" $cmd "$TMP/far.andros-session"
  expect_stderr_matches "far.andros-session:$end_line: error: tick 100000000000: not within a session"
done
{ head -3 "$session"; head -c 20000000 /dev/zero | tr '\0' x; echo; } >"$TMP/long.andros-session"
expect_exit 1 "$BIN" verify "$TMP/long.andros-session"
expect_stdout "NOT INTACT: record 3 (line 4) altered: line longer than 4 MiB (the limit for a session), longer than any record"
expect_exit 2 "$BIN" export "$TMP/long.andros-session"
expect_stderr_matches "long.andros-session:4: error: line longer than 4 MiB"
# Not a session, whatever its name; a FIFO is never waited on.
printf 'hello\n' >"$TMP/not.andros-session"
expect_exit 1 "$BIN" verify "$TMP/not.andros-session"
expect_stdout "NOT INTACT: record 0 (line 1) altered: not a record line"
mkfifo "$TMP/fifo.andros-session"
expect_exit 2 timeout 10 "$BIN" verify "$TMP/fifo.andros-session"
expect_stderr_matches "is a FIFO, not a session file"

# 7. One answer to a reload that cannot be read: replay, as run, keeps the
# old mapping, logs it and goes on.
printf '0 connect pad\n40 reload /proc/self/mem\n200 button leftshoulder 1\n240 axis lefty -32768\n400 end\n' >"$TMP/reload.events"
expect_exit 0 "$BIN" replay "$TMP/reload.events" --robot hd1 --format jsonl --output "$TMP/reload.jsonl"
expect_stderr_matches "reload at [0-9]+ ms failed, the old mapping stays: .*/proc/self/mem"
[[ $(frames "$TMP/reload.jsonl" | tail -1) == "400 255 128 1" ]] || fail "replay after a failed reload: $(frames "$TMP/reload.jsonl" | tail -2)"
run_cmd harness "$TMP/cap" -- "$BIN" run --robot hd1 --port {PTY} --input "$TMP/reload.events"
[[ $code -eq 0 ]] || fail "run after a failed reload exited $code"
expect_stderr_matches "reload .*failed, the old settings stay"

# 6. Names that work everywhere: `sessions` prints bare names that verify,
# replay, plot and export take from any folder; one Ctrl-C, one request.
name=$(basename "$session")
expect_exit 0 "$BIN" sessions
grep -q " $name\$" "$TMP/out" || fail "sessions does not print the bare name: $(cat "$TMP/out")"
for cmd in verify replay plot export; do
  (cd / && "$BIN" $cmd "$name" >/dev/null 2>"$TMP/err") || fail "$cmd $name from /: $(head -c 300 "$TMP/err")"
done
expect_exit 0 "$BIN" sessions --dir "$STATE"
grep -q " $name\$" "$TMP/out" || fail "sessions --dir (the older name) no longer lists: $(cat "$TMP/out")"
run_cmd harness "$TMP/cap" --term-after 10 -- "$BIN" run --robot hd1 --port {PTY} --input "$LIVE/long_drive.events"
stopped=$(ls -t "$STATE"/*.andros-session | head -1)
[[ $(grep -c " request [0-9]* stop " "$stopped") -eq 1 ]] || fail "one SIGTERM made $(grep -c " request [0-9]* stop " "$stopped") stop records"

# 9. export: a row per tick, one strictly increasing time column; the example
# in docs/recording.md is this program's output.
expect_exit 0 "$BIN" export "$session" --output "$TMP/s.csv"
python3 - "$TMP/s.csv" <<'PY' || fail "export's CSV"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert len(rows) > 15, len(rows)
t = [float(r["t"]) for r in rows]
assert all(a < b for a, b in zip(t, t[1:])), "time not strictly increasing"
assert {"drive", "pivot", "safety", "state", "layer", "stopped_by", "shutdown_requested", "link"} <= set(rows[0]), rows[0].keys()
assert any(r["drive"] != "128" for r in rows), "never drove"
PY
expect_exit 0 "$BIN" export "$session" --format jsonl
python3 -c 'import json,sys; r=[json.loads(l) for l in open(sys.argv[1])]; assert len(r)>15 and "drive" in r[0]' "$TMP/out" || fail "export's JSONL"
expect_exit 2 "$BIN" export "$session" --format xml
expect_stderr_matches "^--format: error: expected csv or jsonl"
example=$(python3 -c 'import sys; t=open(sys.argv[1]).read(); print(t.split("<!-- export example")[1].split("```")[1].strip())' \
  "$DATA/../../docs/recording.md")
command=$(head -1 <<<"$example" | sed 's/^\$ andros-bridge //')
got=$(cd "$DATA/../.." && eval "\"$BIN\" $command")
[[ -n $got && $got == "$(tail -n +2 <<<"$example")" ]] || fail "docs/recording.md's export example is not what export writes: $got"

finish
