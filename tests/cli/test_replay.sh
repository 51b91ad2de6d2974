# `replay` as a user runs it: formats, options, determinism and exit codes.
source "$(dirname "$0")/lib.sh"
# --robot must find the shipped files, whatever the user running the tests keeps in ~/.config.
export XDG_CONFIG_HOME="$TMP/no-config"

core="$DATA/mappings/core.yaml"
pivot="$DATA/replay/pivot_deadzone_expo.events"

# Hand-built data bytes (see switchbox-protocol: fixed bits 2.3 2.4 3.5 5.4 5.7,
# byte 11 = code 01, byte 14 = 0xCC, byte 15 = 0x02):
#   neutral:             byte0 00, pivot 0x80, drive 0x80
#   enabled, pivot 162:  byte0 06 (safety + drive_brake), pivot 0xA2
neutral=$("$BIN" frame encode 00001820009080800000000100 00CC02)
pivot162=$("$BIN" frame encode 06001820009 0A280000000010000CC02)

expect_exit 0 "$BIN" replay "$pivot" --mapping "$core"
[[ $(wc -l <"$TMP/out") -eq 8 ]] || fail "pivot replay: $(wc -l <"$TMP/out") frames, expected 8 (0..280)"
[[ $(sed -n 1p "$TMP/out") == "0 $neutral" ]] || fail "first frame: $(sed -n 1p "$TMP/out")"
[[ $(sed -n 3p "$TMP/out") == "80 $pivot162" ]] || fail "pivot 162 frame: $(sed -n 3p "$TMP/out")"
cp "$TMP/out" "$TMP/hex1"

# Same input, same bytes; --output writes exactly what stdout would.
expect_exit 0 "$BIN" replay "$pivot" --mapping "$core" --output "$TMP/hex2"
cmp -s "$TMP/hex1" "$TMP/hex2" || fail "--output differs from stdout"
run_cmd "$BIN" replay - --mapping "$core" <"$pivot"
cmp -s "$TMP/hex1" "$TMP/out" || fail "replay from stdin differs"

# raw: 36 bytes a frame, and the reference decoder finds them all valid.
expect_exit 0 "$BIN" replay "$pivot" --mapping "$core" --format raw --output "$TMP/raw"
[[ $(stat -c %s "$TMP/raw") -eq $((8 * 36)) ]] || fail "raw size $(stat -c %s "$TMP/raw")"
expect_exit 0 "$BIN" frame decode "$TMP/raw"
expect_stderr_matches '^frames: 8, valid: 8, '

# jsonl: t, frame, signals.
expect_exit 0 "$BIN" replay "$pivot" --mapping "$core" --format jsonl --code 3c
python3 - "$TMP/out" <<'PY' || fail "jsonl content"
import json, sys
lines = [json.loads(l) for l in open(sys.argv[1])]
assert [l["t"] for l in lines] == [0, 40, 80, 120, 160, 200, 240, 280], [l["t"] for l in lines]
assert list(lines[2]) == ["t", "frame", "signals"]
assert lines[2]["signals"]["pivot"] == 162 and lines[2]["signals"]["safety"] == 1
assert all(l["signals"]["code"] == 0x3C for l in lines)
assert len(lines[2]["frame"]) == 72 and lines[2]["frame"].startswith("F1F1")
PY

# Weapons: off without --weapons, on with it (armed, deadman held).
armed="$DATA/replay/weapons_on_armed.events"
expect_exit 0 "$BIN" replay "$armed" --mapping "$core" --format jsonl
grep -q '"weapon_1":1' "$TMP/out" && fail "weapon_1 sent without --weapons"
expect_exit 0 "$BIN" replay "$armed" --mapping "$core" --format jsonl --weapons
# One frame: b, held when armed, is released and pressed again; after the deadman is pressed
# again, b and the arm (held since) must be released first.
[[ $(grep -c '"weapon_1":1' "$TMP/out") -eq 1 ]] || fail "weapon_1 with --weapons: $(grep -c '"weapon_1":1' "$TMP/out") frames"

