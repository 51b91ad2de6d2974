# Issue 16's stop, three-position trigger and enable timeout, proven by replay
# on the virtual clock (docs/mapping.md "Stop", "Three-position trigger",
# "Enable timeout"; docs/safety-states.md): the frames the vehicle receives.
source "$(dirname "$0")/lib.sh"
export XDG_CONFIG_HOME="$TMP/no-config"
core="$DATA/mappings/core.yaml"

at() { awk -v t="$1" '$1 == t' "$2"; }

# 1. The stop latches through a held deadman and a held stick; releasing the
# stop, the deadman, or both, never resets it, nor does the stop button
# pressed again and held 2 s (a stop button only ever stops, issue 33); the
# reset chord (back and start) held 2 s with the deadman and the stop
# released does; then a fresh press (stick at rest first) drives again.
printf 'robot: HD1\nextends: %s\nestop: guide\nstop_reset: [back, start]\n' "$core" >"$TMP/stop.yaml"
cat >"$TMP/stop.events" <<'E'
0    connect     pad
40   button      leftshoulder 1
60   axis        lefty -32768
150  button      guide 1
170  button      guide 0
300  button      leftshoulder 0
310  button      guide 1
330  button      leftshoulder 1
400  button      leftshoulder 0
420  button      guide 0
500  button      leftshoulder 1
560  button      leftshoulder 0
580  button      guide 1
2700 button      guide 0
2710 button      back 1
2710 button      start 1
4850 button      back 0
4850 button      start 0
4900 button      leftshoulder 1
5000 axis        lefty 0
5040 axis        lefty -32768
5200 end
E
expect_exit 0 "$BIN" replay "$TMP/stop.events" --mapping "$TMP/stop.yaml" --format jsonl
frames "$TMP/out" >"$TMP/f1"
[[ $(at 120 "$TMP/f1") == "120 255 128 1" ]] || fail "no drive before the stop: $(tr '\n' ';' <"$TMP/f1")"
# From the frame after the press on, neutral whatever is held or let go,
# until the reset (the chord from 2720, done at 4720) and a fresh press (4900) ...
awk '$1 >= 160 && $1 <= 4880 && ($2 != 128 || $3 != 128 || $4 != 0) { exit 1 }' "$TMP/f1" ||
  fail "motion while stopped: $(tr '\n' ';' <"$TMP/f1")"
# ... which enables, the stick held through it waits for rest (5000), drives at 5040.
[[ $(at 4920 "$TMP/f1") == "4920 128 128 1" ]] || fail "the fresh press after the reset does not enable: $(tr '\n' ';' <"$TMP/f1")"
[[ $(at 5000 "$TMP/f1") == "5000 128 128 1" ]] || fail "a stick held through the stop acts before rest: $(tr '\n' ';' <"$TMP/f1")"
[[ $(at 5040 "$TMP/f1") == "5040 255 128 1" ]] || fail "no drive after the stop was reset: $(tr '\n' ';' <"$TMP/f1")"

# 2. A tap between two frames stops too; a deadman held through it and never
# released keeps the stop.
cat >"$TMP/tap.events" <<'E'
0    connect     pad
40   button      leftshoulder 1
60   axis        lefty -32768
121  button      guide 1
122  button      guide 0
600  end
E
expect_exit 0 "$BIN" replay "$TMP/tap.events" --mapping "$TMP/stop.yaml" --format jsonl
frames "$TMP/out" >"$TMP/f2"
[[ $(at 120 "$TMP/f2") == "120 255 128 1" ]] || fail "no drive before the tap"
awk '$1 >= 160 && ($4 != 0 || $2 != 128) { exit 1 }' "$TMP/f2" || fail "a tapped stop did not latch: $(tr '\n' ';' <"$TMP/f2")"

# 3. The stop outlives a link lost and regained, a reload and a suspend, and
# the deadman released and pressed again; the reset chord ends it.
cat >"$TMP/outlives.events" <<'E'
0    connect     pad
40   button      leftshoulder 1
121  button      guide 1
122  button      guide 0
200  link        down
240  link        up
300  reload
400  suspend
500  resume
600  button      leftshoulder 0
640  button      leftshoulder 1
700  button      leftshoulder 0
720  button      back 1
720  button      start 1
2800 button      back 0
2800 button      start 0
2840 button      leftshoulder 1
2900 axis        lefty -32768
3000 end
E
expect_exit 0 "$BIN" replay "$TMP/outlives.events" --mapping "$TMP/stop.yaml" --format jsonl
frames "$TMP/out" >"$TMP/f3"
awk '$1 >= 160 && $1 < 2840 && $4 != 0 { exit 1 }' "$TMP/f3" || fail "the stop did not outlive link, reload, suspend: $(tr '\n' ';' <"$TMP/f3")"
[[ $(at 2920 "$TMP/f3") == "2920 255 128 1" ]] || fail "no drive once reset and pressed afresh: $(tr '\n' ';' <"$TMP/f3")"

