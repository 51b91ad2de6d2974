# `plot`: the shipped plot of the demo drive is current; a script's and a
# session's plot hold what they must; --from/--to; the errors.
source "$(dirname "$0")/lib.sh"
root="$DATA/../.."
export XDG_CONFIG_HOME=$TMP/xdg

# The shipped plots are what the demo drives give today.
bash "$root/scripts/make_plots.sh" "$BIN" "$TMP/plots" || fail "scripts/make_plots.sh failed"
for plot in drive supervised; do
  cmp -s "$TMP/plots/$plot.svg" "$root/docs/plots/$plot.svg" ||
    fail "docs/plots/$plot.svg is stale (or missing): regenerate with scripts/make_plots.sh $BIN"
done
extra=$(cd "$root/docs/plots" && ls | grep -vxE '(drive|supervised)\.svg')
[[ -z $extra ]] || fail "docs/plots/ holds files make_plots.sh does not make: $extra"

# svg_has SVG TEXT...: parses as XML and each TEXT is in the page's text.
svg_has() {
  python3 - "$@" <<'PY' || fail "$1: not well-formed, or a label is missing"
import sys, xml.etree.ElementTree as ET
root = ET.parse(sys.argv[1]).getroot()
text = "\n".join(root.itertext())
missing = [t for t in sys.argv[2:] if t not in text]
if missing: sys.exit(f"{sys.argv[1]}: missing {missing}")
PY
}
shipped=$root/docs/plots/drive.svg
svg_has "$shipped" "HD1 drive, mapping hd1.yaml" "25 Hz, code 01, weapons disabled" "replay of drive.events" \
  "not enabled" "enabled" "drive" "pivot" "time (s)" "front_art_up" "pt_right" \
  "controller (operator)" "link up" "deadman held" "stop button (operator)" "arming input held"
# Its legend names the colours it uses, and only those: this drive was never stopped, lost or shut down.
grep -Eq '>(stopped by the [a-z ]*|no link|no controller|shutting down|reloading)<' "$shipped" &&
  fail "the demo drive's legend names a state it never was in"
grep -q 'width="297mm" height="210mm"' "$shipped" || fail "not an A4 landscape page"
grep -Eq '>(weapon_[0-9]|shotgun|laser|enable_key)<' "$shipped" && fail "the demo drive (weapons disabled) shows a weapon"

# The supervised demo: each colour of its states named, who stopped and who
# reset, the weapons layer in the weapons red (the sheet's), every lane.
supervised=$root/docs/plots/supervised.svg
svg_has "$supervised" "WEAPONS ENABLED" "no link" "no controller" "not enabled" "enabled" \
  "stopped by the operator" "stopped by the supervisor" "reset by the supervisor" "reset by the operator" \
  "weapons layer" "controller (operator)" "controller (supervisor)" "link up" "deadman held" \
  "stop button (operator)" "stop button (supervisor)" "consent (supervisor)" "arming input held"
grep -q 'height="14.0" fill="#b71c1c"' "$supervised" || fail "the weapons layer is not in the weapons red"
grep -q 'fill="#b71c1c"' <("$BIN" sheet --mapping "$root/mappings/examples/supervisor.yaml" --format svg) ||
  fail "the sheet's weapons red is not the plot's"

# Weapons fired: their rows in the weapons red.
expect_exit 0 "$BIN" plot "$DATA/replay/weapons_on_armed.events" --weapons --mapping "$DATA/mappings/core.yaml"
grep -q 'fill="#b71c1c" font-weight="bold">weapon_1<' "$TMP/out" || fail "weapon_1 is not named in red"
grep -q 'height="9.0" fill="#b71c1c"' "$TMP/out" || fail "weapon_1's bar is not red"
# Layers: the layer strip names them.
expect_exit 0 "$BIN" plot "$DATA/replay/layer_entered_stick_held.events" --mapping "$DATA/mappings/layers.yaml"
cp "$TMP/out" "$TMP/layers.svg"
svg_has "$TMP/layers.svg" "(blank: base layer)"

