# Text from outside on every output (issue 34 items 4 and 5; docs/recording.md,
# "Text from outside, on every output"): a session's file name, its robot and
# layer names, a mapping's file name and layer names, each holding a newline
# and a forged table row, ESC[2J, U+202E, a byte that is not UTF-8, a UTF-8
# lead byte alone, NUL, and spreadsheet formulas. No output holds one raw
# (check_text.py says what would be), every session is listed, a JSON text
# gives the bytes back, a CSV text cell is never a formula.
source "$(dirname "$0")/lib.sh"
tool="$(dirname "$0")/session_tool.py"
check="$(dirname "$0")/check_text.py"
dir=$TMP/rec
mkdir -p "$dir"

# clean FILE WHAT [ALLOWED...]: FILE holds no raw text from outside.
clean() {
  local file=$1 what=$2
  shift 2
  local raw
  raw=$(python3 "$check" "$file" "$@") || fail "$what holds raw text from outside: $raw"
}

forged=$'\n2024-01-01 00:00:00   0:00:01  HD1          226  FIRED    0                        0                 0                         0  intact  forged'
bidi=$'\xe2\x80\xae'
names=("a$forged" $'b\e[2Jcleared' "c${bidi}evil" $'d\xff' $'e\xc3')

# The drive session's header records, then a layer named with every hostile
# string, then the robot's name edited to hold them too (JSON escapes: the
# file stays one line a record), rehashed.
base=$TMP/base.andros-session
python3 - "$DATA/sessions/drive.andros-session" "$base" <<'PY'
import sys
lines = open(sys.argv[1]).read().split("\n")
head = [l.split(" ", 1)[1].rsplit(" ", 1)[0] for l in lines[:4]]
layer = '"=HYPERLINK(\\"http://x\\",\\"y\\")\\n\\u001b[2J\\u202e\\u0000 forged"'
rest = "0600182000908080000000010020CC02"
records = head + ['link -1 connecting motion "not opened yet"', "event 0 connect Op pad", "state 0 not enabled",
                  'link 0 up motion ""', f"frame 0 0 sent {rest} gap=0", f"layer 40 {layer}",
                  f"frame 1 40 sent {rest} gap=0", 'layer 80 "+1"', f"frame 2 80 sent {rest} gap=0",
                  'layer 120 "-1"', f"frame 3 120 sent {rest} gap=0", 'layer 160 "@SUM(1)"',
                  f"frame 4 160 sent {rest} gap=0", 'end 160 tick 4 frames 5 "end of the input"']
open(sys.argv[2], "w").write("\n".join(f"{i} {p} {'0' * 64}" for i, p in enumerate(records)) + "\n")
PY
python3 "$tool" settings "$base" 's["robot"] = "HD1\n\x1b[2J\u202e\x00 HD1 226 FIRED intact forged"' ||
  fail "cannot craft the session"
for name in "${names[@]}"; do cp "$base" "$dir/$name.andros-session"; done

# sessions: a row a session, each on its own line, nothing raw.
expect_exit 0 "$BIN" sessions --record-dir "$dir"
clean "$TMP/out" "the sessions table"
rows=$(grep -c 'andros-session$' "$TMP/out")
[[ $rows -eq ${#names[@]} ]] || fail "the sessions table has $rows rows for ${#names[@]} sessions: $(cat "$TMP/out")"
grep -q '^2024-01-01' "$TMP/out" && fail "a forged row: $(cat "$TMP/out")"
# Its heading, its header and its rows; and under them, one line: the crafted sessions are not proven by replay.
[[ $(wc -l <"$TMP/out") -eq $((rows + 3)) ]] || fail "the sessions table has lines besides its rows: $(cat "$TMP/out")"
tail -1 "$TMP/out" | grep -q "sessions with WEAPONS and STOPS marked ?" || fail "the last line: $(tail -1 "$TMP/out")"
grep -qF 'a\n2024-01-01' "$TMP/out" || fail "the file name's newline is not shown as \\n: $(cat "$TMP/out")"
grep -qF 'd\xFF.andros-session' "$TMP/out" || fail "the byte 0xFF is not shown as \\xFF: $(cat "$TMP/out")"

# sessions --format jsonl: every session, its file name's bytes given back by unescaping.
expect_exit 0 "$BIN" sessions --record-dir "$dir" --format jsonl
clean "$TMP/out" "sessions --format jsonl"
python3 - "$TMP/out" "$dir" "${names[@]}" <<'PY' || fail "sessions --format jsonl: $(cat "$TMP/out")"
import json, os, re, sys
rows = [json.loads(l) for l in open(sys.argv[1], encoding="utf-8")]
d = os.fsencode(sys.argv[2])
def unescape(text):  # docs/recording.md: \\, \n, \r, \t, \xNN
    return re.sub(rb"\\(\\|n|r|t|x[0-9A-F]{2})", lambda m: {b"\\": b"\\", b"n": b"\n", b"r": b"\r", b"t": b"\t"}.get(
        m.group(1), bytes([int(m.group(1)[1:], 16)]) if m.group(1)[:1] == b"x" else b""), text.encode())
files = sorted(unescape(r["file"]) for r in rows)
want = sorted(d + b"/" + os.fsencode(n) + b".andros-session" for n in sys.argv[3:])
assert files == want, (files, want)
for r in rows:
    assert r["readable"], r
    assert unescape(r["robot"]) == b"HD1\n\x1b[2J\xe2\x80\xae\x00 HD1 226 FIRED intact forged", r["robot"]
PY

one="$dir/${names[0]}.andros-session"
# export: CSV text cells are never formulas, nothing raw; JSONL likewise.
expect_exit 0 "$BIN" export "$one" --format csv
clean "$TMP/out" "export --format csv"
python3 - "$TMP/out" <<'PY' || fail "export --format csv: a formula cell: $(cat "$TMP/out")"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1], encoding="utf-8", newline="")))
layers = [r["layer"] for r in rows]
assert len(rows) == 5, layers
assert all(not l or l[0] not in "=+-@\t\r" for l in layers), layers
assert layers[1].startswith("'=HYPERLINK(") and "\\x1B[2J" in layers[1] and "\\xE2\\x80\\xAE" in layers[1], layers
assert layers[2:] == ["'+1", "'-1", "'@SUM(1)"], layers
PY
expect_exit 0 "$BIN" export "$one" --format jsonl
clean "$TMP/out" "export --format jsonl"