# 4. Three-position trigger: past the panic point off at once and latched
# until fully released; releasing from a squeeze through the middle never
# enables; a fresh squeeze to the middle does.
printf 'robot: HD1\nextends: %s\ndeadman: lefttrigger\ndeadman_panic: 0.9\n' "$core" >"$TMP/panic.yaml"
cat >"$TMP/panic.events" <<'E'
0    connect     pad
40   axis        lefttrigger 22000
60   axis        lefty -32768
150  axis        lefttrigger 32767
250  axis        lefttrigger 22000
350  axis        lefttrigger 5000
450  axis        lefttrigger 1000
500  axis        lefty 0
550  axis        lefttrigger 22000
600  axis        lefty -32768
700  end
E
expect_exit 0 "$BIN" replay "$TMP/panic.events" --mapping "$TMP/panic.yaml" --format jsonl
frames "$TMP/out" >"$TMP/f4"
[[ $(at 120 "$TMP/f4") == "120 255 128 1" ]] || fail "the middle position does not drive: $(tr '\n' ';' <"$TMP/f4")"
awk '$1 >= 160 && $1 < 560 && $4 != 0 { exit 1 }' "$TMP/f4" || fail "the panic squeeze did not latch: $(tr '\n' ';' <"$TMP/f4")"
[[ $(at 640 "$TMP/f4") == "640 255 128 1" ]] || fail "a fresh squeeze after a full release does not drive: $(tr '\n' ';' <"$TMP/f4")"
# Without the key, the same squeeze keeps driving (today's behaviour).
printf 'robot: HD1\nextends: %s\ndeadman: lefttrigger\n' "$core" >"$TMP/nopanic.yaml"
expect_exit 0 "$BIN" replay "$TMP/panic.events" --mapping "$TMP/nopanic.yaml" --format jsonl
frames "$TMP/out" >"$TMP/f4b"
[[ $(at 200 "$TMP/f4b") == "200 255 128 1" ]] || fail "without deadman_panic a full squeeze should drive: $(tr '\n' ';' <"$TMP/f4b")"

# 5. The enable timeout fires at exactly its time: the last input change is
# seen at frame 80, so with 2 s the frame at 2080 is the first neutral one.
printf 'robot: HD1\nextends: %s\nenable_timeout: 2\n' "$core" >"$TMP/timeout.yaml"
cat >"$TMP/timeout.events" <<'E'
0    connect     pad
40   button      leftshoulder 1
60   axis        lefty -32768
2400 button      leftshoulder 0
2440 axis        lefty 0
2480 button      leftshoulder 1
2520 axis        lefty -32768
2600 end
E
expect_exit 0 "$BIN" replay "$TMP/timeout.events" --mapping "$TMP/timeout.yaml" --format jsonl
frames "$TMP/out" >"$TMP/f5"
[[ $(at 2040 "$TMP/f5") == "2040 255 128 1" ]] || fail "timed out early: $(at 2040 "$TMP/f5")"
[[ $(at 2080 "$TMP/f5") == "2080 128 128 0" ]] || fail "not timed out at 2080: $(at 2080 "$TMP/f5")"
awk '$1 >= 2080 && $1 < 2480 && $4 != 0 { exit 1 }' "$TMP/f5" || fail "enabled again without a fresh press"
[[ $(at 2560 "$TMP/f5") == "2560 255 128 1" ]] || fail "a fresh press does not enable again: $(tr '\n' ';' <"$TMP/f5" | tail -c 300)"
# A stick that keeps moving keeps it enabled.
{ printf '0 connect pad\n40 button leftshoulder 1\n'
  for t in $(seq 100 500 3100); do printf '%d axis lefty %d\n' "$t" $(( (t / 500) % 2 ? -20000 : -30000 )); done
  printf '3200 end\n'; } >"$TMP/busy.events"
expect_exit 0 "$BIN" replay "$TMP/busy.events" --mapping "$TMP/timeout.yaml" --format jsonl
frames "$TMP/out" >"$TMP/f6"
awk '$1 >= 120 && $4 != 1 { exit 1 }' "$TMP/f6" || fail "timed out while the stick moved"

# 6. The keys' errors, at their lines.
printf 'robot: HD1\nextends: %s\nestop: dpup\n' "$core" >"$TMP/bad1.yaml"
expect_exit 2 "$BIN" check "$TMP/bad1.yaml"
grep -q "bad1.yaml:3:8: error: the stop button 'dpup' is already bound" "$TMP/err" || fail "estop bound twice: $(cat "$TMP/err")"
printf 'robot: HD1\nextends: %s\ndeadman_panic: 0.9\n' "$core" >"$TMP/bad2.yaml"
expect_exit 2 "$BIN" check "$TMP/bad2.yaml"
grep -q "bad2.yaml:3:16: error: deadman_panic needs a trigger deadman" "$TMP/err" || fail "panic with a button deadman: $(cat "$TMP/err")"
printf 'robot: HD1\nextends: %s\nenable_timeout: 0.5\n' "$core" >"$TMP/bad3.yaml"
expect_exit 2 "$BIN" check "$TMP/bad3.yaml"
grep -q "bad3.yaml:3:17: error: enable_timeout 0.5 is out of range" "$TMP/err" || fail "timeout out of range: $(cat "$TMP/err")"
printf 'robot: HD1\nextends: %s\nestop: hat9left\n' "$core" >"$TMP/bad4.yaml"
expect_exit 2 "$BIN" check "$TMP/bad4.yaml"
grep -q "bad4.yaml:3:8: error: estop 'hat9left' is on a hat a controller may not have" "$TMP/err" ||
  fail "a stop on a hat the pad cannot have: $(cat "$TMP/err")"
printf 'robot: HD1\nextends: %s\nstop_reset_hold: 12\n' "$core" >"$TMP/bad5.yaml"
expect_exit 2 "$BIN" check "$TMP/bad5.yaml"
grep -q "bad5.yaml:3:18: error: stop_reset_hold 12 is out of range 1..10" "$TMP/err" || fail "reset hold out of range: $(cat "$TMP/err")"
printf 'robot: HD1\nextends: %s\nestop: guide\nstop_reset: [guide, start]\n' "$core" >"$TMP/bad6.yaml"
expect_exit 2 "$BIN" check "$TMP/bad6.yaml"
grep -q "bad6.yaml:4:14: error: 'guide' is the stop button (line 3): a stop button only ever stops" "$TMP/err" ||
  fail "a reset on the stop button: $(cat "$TMP/err")"
finish
