# Room for the last word (issue 34, docs/recording.md): on a full disk and
# under a file-size limit the drive goes on, and the session still closes
# with the records that say why recording stopped: `dropped N "WHY"` at once,
# and at the end `dropped` and `end` (the writer keeps room for them). On the
# landed main a 64 KB tmpfs or `ulimit -f 50` left no `dropped` record and no
# `end`, and `verify` blamed a crash or power loss.
source "$(dirname "$0")/lib.sh"
cd "$TMP"

# Four seconds of a stick moving on every tick: about 30 KB of records.
{
  printf '0 connect pad\n100 button leftshoulder 1\n'
  for ((t = 200; t < 4000; t += 40)); do
    printf '%d axis lefty %d\n%d axis leftx %d\n' $t $((-2000 - (t * 7) % 30000)) $t $((t * 3 % 20000))
  done
  printf '4000 end\n'
} >busy.events

# sent_frames: the frames the vehicle decoded, all of them valid, as the run's
# last line in $TMP/err says: every tick the loop ran, 104 on a machine that
# kept up (a loaded one skips a tick it could not run in time: the session
# says so, a gap, and its end record counts what was sent).
sent_frames() {
  sed -n 's/.*sim vehicle decoded \([0-9]*\) frames: \1 valid, 0 bad checksum, 0 invalid.*/\1/p' "$TMP/err"
}

# check_stopped_session DIR WHY: the session in DIR is intact and closed, and a
# `dropped` record before its end says WHY; the run sent every frame.
check_stopped_session() {
  local session frames; session=$(ls "$1"/*.andros-session)
  frames=$(sent_frames)
  [[ -n $frames ]] || fail "$2: the drive: $(tail -3 "$TMP/err")"
  expect_exit 0 "$BIN" verify "$session"
  grep -Eq "^closed: the run ended and its last record is here; recording stopped at tick [0-9]+: the disk was full or a file-size limit was reached" "$TMP/out" ||
    fail "$2: verify: $(cat "$TMP/out")"
  grep -q " dropped [0-9]* \"$2\" " "$session" || fail "$2: no dropped record says why: $(tail -c 400 "$session")"
  tail -1 "$session" | grep -q " end 4120 tick 103 frames $frames " || fail "$2: the end record: $(tail -1 "$session")"
}

# A full disk: a 16 KB tmpfs in a mount namespace of the test's own (a user
# namespace: no privilege needed); the session is copied out before it goes.
mkdir full kept
expect_exit 0 unshare -rm bash -c 'mount -t tmpfs -o size=16k tmpfs full && "$0" run --input busy.events --port sim \
  --record-dir full && cp full/*.andros-session kept/' "$BIN"
(($(stat -c %s kept/*.andros-session) < 16384)) || fail "the session is larger than the disk"
check_stopped_session kept "No space left on device"

expect_exit 0 "$BIN" sessions --record-dir kept
grep -q ' intact, disk full ' "$TMP/out" || fail "sessions: $(cat "$TMP/out")"

# A file-size limit of 16 KB: the settings record (9 KB) fits, the drive does not.
expect_exit 0 bash -c 'ulimit -f 16 && exec "$0" run --input busy.events --port sim --record-dir limited' "$BIN"
(($(stat -c %s limited/*.andros-session) <= 16384)) || fail "the session grew past the limit"
check_stopped_session limited "File too large"

# A file-size limit of 8 KB: the settings record itself does not fit. The
# session still closes and says why: it cannot be replayed, and says that.
expect_exit 0 bash -c 'ulimit -f 8 && exec "$0" run --input busy.events --port sim --record-dir tiny' "$BIN"
frames=$(sent_frames)
[[ -n $frames ]] || fail "8 KB: the drive: $(tail -3 "$TMP/err")"
tiny=$(ls tiny/*.andros-session)
tail -1 "$tiny" | grep -q " end 4120 tick 103 frames $frames " || fail "8 KB: the end record: $(tail -1 "$tiny")"
expect_exit 1 "$BIN" verify "$tiny"
grep -q 'before the settings: they were dropped (File too large)' "$TMP/out" "$TMP/err" ||
  fail "8 KB: verify: $(cat "$TMP/out" "$TMP/err")"

exit $((failures > 0))
