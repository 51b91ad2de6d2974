# Small things on the command line (issue 19, finding 11): the vehicles'
# names as robots, an unknown command named, --controller refused with an
# event script, a controller database too large refused at its line.
source "$(dirname "$0")/lib.sh"
LIVE=$DATA/live
export XDG_CONFIG_HOME=$TMP/xdg

# --robot takes the vehicle's name (docs/robots.md), in any case.
for robot in HD-1 hd-1 V-A1 va1 Wolverine; do
  expect_exit 0 "$BIN" replay --robot "$robot" "$LIVE/drive.events" --output "$TMP/frames"
done
expect_exit 0 "$BIN" replay --robot hd-1 "$LIVE/drive.events" --output "$TMP/alias"
expect_exit 0 "$BIN" replay --robot hd1 "$LIVE/drive.events" --output "$TMP/type"
cmp -s "$TMP/alias" "$TMP/type" || fail "--robot hd-1 and --robot hd1 gave different frames"
expect_exit 0 "$BIN" sheet --robot HD-1 --format text
grep -q "HD1" "$TMP/out" || fail "sheet --robot HD-1 does not say HD1: $(head -3 "$TMP/out")"
printf 'robot: V-A1\nextends: %s\n' "$DATA/../../mappings/common.yaml" >"$TMP/va1.yaml"
expect_exit 0 "$BIN" check "$TMP/va1.yaml"
expect_exit 2 "$BIN" replay --robot HD-2 "$LIVE/drive.events" --output "$TMP/frames"
expect_stderr_matches "unknown robot 'HD-2'"

# A word that is no command is named, and the commands listed.
expect_exit 2 "$BIN" nonsense
expect_one_line_stderr
expect_stderr_matches "^andros-bridge: error: unknown command 'nonsense' \(one of: frame, replay, check, run, .*inputs, verify, sessions, plot, export\)"
grep -q "help-data" "$TMP/err" && fail "the hidden help-data is listed: $(cat "$TMP/err")"
expect_exit 2 "$BIN"
expect_stderr_matches "^andros-bridge: error: no command given \(one of: frame, replay"
expect_exit 0 "$BIN" --version
expect_exit 0 "$BIN" --help

# --controller chooses a live pad: with an event script it is an error, not ignored.
expect_exit 2 "$BIN" run --port sim --input "$LIVE/drive.events" --controller 0
expect_one_line_stderr
expect_stderr_matches "^--controller: error: chooses a live controller, but the input is the event script '.*drive.events'"

# A controller database past 5,000 mappings for this platform is refused at
# the line that goes past (SDL's cost grows with the square of the count);
# lines for other platforms do not count.
python3 - "$TMP" <<'PY'
import sys
d = sys.argv[1]
def line(i, platform):
    return f"03000000{i:08x}0000{i:012x},P{i},a:b0,b:b1,leftx:a0,lefty:a1,platform:{platform},\n"
with open(f"{d}/big.txt", "w") as f:
    f.write("# too many\n")
    f.writelines(line(i, "Linux") for i in range(5001))
with open(f"{d}/fits.txt", "w") as f:
    f.writelines(line(i, "Linux") for i in range(5000))
    f.writelines(line(i, "Windows") for i in range(20000))
PY
export SDL_VIDEODRIVER=dummy SDL_AUDIODRIVER=dummy
expect_exit 2 "$BIN" controllers --controller-db "$TMP/big.txt"
expect_stderr_matches "^$TMP/big.txt:5002:1: error: more than 5000 controller mappings for Linux"
expect_exit 0 "$BIN" controllers --controller-db "$TMP/fits.txt"
finish
