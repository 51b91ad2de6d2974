# One reading of a session for verify, sessions, replay, plot and export
# (docs/recording.md, "Verify"): a last line without its newline is never
# data, even forged to chain (a weapon bit, a stop, an end that claims 226
# frames); nor are records after the chain breaks, or NUL bytes after the end.
# Each reader's output with such a line is its output without it. An end
# holds no more than a session can; a session whose records say the disk
# filled is said so; a FIFO, directory, device or socket is refused at once,
# saying what it is; an output FIFO with no reader is refused, not waited on.
source "$(dirname "$0")/lib.sh"
HERE=$(dirname "$0")
tool() { python3 "$HERE/session_tool.py" "$@"; }
S=$DATA/sessions/drive.andros-session  # 23 records: enabled 120..720 ms, frame records to tick 18, closed at tick 23
F=$TMP/f
mkdir -p "$F"

# forge NAME N LINE: the drive's first N records, then LINE without its newline, the chain made again.
forge() {
  { head -n "$2" "$S"; printf '%s' "$3"; } >"$F/$1.andros-session"
  tool rehash "$F/$1.andros-session"
}
head -n 17 "$S" >"$F/to17.andros-session"  # to the frame record of tick 15 (600 ms), enabled, not closed
head -n 22 "$S" >"$F/to22.andros-session"  # all but the end record
forge weapon 17 "17 frame 16 640 sent 0600182100908080000000010020CC02 gap=0"
forge stop 17 '17 stop 640 supervisor {"name":"boss","path":"","serial":"","guid":""}'
forge end 22 '22 end 9000 tick 225 frames 226 "end of the input"'

# alone FILE DIR: FILE as the one session in $TMP/DIR (20240101-000000-1.andros-session).
alone() {
  mkdir -p "$TMP/$2"
  cp "$1" "$TMP/$2/20240101-000000-1.andros-session"
}
# listed FILE DIR VERDICT NOTE: sessions lists FILE, alone in DIR, as VERDICT, with NOTE (a regex) under the table.
listed() {
  alone "$1" "$2"
  expect_exit 0 "$BIN" sessions --record-dir "$TMP/$2"
  grep -Eq " $3 +$TMP/$2/20240101-000000-1.andros-session\$" "$TMP/out" || fail "sessions of $2: $(cat "$TMP/out")"
  grep -Eq "^$TMP/$2/20240101-000000-1.andros-session: $4" "$TMP/out" || fail "sessions of $2 does not say /$4/: $(cat "$TMP/out")"
}
# jsonl_row DIR: the one session's JSON object in DIR without its file name and verdict.
jsonl_row() {
  "$BIN" sessions --record-dir "$1" --format jsonl |
    python3 -c 'import json,sys; r=json.loads(sys.stdin.read()); [r.pop(k) for k in ("file","verify")]; print(json.dumps(r, sort_keys=True))'
}
# svg_body FILE: the page without its source line (which names the file and says it was cut short).
svg_body() { grep -v '>session ' "$1"; }
# same_page_and_rows BASE FILE WHAT: FILE's plot (but for its source line,
# $TMP/got.svg) and export ($TMP/err: its warnings) are BASE's.
same_page_and_rows() {
  expect_exit 0 "$BIN" plot "$1" --output "$TMP/base.svg"
  expect_exit 0 "$BIN" plot "$2" --output "$TMP/got.svg"
  [[ $(svg_body "$TMP/got.svg") == "$(svg_body "$TMP/base.svg")" ]] || fail "plot drew $3"
  expect_exit 0 "$BIN" export "$1" --output "$TMP/base.csv"
  expect_exit 0 "$BIN" export "$2" --output "$TMP/got.csv"
  cmp -s "$TMP/base.csv" "$TMP/got.csv" || fail "export wrote $3: $(diff "$TMP/base.csv" "$TMP/got.csv" | head -5)"
}

