# `sheet`: the shipped cheat sheets are current, well-formed and complete; the
# options and their errors.
source "$(dirname "$0")/lib.sh"

root="$DATA/../.."
shipped="$root/docs/sheets"

# Every shipped sheet is what the mapping gives today.
bash "$root/scripts/make_sheets.sh" "$BIN" "$TMP/sheets" || fail "scripts/make_sheets.sh failed"
for robot in f6a va1 wolverine hd1 prowler rav rons; do
  for ext in svg txt; do
    [[ -f "$TMP/sheets/$robot.$ext" ]] || fail "make_sheets.sh wrote no $robot.$ext"
    cmp -s "$TMP/sheets/$robot.$ext" "$shipped/$robot.$ext" ||
      fail "docs/sheets/$robot.$ext is stale (or missing): regenerate with scripts/make_sheets.sh $BIN"
  done
done
extra=$(cd "$shipped" && ls | grep -Evx '(f6a|va1|wolverine|hd1|prowler|rav|rons)\.(svg|txt)')
[[ -z $extra ]] || fail "docs/sheets/ holds files make_sheets.sh does not make: $extra"

# well_formed SVG [TEXT...]: parses as XML and each TEXT is in the page's text.
well_formed() {
  python3 - "$@" <<'PY' || fail "$1: not well-formed, or a label is missing"
import sys, xml.etree.ElementTree as ET
root = ET.parse(sys.argv[1]).getroot()
text = "".join(root.itertext())
missing = [t for t in sys.argv[2:] if t not in text]
if missing: sys.exit(f"{sys.argv[1]}: missing {missing}")
PY
}
for robot in f6a va1 wolverine hd1 prowler rav rons; do
  well_formed "$shipped/$robot.svg" "DEADMAN" "ARM LAYER" "CAMERA LAYER" "WEAPONS LAYER" "fire weapon 1" "laser" \
    "zoom out" "reel in tether" "drive forward/back" "deadzone 0.1, expo 0.3"
done
grep -q "^HD1 cheat sheet (hd1.yaml)" "$shipped/hd1.txt" || fail "hd1.txt header"
wide=$(awk 'length > 80' "$shipped/hd1.txt")
[[ -z $wide ]] || fail "hd1.txt is wider than a terminal's 80 columns: $wide"

# Every binding kind, in both formats: each label of the text tables is in the SVG.
kinds="$DATA/sheet/kinds.yaml"
expect_exit 0 "$BIN" sheet --mapping "$kinds" --format text
cp "$TMP/out" "$TMP/kinds.txt"
for line in \
  "  LT                     DEADMAN  hold to enable motion (past half way)" \
  "  LB                     LAYER    hold: arm layer" \
  "  RB                     LAYER    weapons layer on/off" \
  "  X                      TOGGLE   tool on" \
  "  B                      KNOB     light brighter (64/s)" \
  "  Start                  SELECTOR speed selector: next" \
  "  Back                   SELECTOR speed selector: previous" \
  "  D-pad up                        front articulators up" \
  "  RT                              pay out tether" \
  "  right stick up/down             up: rear articulators up (past 30%)" \
  "  right stick left/right          left: pan left, right: pan right" \
  "  left stick up/down              drive forward/back (up = forward)" \
  "  RT                              arm speed faster/slower (analog 0..255)" \
  "  Y                      WEAPON   fire weapon 1 (needs --weapons + left stick click)" \
  "  left stick click       ARMING   hold to arm weapons" \
  "  RB                     LAYER    weapons layer off (back to base)"; do
  grep -qxF -- "$line" "$TMP/kinds.txt" || fail "text sheet lacks '$line'"
done
expect_exit 0 "$BIN" sheet --mapping "$kinds" --output "$TMP/kinds.svg"
[[ -s "$TMP/out" ]] && fail "--output also wrote to stdout"
mapfile -t labels < <(sed -n '/^NOTES$/q; s/^  .\{32\}\(.*\)$/\1/p' "$TMP/kinds.txt" | sed 's/ (.*//; s/ \[base\]$//' | grep -vx function | sort -u)
((${#labels[@]} > 10)) || fail "too few labels read from the text sheet: ${#labels[*]}"
well_formed "$TMP/kinds.svg" "${labels[@]}"
expect_exit 0 "$BIN" sheet --mapping "$kinds"
cmp -s "$TMP/out" "$TMP/kinds.svg" || fail "svg on stdout differs from --output"

# A plain joystick: a list instead of the pad.
expect_exit 0 "$BIN" sheet --mapping "$DATA/mappings/joystick.yaml" --output "$TMP/joy.svg"
well_formed "$TMP/joy.svg" "button 4" "hat 0 up" "axis 1" "DEADMAN"
grep -q "<ellipse" "$TMP/joy.svg" && fail "a joystick's sheet draws the pad"

# --robot finds the shipped file (no user mapping in the way); HD1 is the default.
export XDG_CONFIG_HOME="$TMP/xdg"
expect_exit 0 "$BIN" sheet --robot hd1 --format text
cmp -s "$TMP/out" "$shipped/hd1.txt" || fail "--robot hd1 differs from the shipped sheet"
expect_exit 0 "$BIN" sheet --format text
cmp -s "$TMP/out" "$shipped/hd1.txt" || fail "the default robot is not HD1"

# Errors: one line, exit 2 for bad input, 1 when the file cannot be written.
expect_exit 2 "$BIN" sheet --robot hd1 --mapping "$kinds"
expect_stderr_matches "give --robot or --mapping, not both"
expect_exit 2 "$BIN" sheet --robot hd1 --format png
expect_stderr_matches "^--format: error: unknown format 'png' \(svg or text\)$"
expect_one_line_stderr
expect_exit 2 "$BIN" sheet --robot nosuch
expect_one_line_stderr
printf 'robot: HD1\ndeadman: a\nbindings:\n  - signal: nosuch\n    button: b\n' >"$TMP/bad.yaml"
expect_exit 2 "$BIN" sheet --mapping "$TMP/bad.yaml" --output "$TMP/bad.svg"
expect_stderr_matches "bad.yaml:4:13: error: unknown signal"
[[ -e "$TMP/bad.svg" ]] && fail "--output created for a bad mapping"
expect_exit 1 "$BIN" sheet --robot hd1 --output "$TMP/no/such/dir/x.svg"
expect_stderr_matches "cannot open '$TMP/no/such/dir/x.svg' for writing: No such file or directory$"
expect_exit 0 "$BIN" sheet --help
grep -q "A4 or Letter" "$TMP/out" || fail "--help does not say what the page fits"

finish
