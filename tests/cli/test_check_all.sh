# `check` as a compiler reports (issue 19, finding 9): every error of a file,
# each at the line of the file that has it (an extending file's own line, not
# the base's); a signal the base bound and this file leaves on no input is a
# warning; a mapping file that cannot be opened says why, and a FIFO is never
# waited on.
source "$(dirname "$0")/lib.sh"
MAPPINGS=$DATA/../../mappings
cd "$TMP" || exit 1

# A layer key in the extending file on an input its base binds: said at the
# extending file's line, naming the base's.
cat >base.yaml <<'YAML'
deadman: leftshoulder
bindings:
  - signal: tool_on
    button: x
    toggle: true
YAML
cat >ext.yaml <<'YAML'
robot: HD1
extends: base.yaml
layers:
  arm:
    hold: x
    bindings: []
YAML
expect_exit 2 "$BIN" check ext.yaml
expect_one_line_stderr
expect_stderr_matches "^ext.yaml:5:11: error: 'x' is bound at line 4 of base.yaml; it cannot also be the deadman or switch a layer$"

# Every error, in the order of the file, the loader's and validate()'s together; exit 2.
cat >multi.yaml <<'YAML'
robot: HD1
deadman: leftshoulder
bindings:
  - signal: tool_onn
    button: x
  - signal: rear_art_up
    button: yy
  - signal: rear_art_down
    button: a
  - signal: front_art_up
    button: a
YAML
expect_exit 2 "$BIN" check multi.yaml
[[ $(wc -l <"$TMP/err") -eq 3 ]] || fail "not three errors: $(cat "$TMP/err")"
expect_stderr_matches "^multi.yaml:4:13: error: unknown signal 'tool_onn'"
expect_stderr_matches "^multi.yaml:7:13: error: .*'yy'"
expect_stderr_matches "^multi.yaml:11:13: error: 'a' is bound twice in this layer \(first at line 9\)$"
# run stops on them all the same, before the first frame.
expect_exit 2 "$BIN" replay --mapping multi.yaml "$DATA/live/drive.events" --output frames
[[ $(wc -l <"$TMP/err") -eq 3 ]] || fail "replay: not three errors: $(cat "$TMP/err")"
# Two files: both checked, each error of each said.
expect_exit 2 "$BIN" check multi.yaml ext.yaml "$MAPPINGS/hd1.yaml"
[[ $(wc -l <"$TMP/err") -eq 4 ]] || fail "two files: not four errors: $(cat "$TMP/err")"
grep -q "hd1.yaml: ok" "$TMP/out" || fail "the good file after two bad ones: $(cat "$TMP/out")"

# Moving rear_art_up to X takes X from the tool toggle: ok, with a warning at the line that did it.
cat >moved.yaml <<YAML
robot: HD1
extends: $MAPPINGS/hd1.yaml
bindings:
  - signal: rear_art_up
    button: x
YAML
expect_exit 0 "$BIN" check moved.yaml
expect_stdout "moved.yaml: ok"
expect_one_line_stderr
expect_stderr_matches "^moved.yaml:4:5: warning: 'tool_on' is on no input: the file it extends bound it to 'x' \(common.yaml line [0-9]+\), which this binding gives to 'rear_art_up'"
# The docs' own example moves both: nothing is lost, nothing said.
cat >both.yaml <<YAML
robot: HD1
extends: $MAPPINGS/hd1.yaml
bindings:
  - signal: tool_on
    button: y
    toggle: true
  - signal: rear_art_up
    button: x
YAML
expect_exit 0 "$BIN" check both.yaml
[[ ! -s $TMP/err ]] || fail "a warning for a mapping that loses nothing: $(cat "$TMP/err")"

# Issue 28, item 8: an error that names another line names that line's file
# when it is another file; a clash with the deadman set here is reported here.
cat >base2.yaml <<'YAML'
deadman: leftshoulder
bindings:
  - signal: tool_on
    button: y
    toggle: true
  - signal: weapon_1
    button: a
    arm: lefttrigger
YAML
printf 'robot: HD1\nextends: base2.yaml\nestop: y\n' >stop_clash.yaml
expect_exit 2 "$BIN" check stop_clash.yaml
expect_stderr_matches "^stop_clash.yaml:3:8: error: the stop button 'y' is already bound \(line 4 of base2.yaml\): a stop button is bound to nothing else$"
printf 'robot: HD1\nextends: base2.yaml\ndeadman: lefttrigger\n' >trigger.yaml
expect_exit 2 "$BIN" check trigger.yaml
expect_stderr_matches "^trigger.yaml:3:10: error: 'arm' must be a second button, not the deadman \(line 8 of base2.yaml\)$"

# The shipped examples (mappings/examples/, docs/mapping.md) are good mappings.
for example in "$MAPPINGS"/examples/*.yaml; do
  expect_exit 0 "$BIN" check "$example"
done
# The trigger deadman on the shipped layout, as docs/mapping.md shows it.
expect_exit 0 "$BIN" sheet --mapping "$MAPPINGS/examples/trigger-deadman.yaml" --format text
grep -q "LT                     DEADMAN  hold to enable motion" "$TMP/out" ||
  fail "the example's sheet has no trigger deadman: $(head -5 "$TMP/out")"

# Why a mapping file cannot be opened; a FIFO nobody writes is refused at once.
mkdir adir
mkfifo fifo
printf 'robot: HD1\n' >locked.yaml
chmod 000 locked.yaml
expect_exit 2 "$BIN" check missing.yaml
expect_stderr_matches "^missing.yaml: error: cannot open mapping file 'missing.yaml': No such file or directory$"
expect_exit 2 "$BIN" check adir
expect_stderr_matches "^adir: error: cannot open mapping file 'adir': it is a directory$"
expect_exit 2 timeout 5 "$BIN" check fifo
expect_stderr_matches "^fifo: error: cannot open mapping file 'fifo': it is a FIFO \(a named pipe\), not a regular file$"
expect_exit 2 "$BIN" check /dev/null
expect_stderr_matches "^/dev/null: error: cannot open mapping file '/dev/null': it is a device, not a regular file$"
expect_exit 2 "$BIN" replay --mapping fifo "$DATA/live/drive.events" --output frames
expect_stderr_matches "it is a FIFO"
printf 'robot: HD1\nextends: adir\n' >extends_dir.yaml
expect_exit 2 "$BIN" check extends_dir.yaml
expect_stderr_matches "^extends_dir.yaml:2:10: error: cannot open mapping file 'adir': it is a directory$"
if [[ $(id -u) -ne 0 ]]; then
  expect_exit 2 "$BIN" check locked.yaml
  expect_stderr_matches "^locked.yaml: error: .*Permission denied"
elif command -v setpriv >/dev/null; then
  chmod 755 "$TMP"
  expect_exit 2 setpriv --reuid=nobody --regid=nogroup --clear-groups -- "$BIN" check "$TMP/locked.yaml"
  expect_stderr_matches "^$TMP/locked.yaml: error: .*Permission denied"
fi
finish
