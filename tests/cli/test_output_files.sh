# Every command's --output is written the one way (base/output_file.hpp):
# `-` is standard output, a device or FIFO is written in place and never
# removed, a symlink is followed and kept, a failed write leaves the old file
# as it was and removes nothing. Nodes and links are made in $TMP, never
# under /dev. A full disk is RLIMIT_FSIZE (a write past it fails with EFBIG
# once SIGXFSZ is ignored); device nodes need root, a read-only folder a user
# that is not root (setpriv to nobody when run as root).
source "$(dirname "$0")/lib.sh"
export SDL_VIDEODRIVER=dummy XDG_CONFIG_HOME=$TMP/config
cd "$TMP" || exit 1
printf '0 connect pad\n10 button leftshoulder 1\n20 axis lefty -32768\n60000 end\n' >long.events  # 60 kB of frames

# small_disk CMD...: runs CMD with files limited to 4 KiB.
small_disk() { (trap '' XFSZ; ulimit -f 4; "$@"); }

# is_char PATH / is_link PATH
is_char() { [[ -c $1 && ! -L $1 ]]; }

# sheet --output -: standard output, never a file named '-'.
expect_exit 0 "$BIN" sheet --robot hd1 --format text --output -
grep -q "^HD1 cheat sheet" "$TMP/out" || fail "sheet --output - wrote nothing to stdout"
[[ -e ./- ]] && fail "sheet --output - made a file named '-'"

# replay --output -, record --output - (standard output) likewise.
expect_exit 0 "$BIN" replay long.events --output -
[[ -s $TMP/out && ! -e ./- ]] || fail "replay --output - did not write to stdout"

# A full disk: the old file is left whole, no temporary is left beside it, and the error says why.
for cmd in "sheet --robot hd1" "replay long.events"; do
  printf 'the good old file\n' >old.out
  run_cmd small_disk "$BIN" $cmd --output old.out
  [[ $code -eq 1 ]] || fail "$cmd on a full disk exited $code: $(cat "$TMP/err")"
  expect_stderr_matches "^andros-bridge: error: cannot write 'old.out': File too large$"
  [[ $(cat old.out) == 'the good old file' ]] || fail "$cmd on a full disk did not leave the old file"
  leftover=$(ls -A | grep -v -e '^old.out$' -e '^long.events$' -e '^out$' -e '^err$' -e '^config$')
  [[ -z $leftover ]] || fail "$cmd on a full disk left: $leftover"
done

# A symlink is followed: its target replaced, the link kept; on a failure both stay as they were.
mkdir -p real
for cmd in "sheet --robot hd1" "replay long.events"; do
  printf 'old target\n' >real/target.out
  ln -sfn real/target.out link.out
  expect_exit 0 "$BIN" $cmd --output link.out
  [[ -L link.out ]] || fail "$cmd --output LINK replaced the link"
  [[ $(head -c 10 real/target.out) != 'old target' && -s real/target.out ]] || fail "$cmd did not write the link's target"
  printf 'old target\n' >real/target.out
  run_cmd small_disk "$BIN" $cmd --output link.out
  [[ $code -eq 1 ]] || fail "$cmd to a link on a full disk exited $code"
  [[ -L link.out ]] || fail "$cmd on a full disk removed the link"
  [[ $(cat real/target.out) == 'old target' ]] || fail "$cmd on a full disk emptied the link's target"
done
# A dangling link: its target is written, the link kept.
ln -sfn real/new.svg dangling.svg
expect_exit 0 "$BIN" sheet --robot hd1 --output dangling.svg
[[ -L dangling.svg && -s real/new.svg ]] || fail "a dangling link's target was not written"

# The old file's mode is kept.
printf 'old\n' >mode.svg
chmod 640 mode.svg
expect_exit 0 "$BIN" sheet --robot hd1 --output mode.svg
[[ $(stat -c %a mode.svg) == 640 ]] || fail "sheet --output changed the mode to $(stat -c %a mode.svg)"

# A FIFO is written in place and stays a FIFO.
mkfifo fifo
cat fifo >from_fifo &
reader=$!
expect_exit 0 "$BIN" sheet --robot hd1 --format text --output fifo
wait "$reader"
[[ -p fifo ]] || fail "sheet --output FIFO replaced the FIFO"
grep -q "^HD1 cheat sheet" from_fifo || fail "nothing came through the FIFO"

