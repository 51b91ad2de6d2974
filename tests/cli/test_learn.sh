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
expect_exit 2 "$BIN" learn --robot hd1 --output -
expect_stderr_matches "^--output: error: learn writes a file"
printf 'x' >"$TMP/afile"
expect_exit 2 "$BIN" learn --robot hd1 --output "$TMP/afile/mine.yaml"
expect_stderr_matches "^--output: error: '$TMP/afile' is not a folder$"

# A missing folder is made when the file is written: the session starts (q quits it).
printf 'q\n' | "$BIN" learn --robot hd1 --output "$TMP/no/such/folder/mine.yaml" >"$TMP/out" 2>"$TMP/err"
code=$?
[[ $code -eq 1 ]] || fail "learn to a missing folder exited $code: $(cat "$TMP/err")"
grep -q '^\[1/' "$TMP/out" || fail "learn to a missing folder did not start: $(cat "$TMP/out" "$TMP/err")"

# The documented output on a fresh account (HOME empty): the session starts.
mkdir -p "$TMP/home"
user_hd1="$TMP/home/.config/andros-bridge/mappings/hd1.yaml"
printf 'q\n' | env -u XDG_CONFIG_HOME HOME="$TMP/home" "$BIN" learn --robot hd1 --output "$user_hd1" >"$TMP/out" 2>"$TMP/err"
code=$?
[[ $code -eq 1 ]] || fail "learn on a fresh account exited $code: $(cat "$TMP/err")"
grep -q '^\[1/' "$TMP/out" || fail "learn on a fresh account did not start: $(cat "$TMP/out" "$TMP/err")"

# The second run on its own output: refused without --force, started with it.
mkdir -p "$(dirname "$user_hd1")"
printf 'robot: HD1\nextends: hd1\ndeadman: paddle1\n' >"$user_hd1"
run_cmd env -u XDG_CONFIG_HOME HOME="$TMP/home" "$BIN" learn --robot hd1 --output "$user_hd1"
[[ $code -eq 2 ]] || fail "learn over its own output without --force exited $code"
expect_stderr_matches "^--output: error: '$user_hd1' exists: give --force to replace it"
printf 'q\n' | env -u XDG_CONFIG_HOME HOME="$TMP/home" "$BIN" learn --robot hd1 --output "$user_hd1" --force >"$TMP/out" 2>"$TMP/err"
code=$?
[[ $code -eq 1 ]] || fail "learn over its own output with --force exited $code: $(cat "$TMP/err")"
grep -q 'Enter keeps paddle1' "$TMP/out" || fail "the second run does not start from the first's buttons: $(head -3 "$TMP/out")"

# An existing file is refused unless --force; a file the mapping extends even with it.
printf "an operator's notes\n" >"$TMP/notes.txt"
expect_exit 2 "$BIN" learn --robot hd1 --output "$TMP/notes.txt"
expect_stderr_matches "exists: give --force"
[[ $(cat "$TMP/notes.txt") == "an operator's notes" ]] || fail "learn touched an existing file"
cp "$MAPPINGS/hd1.yaml" "$MAPPINGS/common.yaml" "$TMP/"
expect_exit 2 "$BIN" learn --mapping "$TMP/hd1.yaml" --output "$TMP/common.yaml" --force
expect_stderr_matches "is a file the mapping learned from extends: it would extend itself"
cmp -s "$TMP/common.yaml" "$MAPPINGS/common.yaml" || fail "learn touched the base it refused to write"
# A long name is never cut in an error.
long="$TMP/$(printf 'x%.0s' $(seq 100))-the-end"
mkdir -p "$long" && printf 'x' >"$long/mine.yaml"
expect_exit 2 "$BIN" learn --robot hd1 --output "$long/mine.yaml"
expect_stderr_matches "'$long/mine.yaml' exists"

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