# --from/--to narrow the time axis.
expect_exit 0 "$BIN" plot "$root/demos/drive.events" --mapping "$root/mappings/hd1.yaml" --from 2 --to 4.5
cp "$TMP/out" "$TMP/part.svg"
svg_has "$TMP/part.svg" "2 to 4.5 s, 63 ticks"

# A session's plot: its title, and what was recorded.
run_cmd "$BIN" run --robot hd1 --input "$root/demos/drive.events"
[[ $code -eq 0 ]] || fail "run exited $code"
session=$(ls "$XDG_STATE_HOME"/andros-bridge/*.andros-session | tail -1)
# (to 12 s: the run ends on neutral frames past the script's end; replay does not)
expect_exit 0 "$BIN" plot "$session" --to 12 --output "$TMP/session.svg"
svg_has "$TMP/session.svg" "HD1 drive, mapping hd1.yaml" "input $root/demos/drive.events" "session $(basename "$session")" \
  "deadman held" "link up" "controller (operator)"
# The plot draws what the session recorded (a real-time run on a busy machine
# may skip a tick or meet a busy link, which the replay of the script on its
# virtual clock never does: compared with the shipped plot, the verdict would
# depend on the machine's load), and those frames are the loop's own: replay
# runs the session again on the virtual clock, its inputs and the link's
# answers at the ticks the run met them.
python3 "$(dirname "$0")/check_plot.py" "$BIN" "$session" "$TMP/session.svg" 0 12 guide >"$TMP/check" 2>&1 ||
  fail "the session's plot: $(cat "$TMP/check")"
sent=$(sed -n 's/^[0-9]* end [0-9]* tick [0-9]* frames \([0-9]*\) .*/\1/p' "$session")
expect_exit 0 "$BIN" replay "$session"
grep -qE "^$sent frames identical; [0-9]+ records .* made again the same$" "$TMP/out" || fail "replay: $(cat "$TMP/out")"

# A session that is not intact is drawn, and says so.
python3 -c 'import sys; p=sys.argv[1]; l=open(p).read().split("\n"); l[7],l[8]=l[8],l[7]; open(sys.argv[2],"w").write("\n".join(l))' \
  "$session" "$TMP/swapped.andros-session"
expect_exit 0 "$BIN" plot "$TMP/swapped.andros-session" --output "$TMP/swapped.svg"
svg_has "$TMP/swapped.svg" "NOT INTACT: record 7 reordered"

# Errors: one line, exit 2 for bad input, 1 when the file cannot be written.
expect_exit 2 "$BIN" plot "$TMP/none.events"
expect_one_line_stderr
expect_exit 2 "$BIN" plot "$root/demos/drive.events" --from x
expect_stderr_matches "^--from: error: expected seconds"
expect_exit 2 "$BIN" plot "$root/demos/drive.events" --from 5 --to 4
expect_stderr_matches "^--to: error: must be later than --from"
expect_exit 2 "$BIN" plot "$session" --robot hd1
expect_stderr_matches "^--robot: error: not for a session"
expect_exit 1 "$BIN" plot "$root/demos/drive.events" --output "$TMP/no/such/dir/x.svg"
expect_stderr_matches "cannot open '.*' for writing"
# --output onto a link to a device that fails: the write fails, nothing is removed.
ln -s /dev/full "$TMP/full.svg"
expect_exit 1 "$BIN" plot "$root/demos/drive.events" --output "$TMP/full.svg"
expect_stderr_matches "No space left on device"
[[ -L $TMP/full.svg && -c /dev/full ]] || fail "a failed plot --output removed the link or the device"
expect_exit 0 "$BIN" plot --help
grep -q "A4" "$TMP/out" || fail "--help does not say what the page fits"

finish