for forged in weapon:to17:17 stop:to17:17 end:to22:22; do
  IFS=: read -r name base n <<<"$forged"
  # verify: cut short at the forged line, the records before it intact, not closed.
  expect_exit 0 "$BIN" verify "$F/$name.andros-session"
  [[ $(head -1 "$TMP/out") == "cut short at line $((n + 1)): the run was cut off, power lost or disk full; the $n records before it are intact" ]] ||
    fail "verify of the forged $name line: $(cat "$TMP/out")"
  grep -q "^not closed: " "$TMP/out" || fail "verify: the forged $name line closed the session: $(cat "$TMP/out")"
  # sessions, table and JSON: what the records before it say.
  alone "$F/$name.andros-session" "$name"
  alone "$F/$base.andros-session" "$name-base"
  expect_exit 0 "$BIN" sessions --record-dir "$TMP/$name"
  grep -q "intact, cut short" "$TMP/out" || fail "sessions of the forged $name line: $(cat "$TMP/out")"
  [[ $(jsonl_row "$TMP/$name") == "$(jsonl_row "$TMP/$name-base")" ]] ||
    fail "sessions --format jsonl read the forged $name line: $(jsonl_row "$TMP/$name") against $(jsonl_row "$TMP/$name-base")"
  # replay: the records before it, as if it were not there.
  expect_exit 0 "$BIN" replay "$F/$base.andros-session"
  want=$(cat "$TMP/out")
  expect_exit 0 "$BIN" replay "$F/$name.andros-session"
  expect_stdout "$want"
  # plot and export: the same page (its source line says it was cut short) and rows (and a warning).
  same_page_and_rows "$F/$base.andros-session" "$F/$name.andros-session" "the forged $name line"
  expect_stderr_matches "cut short at line $((n + 1))"
  grep -q "cut short at line $((n + 1))" "$TMP/got.svg" || fail "plot does not say the $name session was cut short"
done
# The issue's words, each: no weapon fired, no stop, not 226 frames.
cp "$F/weapon.andros-session" "$F/stop.andros-session" "$F/end.andros-session" "$TMP/weapon/"
expect_exit 0 "$BIN" sessions --record-dir "$TMP/weapon" --format jsonl
python3 - "$TMP/out" <<'PY' || fail "sessions read a forged line: $(cat "$TMP/out")"
import json, sys
rows = {r["file"].rsplit("/", 1)[1]: r for r in map(json.loads, open(sys.argv[1]))}
assert not rows["weapon.andros-session"]["weapons_fired"], rows["weapon.andros-session"]
assert rows["stop.andros-session"]["stops"] == {"operator": 0, "supervisor": 0, "gate": 0}, rows["stop.andros-session"]
assert rows["end.andros-session"]["frames_sent"] == 19, rows["end.andros-session"]  # ticks 0..18, as recorded
PY

# Records after the chain breaks are not data: the frame of tick 15 given a
# weapon bit, not rehashed. sessions lists, plot draws and export writes what
# the 16 records before it say; replay refuses.
sed '17s/ sent 0600182000908080000000010020CC02 / sent 0600182100908080000000010020CC02 /' "$S" >"$F/altered.andros-session"
head -n 16 "$S" >"$F/to16.andros-session"
alone "$F/altered.andros-session" altered
alone "$F/to16.andros-session" altered-base
expect_exit 0 "$BIN" sessions --record-dir "$TMP/altered"
grep -Eq " HD1 +[0-9]+ +no\? +0\? .* NOT INTACT " "$TMP/out" || fail "sessions counted a record after the break: $(cat "$TMP/out")"
[[ $(jsonl_row "$TMP/altered" | python3 -c 'import json,sys; r=json.loads(sys.stdin.read()); print(r["weapons_fired"], r["frames_sent"])') == \
  "$(jsonl_row "$TMP/altered-base" | python3 -c 'import json,sys; r=json.loads(sys.stdin.read()); print(r["weapons_fired"], r["frames_sent"])')" ]] ||
  fail "sessions --format jsonl read records after the break: $(jsonl_row "$TMP/altered")"
expect_exit 1 "$BIN" replay "$F/altered.andros-session"
expect_stdout "NOT INTACT: record 16 (line 17) altered: its content or hash no longer matches the chain (andros-bridge verify)"
same_page_and_rows "$F/to16.andros-session" "$F/altered.andros-session" "records after the break"
grep -q "NOT INTACT: record 16 (line 17) altered" "$TMP/got.svg" || fail "plot does not say the session is not intact"
expect_stderr_matches "NOT INTACT: record 16 \(line 17\) altered.*: exported the 16 records before it"

