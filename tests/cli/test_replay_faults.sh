# `replay` with fault events (docs/event-scripts.md, "Fault events"): the run
# loop answers a link lost, regained or taken, a suspend, a reload and a stop
# as it answers the real thing, and the frames the vehicle receives prove it.
# Issue 15's motion cases: a link that comes back, a port taken over, and a
# mapping's center, which no neutral frame follows.
source "$(dirname "$0")/lib.sh"
export XDG_CONFIG_HOME="$TMP/no-config"
core="$DATA/mappings/core.yaml"


# 1. Held deadman and stick through a link loss: nothing moves on the link that
# comes back until the deadman is released and pressed afresh.
cat >"$TMP/regained.events" <<'E'
0    connect     pad
40   button      leftshoulder 1
120  axis        lefty -32768
200  link        down
400  link        up
600  button      leftshoulder 0
640  axis        lefty 0
680  button      leftshoulder 1
760  axis        lefty -32768
840  end
E
expect_exit 0 "$BIN" replay "$TMP/regained.events" --mapping "$core" --format jsonl
frames "$TMP/out" >"$TMP/f"
grep -q '^160 255 128 1$' "$TMP/f" || fail "no full drive before the loss: $(tr '\n' ';' <"$TMP/f")"
# Nothing delivered while the link is down; the first frame after it is neutral.
awk '$1 > 160 && $1 < 400 { exit 1 }' "$TMP/f" || fail "frames delivered while the link was down"
[[ $(awk '$1 == 400' "$TMP/f") == "400 128 128 0" ]] || fail "first frame on the regained link: $(awk '$1 == 400' "$TMP/f")"
awk '$1 >= 400 && $1 < 680 && ($2 != 128 || $4 != 0) { exit 1 }' "$TMP/f" ||
  fail "motion on the regained link before a fresh press: $(tr '\n' ';' <"$TMP/f")"
[[ $(awk '$1 == 800' "$TMP/f") == "800 255 128 1" ]] || fail "no drive after the fresh press: $(tr '\n' ';' <"$TMP/f")"

# 2. The port taken by another program, then ours again: a new link, the same rule.
sed 's/link        down/link        taken/' "$TMP/regained.events" >"$TMP/taken.events"
expect_exit 0 "$BIN" replay "$TMP/taken.events" --mapping "$core" --format jsonl
frames "$TMP/out" >"$TMP/f2"
cmp -s "$TMP/f" "$TMP/f2" || fail "a take-over is answered unlike a loss"

# 3. A mapping's center: a trim while enabled; every neutral frame (not enabled,
# link regained, reload, suspend, stop) carries 128 whatever it says.
printf 'robot: HD1\nextends: %s\ncenter: 124\n' "$core" >"$TMP/trim.yaml"
cat >"$TMP/trim.events" <<'E'
0    connect     pad
40   button      leftshoulder 1
120  link        down
200  link        up
280  reload
440  suspend
600  resume
680  stop
E
expect_exit 0 "$BIN" replay "$TMP/trim.events" --mapping "$TMP/trim.yaml" --format jsonl
frames "$TMP/out" >"$TMP/f3"
[[ $(awk '$1 == 80' "$TMP/f3") == "80 124 124 1" ]] || fail "enabled rest is not the trim: $(tr '\n' ';' <"$TMP/f3")"
awk '$4 == 0 && ($2 != 128 || $3 != 128) { exit 1 }' "$TMP/f3" ||
  fail "a neutral frame follows center: $(tr '\n' ';' <"$TMP/f3")"
# Suspend: 440, 480, 520 then nothing until the resume; stop: 3 neutral frames and the end.
[[ $(awk '$1 > 520 && $1 < 600' "$TMP/f3" | wc -l) -eq 0 ]] || fail "frames while suspended"
[[ $(tail -n 3 "$TMP/f3" | awk '{print $1}' | tr '\n' ' ') == "680 720 760 " ]] || fail "stop's tail: $(tail -n 4 "$TMP/f3" | tr '\n' ';')"

# 4. reload MAPPING: a bad one keeps the old mapping; either way a fresh press first.
printf '0 connect\n40 button leftshoulder 1\n80 reload %s\n240 axis lefty -32768\n320 end\n' "$TMP/missing.yaml" >"$TMP/bad_reload.events"
expect_exit 0 "$BIN" replay "$TMP/bad_reload.events" --mapping "$core" --format jsonl
frames "$TMP/out" >"$TMP/f4"
awk '$1 >= 80 && $4 != 0 { exit 1 }' "$TMP/f4" || fail "enabled after a reload without a fresh press"
printf 'robot: HD1\nextends: %s\n' "$core" >"$TMP/other.yaml"
printf '0 connect\n40 button leftshoulder 1\n80 reload other.yaml\n200 button leftshoulder 0\n240 button leftshoulder 1\n320 axis lefty -32768\n400 end\n' >"$TMP/good_reload.events"
expect_exit 0 "$BIN" replay "$TMP/good_reload.events" --mapping "$core" --format jsonl
frames "$TMP/out" >"$TMP/f5"
[[ $(awk '$1 == 400' "$TMP/f5") == "400 255 128 1" ]] || fail "the reloaded mapping (relative to the script) does not drive: $(tr '\n' ';' <"$TMP/f5")"

# 5. A bad fault event is an error at its place.
printf '0 connect\n10 link sideways\n' >"$TMP/bad.events"
expect_exit 2 "$BIN" replay "$TMP/bad.events" --mapping "$core"
expect_stderr_matches "bad.events:2:9: error: unknown link event 'sideways' \(expected down, up, taken, stalled or reading\)"

finish