# Device nodes (root only): /dev/null's and /dev/full's twins, made here.
if [[ $(id -u) -eq 0 ]]; then
  mknod null c 1 3
  mknod full c 1 7
  ln -s full full_link
  for cmd in "sheet --robot hd1" "replay long.events"; do
    expect_exit 0 "$BIN" $cmd --output null
    is_char null || fail "$cmd --output NULL-NODE replaced the node"
    for target in full full_link; do
      expect_exit 1 "$BIN" $cmd --output $target
      expect_stderr_matches "^andros-bridge: error: cannot write '$target': No space left on device$"
      is_char full || fail "$cmd --output $target: the full node is gone"
    done
    [[ -L full_link ]] || fail "$cmd removed the link to the full node"
  done
  # A recording to a full node: the node stays.
  "$BIN" record --output full 2>"$TMP/err" &
  pid=$!
  # Until it has said so (or ended): a SIGINT before its start-up has set up its
  # handling would end it with the signal's default action, before any word.
  for _ in $(seq 600); do grep -q 'No space left' "$TMP/err" && break; kill -0 "$pid" 2>/dev/null || break; sleep 0.05; done  # bounded: 30 s
  kill -INT "$pid" 2>/dev/null  # it may have ended on its own
  wait "$pid"
  is_char full || fail "record --output FULL-NODE removed the node"
  grep -q "cannot write 'full': No space left on device" "$TMP/err" || fail "record to a full node: $(cat "$TMP/err")"
fi

# A read-only folder: the old file stays, the reason is given (as a user that is not root).
as_user() { if [[ $(id -u) -eq 0 ]]; then setpriv --reuid=nobody --regid=nogroup --clear-groups -- "$@"; else "$@"; fi; }
if [[ $(id -u) -ne 0 ]] || command -v setpriv >/dev/null; then
  mkdir -p ro && printf 'old\n' >ro/sheet.svg && chmod 755 ro && chmod 666 ro/sheet.svg
  [[ $(id -u) -eq 0 ]] && chmod 755 "$TMP" && chown -R nobody ro
  chmod 555 ro
  run_cmd as_user "$BIN" sheet --robot hd1 --output ro/sheet.svg
  [[ $code -eq 1 ]] || fail "sheet into a read-only folder exited $code"
  expect_stderr_matches "^andros-bridge: error: cannot open 'ro/sheet.svg' for writing: Permission denied$"
  [[ $(cat ro/sheet.svg) == old ]] || fail "sheet into a read-only folder touched the old file"
  chmod 755 ro
fi

# A missing folder, a folder: the reason, nothing made.
expect_exit 1 "$BIN" sheet --robot hd1 --output no/such/x.svg
expect_stderr_matches "^andros-bridge: error: cannot open 'no/such/x.svg' for writing: No such file or directory$"
expect_exit 1 "$BIN" replay long.events --output real
expect_stderr_matches "cannot open 'real' for writing: Is a directory$"

# record: an existing recording is replaced only when the new one ends; a new one grows as it goes.
printf 'old recording\n' >rec.events
"$BIN" record --output rec.events 2>"$TMP/err" &
pid=$!
for _ in $(seq 600); do ls -A | grep -q '^\.rec\.events\.' && break; sleep 0.05; done  # bounded: 30 s (a ceiling: ASan on a loaded machine)
[[ $(cat rec.events) == 'old recording' ]] || fail "record touched the old recording before it ended"
kill -INT "$pid"
wait "$pid"
grep -Eq '^[0-9]+ +end$' rec.events || fail "record did not replace the old recording: $(cat rec.events)"
printf 'old recording\n' >rec.events
# (stderr through a pipe: the limit holds for a regular file there too)
(trap '' XFSZ; ulimit -f 0; exec "$BIN" record --output rec.events 2>&1) | cat >"$TMP/err"
code=${PIPESTATUS[0]}
[[ $code -eq 1 ]] || fail "record on a full disk exited $code: $(cat "$TMP/err")"
grep -q "cannot write 'rec.events': File too large" "$TMP/err" || fail "record on a full disk: $(cat "$TMP/err")"
[[ $(cat rec.events) == 'old recording' ]] || fail "record on a full disk did not leave the old recording"
[[ -z $(ls -A | grep '^\.rec\.events\.') ]] || fail "record on a full disk left its temporary"

finish
