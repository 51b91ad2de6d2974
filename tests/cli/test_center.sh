# `center:` only trims where drive and pivot rest while enabled, within
# 120..136 (docs/mapping.md). Neutral is the protocol's (its safety rules):
# drive and pivot are 128 in every neutral frame, whatever a mapping says.
source "$(dirname "$0")/lib.sh"
export XDG_CONFIG_HOME="$TMP/xdg"  # the user mapping below, and nothing else, is found by --robot
trim="$DATA/mappings/trim.yaml"    # core.yaml with center: 124
core="$DATA/mappings/core.yaml"
script="$DATA/replay/center_trim.events"
hd1=$(cd "$DATA/../../mappings" && pwd)/hd1.yaml

# replay: not-enabled frames carry 128/128; enabled at rest, the trim.
expect_exit 0 "$BIN" replay "$script" --mapping "$trim" --format jsonl
python3 - "$TMP/out" <<'PY' || fail "trimmed replay: $(cat "$TMP/out")"
import json, sys
frames = [json.loads(l) for l in open(sys.argv[1])]
neutral = [f for f in frames if f["signals"]["safety"] == 0]
assert [f["t"] for f in neutral] == [0, 240, 280], [f["t"] for f in neutral]
for f in neutral:
    assert (f["signals"]["drive"], f["signals"]["pivot"]) == (128, 128), f
at_rest = {f["t"]: (f["signals"]["drive"], f["signals"]["pivot"]) for f in frames if f["signals"]["safety"] == 1}
assert at_rest[40] == (124, 124) and at_rest[200] == (124, 124), at_rest
assert at_rest[80] == (255, 124) and at_rest[120] == (0, 124), at_rest
PY
# A trimmed mapping's neutral frames are byte for byte those of an untrimmed one.
expect_exit 0 "$BIN" replay "$script" --mapping "$trim"
grep -E '^(0|240|280) ' "$TMP/out" >"$TMP/trim_neutral"
expect_exit 0 "$BIN" replay "$script" --mapping "$core"
grep -E '^(0|240|280) ' "$TMP/out" >"$TMP/core_neutral"
[[ $(wc -l <"$TMP/trim_neutral") -eq 3 ]] && cmp -s "$TMP/trim_neutral" "$TMP/core_neutral" ||
  fail "neutral frames differ: $(cat "$TMP/trim_neutral") vs $(cat "$TMP/core_neutral")"

# check says what a trim does; 'FILE: ok' stays as it was without one.
printf 'deadman: a\ncenter: 136\n' >"$TMP/base.yaml"
expect_exit 0 "$BIN" check "$trim" "$core" "$TMP/base.yaml"
grep -Fxq "$trim: ok (center 124: drive and pivot rest at 124 while enabled; neutral frames carry 128)" "$TMP/out" ||
  fail "trim line: $(cat "$TMP/out")"
grep -Fxq "$core: ok" "$TMP/out" || fail "core line (center: 128): $(cat "$TMP/out")"
grep -Fxq "$TMP/base.yaml: ok (a base mapping: no robot; center 136: drive and pivot rest at 136 while enabled; neutral frames carry 128)" "$TMP/out" ||
  fail "base line: $(cat "$TMP/out")"
[[ -s "$TMP/err" ]] && fail "stderr on success: $(cat "$TMP/err")"

# Outside the band: a load error at FILE:LINE:COL, exit 2, from check, replay
# and run, also for the user's hd1.yaml that --robot hd1 picks up.
user="$XDG_CONFIG_HOME/andros-bridge/mappings"
mkdir -p "$user"
for c in 0 255 119 137; do
  printf 'robot: HD1\nextends: %s\ncenter: %s\n' "$hd1" "$c" >"$user/hd1.yaml"
  want="^$user/hd1.yaml:3:9: error: center $c is out of range 120..136 \(it only trims drive and pivot's rest while enabled; neutral frames carry 128\)$"
  expect_exit 2 "$BIN" check "$user/hd1.yaml"
  expect_one_line_stderr
  expect_stderr_matches "$want"
  expect_exit 2 "$BIN" replay "$script" --robot hd1
  expect_one_line_stderr
  expect_stderr_matches "$want"
  expect_exit 2 "$BIN" run --robot hd1 --port "$TMP/no-such-port" --input "$script"
  expect_stderr_matches "$want"
  [[ -e "$TMP/no-such-port" ]] && fail "run with center $c created the port"
done
# The band's ends load, and --robot hd1 uses the user's trimmed file.
for c in 120 136; do
  printf 'robot: HD1\nextends: %s\ncenter: %s\n' "$hd1" "$c" >"$user/hd1.yaml"
  expect_exit 0 "$BIN" replay "$script" --robot hd1 --format jsonl
  grep -q "\"drive\":$c," "$TMP/out" || fail "center $c: no frame at rest at $c"
  grep -q '"safety":0,' "$TMP/out" || fail "center $c: no neutral frame"
done
finish