# plot: the SVG is XML, nothing raw; U+202E shown as its bytes (\xE2\x80\xAE), not as '?'.
expect_exit 0 "$BIN" plot "$one" --output "$TMP/plot.svg"
clean "$TMP/plot.svg" "the plot's SVG"
python3 -c 'import sys, xml.dom.minidom; xml.dom.minidom.parse(sys.argv[1])' "$TMP/plot.svg" ||
  fail "the plot's SVG is not XML"
grep -qF 'HD1\n\x1B[2J\xE2\x80\xAE\x00 HD1 226' "$TMP/plot.svg" || fail "the plot's title does not show the robot's bytes"

# verify and replay: their lines, nothing raw (the session's own text is in none of them).
expect_exit 0 "$BIN" verify "$one"
clean "$TMP/out" "verify"

# A mapping's file name and layer names: check's ok line, the sheet's SVG and text, the log.
mapping="m${forged}${bidi}"$'\e[2J\xff.yaml'
printf 'robot: HD1\ndeadman: leftshoulder\nlayers:\n  "x\\n\\e[2J\\u202E\\x7F":\n    hold: a\n    bindings:\n      - signal: tool_on\n        button: b\n' \
  >"$TMP/$mapping"
expect_exit 0 "$BIN" check "$TMP/$mapping"
clean "$TMP/out" "check's ok line"
clean "$TMP/err" "check's warnings"
[[ $(wc -l <"$TMP/out") -eq 1 ]] || fail "check printed more than its ok line: $(cat "$TMP/out")"
expect_exit 0 "$BIN" sheet --mapping "$TMP/$mapping" --output "$TMP/sheet.svg"
clean "$TMP/sheet.svg" "the sheet's SVG"
grep -qF 'x\n\x1B[2J\xE2\x80\xAE\x7F' "$TMP/sheet.svg" ||
  fail "the sheet does not show the layer name's bytes"
printf '0 connect pad\n100 button leftshoulder 1\n200 button a 1\n300 button a 0\n400 end\n' >"$TMP/layer.events"
# (A path that is not UTF-8 is the recorder's to take: issue 34 item 1; this one is UTF-8.)
utf8_mapping="m${forged}${bidi}"$'\e[2J.yaml'
cp "$TMP/$mapping" "$TMP/$utf8_mapping"
expect_exit 0 "$BIN" run --mapping "$TMP/$utf8_mapping" --input "$TMP/layer.events"
clean "$TMP/err" "run's log"
grep -qF 'layer: x\n\x1B[2J\xE2\x80\xAE\x7F' "$TMP/err" || fail "the log does not show the layer's name escaped: $(cat "$TMP/err")"

# inputs, off a terminal: its two header lines, the mapping's file name escaped.
cp "$DATA/mappings/core.yaml" "$TMP/$mapping.core.yaml"
SDL_VIDEODRIVER=dummy "$BIN" inputs --mapping "$TMP/$mapping.core.yaml" --controller "no such pad" >"$TMP/inputs" \
  2>"$TMP/err" &
pid=$!
for _ in $(seq 600); do [[ $(wc -l <"$TMP/inputs") -ge 2 ]] && break; sleep 0.05; done  # bounded: 30 s
kill -INT "$pid"
wait "$pid"
clean "$TMP/inputs" "inputs' header"
[[ $(wc -l <"$TMP/inputs") -eq 2 ]] || fail "inputs' header is not two lines: $(cat "$TMP/inputs")"

# A folder with no sessions, named with them: one line, nothing raw.
expect_exit 0 "$BIN" sessions --record-dir "$TMP/${names[0]}${names[1]}/none"
clean "$TMP/out" "sessions' empty folder"
[[ $(wc -l <"$TMP/out") -eq 1 ]] || fail "sessions of an empty folder: $(cat "$TMP/out")"
finish