# An end holds what a session can: its time within 24 h, its tick -1 only at
# 0 ms with no frame record, and at most a frame a tick 0 through its tick.
for end in "0 tick -1 frames 5000000000:5000000000 frames sent: not within a session that ended at tick -1" \
  "9000000000000000 tick -1 frames 0:time 9000000000000000 ms: not within a session"; do
  IFS=: read -r fields why <<<"$end"
  { head -n 9 "$S"; echo "9 end $fields \"SIGINT\""; } >"$F/end-range.andros-session"  # no frame record before it
  tool rehash "$F/end-range.andros-session"
  expect_exit 1 "$BIN" verify "$F/end-range.andros-session"
  grep -q "^unreadable: .*end-range.andros-session:10: error: $why" "$TMP/out" || fail "verify of end $fields: $(cat "$TMP/out")"
  for cmd in replay plot export; do
    expect_exit 2 "$BIN" $cmd "$F/end-range.andros-session"
    expect_stderr_matches "end-range.andros-session:10: error: $why"
  done
  alone "$F/end-range.andros-session" range
  expect_exit 0 "$BIN" sessions --record-dir "$TMP/range"
  grep -Eq '^\? +\? .* unreadable ' "$TMP/out" || fail "sessions of end $fields: $(cat "$TMP/out")"
done

# A FIFO, a directory, a device or a socket named as a session: refused at
# once by every reader, saying what it is; never waited on.
mkfifo "$F/fifo.andros-session"
mkdir "$F/dir.andros-session"
python3 -c 'import socket,sys; socket.socket(socket.AF_UNIX).bind(sys.argv[1])' "$F/sock.andros-session"
for what in "fifo:a FIFO" "dir:a directory" "sock:a socket"; do
  IFS=: read -r name kind <<<"$what"
  for cmd in verify replay export; do
    expect_exit 2 timeout 10 "$BIN" $cmd "$F/$name.andros-session"
    expect_stderr_matches "$name.andros-session: error: is $kind, not a session file"
  done
  expect_exit 2 timeout 10 "$BIN" plot "$F/$name.andros-session"
  expect_stderr_matches "$name.andros-session: error: is $kind, not a session or an event script file"
done
expect_exit 2 timeout 10 "$BIN" plot /dev/null
expect_stderr_matches "^/dev/null: error: is a character device, not a session or an event script file"
expect_exit 2 timeout 10 "$BIN" verify /dev/null
expect_stderr_matches "^/dev/null: error: is a character device, not a session file"

# NUL bytes after a closed session (blocks a power loss left unwritten): closed all the same, and said.
{ cat "$S"; head -c 4096 /dev/zero; } >"$F/nul.andros-session"
expect_exit 0 "$BIN" verify "$F/nul.andros-session"
[[ $(head -2 "$TMP/out") == "intact (23 records)
closed: the run ended and its last record is here; 4096 NUL bytes after it (blocks a power loss left unwritten)" ]] ||
  fail "verify of a closed session with a NUL tail: $(cat "$TMP/out")"
listed "$F/nul.andros-session" nul "intact" "closed: .*4096 NUL bytes after it"

# The recording stopped for want of room, as the run's own records say: a
# `dropped` record last (with or without its reason), and no end after it.
for dropped in 'dropped 3 "No space left on device"' "dropped 3"; do
  { cat "$F/to17.andros-session"; echo "17 $dropped"; } >"$F/full.andros-session"
  tool rehash "$F/full.andros-session"
  expect_exit 0 "$BIN" verify "$F/full.andros-session"
  grep -qx "not closed: recording stopped at tick 15: the disk was full or a file-size limit was reached" "$TMP/out" ||
    fail "verify after '$dropped': $(cat "$TMP/out")"
  listed "$F/full.andros-session" full "intact, disk full" "recording stopped at tick 15: the disk was full"
done

# An output FIFO that no reader opens: refused with a clear line, not waited on for ever.
# The three at once: each waits its own 5 s.
mkfifo "$TMP/out.fifo"
cmds=("plot $S" "export $S" "sheet --robot hd1")
for i in "${!cmds[@]}"; do
  (timeout 30 "$BIN" ${cmds[$i]} --output "$TMP/out.fifo" >/dev/null 2>"$TMP/fifo$i.err"; echo $? >"$TMP/fifo$i.code") &
done
wait
for i in "${!cmds[@]}"; do
  [[ $(cat "$TMP/fifo$i.code") == 1 ]] || fail "'${cmds[$i]} --output FIFO' exited $(cat "$TMP/fifo$i.code"), expected 1"
  grep -q "cannot open '.*out.fifo' for writing: a FIFO that no reader opened in 5 s" "$TMP/fifo$i.err" ||
    fail "'${cmds[$i]} --output FIFO': $(cat "$TMP/fifo$i.err")"
done

finish
