# `learn` as a process: its options, its refusals, and its keyboard on a pipe
# and on a pty. No controller is attached here: SDL's virtual pad lives inside
# one process, so the presses are tested in tests/cli/test_learn_live.cpp.
source "$(dirname "$0")/lib.sh"
export SDL_VIDEODRIVER=dummy XDG_CONFIG_HOME=$TMP/config
HERE=$(dirname "$0")
MAPPINGS=$(cd "$DATA/../../mappings" && pwd)

expect_exit 0 "$BIN" learn --help
grep -q "docs/mapping.md (Changing buttons with learn)" "$TMP/out" || fail "learn --help does not point at its docs"

expect_exit 2 "$BIN" learn --output "$TMP/mine.yaml"
expect_stderr_matches "give --robot NAME or --mapping FILE"
expect_exit 2 "$BIN" learn --robot hd1 --mapping "$MAPPINGS/hd1.yaml" --output "$TMP/mine.yaml"
expect_exit 2 "$BIN" learn --robot hd1
expect_exit 2 "$BIN" learn --robot hd1 --output "$TMP/no/such/folder/mine.yaml"
expect_stderr_matches "^--output: error: no folder"

# The output may not be the file learned from, nor one it extends.
cp "$MAPPINGS/hd1.yaml" "$MAPPINGS/common.yaml" "$TMP/"
expect_exit 2 "$BIN" learn --mapping "$TMP/hd1.yaml" --output "$TMP/hd1.yaml"
expect_stderr_matches "is the mapping learned from or a file it extends"
expect_exit 2 "$BIN" learn --mapping "$TMP/hd1.yaml" --output "$TMP/common.yaml"
cmp -s "$TMP/common.yaml" "$MAPPINGS/common.yaml" || fail "learn touched the base it refused to write"

printf 'robot: HD1\ndeadman: leftshoulder\nbindings:\n  - signal: tool_on\n    butten: a\n' >"$TMP/bad.yaml"
expect_exit 2 "$BIN" learn --mapping "$TMP/bad.yaml" --output "$TMP/mine.yaml"
expect_stderr_matches "^$TMP/bad.yaml:5:5: error: unknown key 'butten'"

# Off a terminal, one key per line. Nothing changed: nothing written, exit 0.
printf '\n\ns\nw\n' | "$BIN" learn --robot hd1 --output "$TMP/mine.yaml" >"$TMP/out" 2>"$TMP/err"
code=$?
[[ $code -eq 0 ]] || fail "learn ... w exited $code: $(cat "$TMP/err")"
grep -q '^\[1/[0-9]*\] base layer, the deadman: press a button or pull a trigger (Enter keeps leftshoulder)$' "$TMP/out" ||
  fail "no deadman prompt in: $(cat "$TMP/out")"
grep -q '^  no controller: waiting for the first controller$' "$TMP/out" || fail "no word of the missing controller"
grep -q '^  kept leftshoulder$' "$TMP/out" || fail "Enter did not keep the deadman: $(cat "$TMP/out")"
grep -q '^  kept the rest of this layer$' "$TMP/out" || fail "s did not skip the layer: $(cat "$TMP/out")"
grep -q "layer 'arm', the key of layer 'arm' (toggle)" "$TMP/out" || fail "s did not go to the arm layer"
grep -q "^nothing changed: $TMP/mine.yaml not written$" "$TMP/out" || fail "$(cat "$TMP/out")"
[[ ! -e $TMP/mine.yaml ]] || fail "learn wrote a file with nothing changed"

# q, and the end of the input, quit without writing: exit 1.
for keys in 'q\n' '\n\n'; do
  printf "$keys" | "$BIN" learn --robot hd1 --output "$TMP/mine.yaml" >"$TMP/out" 2>"$TMP/err"
  code=$?
  [[ $code -eq 1 ]] || fail "learn with keys '$keys' exited $code, expected 1"
  grep -q "^quit: $TMP/mine.yaml not written$" "$TMP/out" || fail "$(cat "$TMP/out")"
done
[[ ! -e $TMP/mine.yaml ]] || fail "learn wrote a file on quit"

# On a terminal: Ctrl-C and SIGTERM quit, and the terminal's settings are restored.
for how in '\x03' 'q' --term; do
  python3 "$HERE/learn_tty.py" "$how" -- "$BIN" learn --robot hd1 --output "$TMP/mine.yaml" >"$TMP/out" 2>&1
  code=$?
  [[ $code -eq 1 ]] || fail "learn on a pty, '$how': exit $code, expected 1: $(cat "$TMP/out")"
  grep -q "quit: $TMP/mine.yaml not written" "$TMP/out" || fail "'$how': $(cat "$TMP/out")"
done
[[ ! -e $TMP/mine.yaml ]] || fail "learn wrote a file on Ctrl-C"

finish