# weapon_1 at frame T (0 or 1) in $TMP/out (jsonl).
weapon_at() { python3 -c 'import json, sys
print(next(l["signals"]["weapon_1"] for l in map(json.loads, open(sys.argv[1])) if l["t"] == int(sys.argv[2])))' "$TMP/out" "$1"; }
# A weapon in the base layer of a mapping with no layers (issue 15, case 5): LB at 10, RB at 20,
# b at 30, all in the frame at 40. RB counts; b, pressed in that frame too, waits for a release.
printf 'robot: HD1\ndeadman: leftshoulder\nbindings:\n  - signal: weapon_1\n    button: b\n    arm: rightshoulder\n' >"$TMP/base_weapon.yaml"
printf '0 connect\n10 button leftshoulder 1\n20 button rightshoulder 1\n30 button b 1\n90 button b 0\n130 button b 1\n200 end\n' >"$TMP/base_weapon.events"
expect_exit 0 "$BIN" replay "$TMP/base_weapon.events" --mapping "$TMP/base_weapon.yaml" --format jsonl --weapons
[[ "$(weapon_at 80) $(weapon_at 120) $(weapon_at 160) $(weapon_at 200)" == "0 0 1 1" ]] ||
  fail "base-layer weapon_1 at 80 120 160 200: $(weapon_at 80) $(weapon_at 120) $(weapon_at 160) $(weapon_at 200)"
# A toggled weapons layer (issue 15, case 4) ends with the deadman: with LB pressed again the
# bridge is in the base layer, where b fires nothing, the arm pressed afresh or not.
printf 'robot: HD1\ndeadman: leftshoulder\nlayers:\n  weapons:\n    toggle: y\n    bindings:\n      - signal: weapon_1\n        button: b\n        arm: rightshoulder\n' >"$TMP/toggled.yaml"
printf '0 connect\n10 button leftshoulder 1\n20 button y 1\n25 button y 0\n50 button rightshoulder 1\n90 button b 1\n130 button leftshoulder 0\n170 button leftshoulder 1\n210 button b 0\n210 button rightshoulder 0\n230 button rightshoulder 1\n250 button b 1\n300 end\n' >"$TMP/toggled.events"
expect_exit 0 "$BIN" replay "$TMP/toggled.events" --mapping "$TMP/toggled.yaml" --format jsonl --weapons
[[ "$(weapon_at 120) $(weapon_at 280)" == "1 0" ]] || fail "toggled weapons layer at 120 280: $(weapon_at 120) $(weapon_at 280)"

# Rates: frame times floor(k * 1000 / rate); at most 26.666 Hz (360 bits at 9600 baud).
expect_exit 0 "$BIN" replay "$DATA/replay/rate_24hz.events" --mapping "$core" --rate 24
[[ $(cut -d' ' -f1 "$TMP/out" | tr '\n' ' ') == "0 41 83 125 166 208 " ]] || fail "24 Hz times: $(cut -d' ' -f1 "$TMP/out" | tr '\n' ' ')"
expect_exit 0 "$BIN" replay "$pivot" --mapping "$core" --rate 26.666
for bad in 27 26.667 0 0.5 abc 25.0001 -5; do
  expect_exit 2 "$BIN" replay "$pivot" --mapping "$core" --rate "$bad"
  expect_one_line_stderr
  expect_stderr_matches '^--rate: error: rate'
done

# Every robot type, by any case.
for robot in f6a VA1 Wolverine hd1 PROWLER rav Rons; do
  expect_exit 0 "$BIN" replay "$DATA/standard_session.events" --robot "$robot"
  [[ $(wc -l <"$TMP/out") -eq 14 ]] || fail "--robot $robot: $(wc -l <"$TMP/out") frames"
done
# The default robot is HD1.
expect_exit 0 "$BIN" replay "$DATA/standard_session.events"
cp "$TMP/out" "$TMP/default"
expect_exit 0 "$BIN" replay "$DATA/standard_session.events" --robot HD1
cmp -s "$TMP/default" "$TMP/out" || fail "default robot is not HD1"

# A user's own mapping in $XDG_CONFIG_HOME wins over the shipped one.
mkdir -p "$TMP/xdg/andros-bridge/mappings"
printf 'robot: HD1\ndeadman: leftshoulder\nconstants: {battery: 0x11}\n' >"$TMP/xdg/andros-bridge/mappings/hd1.yaml"
XDG_CONFIG_HOME="$TMP/xdg" run_cmd "$BIN" replay "$pivot" --robot hd1 --format jsonl
grep -q '"battery":17' "$TMP/out" || fail "XDG mapping not used"

# Bad input: exit 2, one line naming the file and position.
expect_exit 2 "$BIN" replay "$pivot" --robot HD9
expect_one_line_stderr
expect_stderr_matches "unknown robot 'HD9'"
expect_exit 2 "$BIN" replay "$pivot" --robot HD1 --mapping "$core"
expect_one_line_stderr
expect_exit 2 "$BIN" replay "$pivot" --mapping "$core" --format csv
expect_stderr_matches "^--format: error: format 'csv'"
expect_exit 2 "$BIN" replay "$pivot" --mapping "$core" --code 1FF
expect_exit 2 "$BIN" replay "$TMP/nothing.events" --mapping "$core"
expect_stderr_matches "nothing.events: error: cannot read the event script: No such file or directory"
# bad_input FILE TEXT REGEX ARGS...: FILE holding TEXT makes `replay ARGS` exit 2 with one line.
bad_input() {
  local file=$1 text=$2 regex=$3; shift 3
  printf "$text" >"$TMP/$file"
  expect_exit 2 "$BIN" replay "$@"
  expect_one_line_stderr
  expect_stderr_matches "$regex"
}
bad_input back.events '0 connect\n10 button leftshoulder 1\n5 button a 1\n' \
  "back.events:3:1: error: time 5 ms goes backwards" "$TMP/back.events" --mapping "$core"
bad_input range.events '0 connect\n10 button start 3\n' \
  "range.events:2:17: error: button value 3 is out of range" "$TMP/range.events" --mapping "$core"
bad_input fixed.yaml 'robot: HD1\ndeadman: leftshoulder\nbindings:\n  - signal: byte5.4\n    button: a\n' \
  "fixed.yaml:4:13: error: byte 5 bit 4 is a fixed validation bit" "$pivot" --mapping "$TMP/fixed.yaml"
expect_exit 2 "$BIN" replay "$pivot" --mapping "$DATA/../../mappings/common.yaml"
expect_stderr_matches "common.yaml: error: missing 'robot'"
expect_exit 2 "$BIN" replay
expect_exit 1 "$BIN" replay "$pivot" --mapping "$core" --output "$TMP/no/such/dir/out"
expect_one_line_stderr

expect_exit 0 "$BIN" replay --help
grep -q -- "--weapons" "$TMP/out" || fail "replay --help"
finish
