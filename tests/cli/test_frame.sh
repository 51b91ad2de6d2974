# `frame encode` and `frame decode` as a user runs them.
source "$(dirname "$0")/lib.sh"

example_data=00001C2000907F7E3E0000FFFF20CC02
example_frame=F1F13030303031433230303039303746374533453030303046464646323043433032F206

expect_exit 0 "$BIN" frame encode $example_data
expect_stdout $example_frame
expect_exit 0 "$BIN" frame encode 00001c2000907f7e3e0000ffff20cc02
expect_stdout $example_frame
expect_exit 0 "$BIN" frame encode "00 00 1C 20 00 90 7F 7E 3E 00 00 FF FF 20 CC 02"
expect_stdout $example_frame

for bad in 00001C2000907F7E3E0000FFFF20CC0 00001C2000907F7E3E0000FFFF20CC020 00001C2000907F7E3E0000FFFF20CC0G ""; do
  expect_exit 2 "$BIN" frame encode "$bad"
  expect_one_line_stderr
  expect_stderr_matches '^andros-bridge: error: frame encode: '
done
expect_exit 2 "$BIN" frame encode
expect_one_line_stderr
expect_exit 2 "$BIN" frame bogus
expect_exit 2 "$BIN"

# Decode the worked example from a file and from standard input.
"$BIN" frame encode --raw $example_data >"$TMP/example.bin"
[[ $(stat -c %s "$TMP/example.bin") -eq 36 ]] || fail "--raw wrote $(stat -c %s "$TMP/example.bin") bytes"
expect_exit 0 "$BIN" frame decode "$TMP/example.bin"
grep -q '"offset":0,"data":"'$example_data'","checksum_ok":true,"valid":true,"errors":\[\]' "$TMP/out" ||
  fail "decode output: $(cat "$TMP/out")"
grep -q '"pivot":127,"drive":126' "$TMP/out" || fail "decoded signals: $(cat "$TMP/out")"
expect_stderr_matches '^frames: 1, valid: 1, bad checksum: 0, invalid: 0, bytes skipped: 0'
run_cmd "$BIN" frame decode - <"$TMP/example.bin"
[[ $code -eq 0 && $(wc -l <"$TMP/out") -eq 1 ]] || fail "decode from stdin"
# The example's byte 11 is 0xFF: --code 01 flags it.
expect_exit 0 "$BIN" frame decode --code 01 "$TMP/example.bin"
grep -q '"valid":false' "$TMP/out" && grep -q 'byte 11 code 0xFF, expected 0x01' "$TMP/out" || fail "--code check: $(cat "$TMP/out")"
expect_exit 2 "$BIN" frame decode --code XYZ "$TMP/example.bin"
expect_one_line_stderr

# The mixed capture: garbage, false starts, a truncated frame, a frame that
# lost its checksum, checksums holding F1. See data/mixed_capture.expected.
expect_exit 0 "$BIN" frame decode "$DATA/mixed_capture.bin"
python3 - "$TMP/out" "$DATA/mixed_capture.expected" <<'PY' || fail "mixed capture frames differ"
import json, sys
got = [json.loads(l) for l in open(sys.argv[1])]
want = [l.split() for l in open(sys.argv[2]) if l.strip() and not l.startswith('#')]
ok = True
valid_got = [(f["offset"], f["data"]) for f in got if f["valid"]]
valid_want = [(int(o), d) for o, d, v in want if v == "valid"]
if valid_got != valid_want:
    print("valid frames:", valid_got, "expected", valid_want); ok = False
if len(got) != len(want):
    print("frames:", [(f["offset"], f["valid"]) for f in got], "expected", want); ok = False
sys.exit(0 if ok else 1)
PY

# Random bytes decode without error.
head -c 2000000 /dev/urandom >"$TMP/random.bin"
expect_exit 0 "$BIN" frame decode "$TMP/random.bin"
expect_stderr_matches '^frames: [0-9]+, valid: 0, '

expect_exit 2 "$BIN" frame decode "$TMP/does-not-exist"
expect_one_line_stderr
expect_stderr_matches "does-not-exist: error: cannot open"

expect_exit 0 "$BIN" --version
expect_stdout "$("$BIN" --version)"
grep -q '^andros-bridge [0-9]' "$TMP/out" || fail "--version"
for cmd in "" "frame" "frame encode" "frame decode"; do
  expect_exit 0 "$BIN" $cmd --help
  grep -q "Usage:" "$TMP/out" || fail "$cmd --help"
done
finish
