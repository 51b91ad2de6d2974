# A HOME the user cannot read (issue 19, finding 5): one warning line naming
# the config file and why, then the run goes on; a mapping given by path (or
# the robot's, found past the unreadable folder) needs no HOME.
source "$(dirname "$0")/lib.sh"
LIVE=$DATA/live
unset XDG_CONFIG_HOME
mkdir "$TMP/home"
chmod 000 "$TMP/home"
# As root a mode-000 folder is readable: the checks run as nobody then.
as_user=()
if [[ $(id -u) -eq 0 ]]; then
  as_user=(setpriv --reuid=nobody --regid=nogroup --clear-groups --)
  chmod 755 "$TMP"
fi
cp "$LIVE/drive.events" "$TMP/drive.events"
cp "$DATA/../../mappings/common.yaml" "$DATA/../../mappings/hd1.yaml" "$TMP/"
chmod 644 "$TMP"/*.yaml "$TMP/drive.events"
[[ -x $BIN ]] && "${as_user[@]}" test -x "$BIN" || { echo "SKIP: $BIN cannot be run as nobody"; exit 0; }
conf=$TMP/home/.config/andros-bridge/andros-bridge.conf
warning="config: cannot look for $conf: Permission denied; going on without it"

for robot in "--mapping $TMP/hd1.yaml" "--robot hd1"; do
  # shellcheck disable=SC2086
  run_cmd env HOME="$TMP/home" "${as_user[@]}" "$BIN" run $robot --port sim --input "$TMP/drive.events"
  [[ $code -eq 0 ]] || fail "run $robot with HOME unreadable exited $code: $(head -c 400 "$TMP/err")"
  grep -q "filesystem error" "$TMP/err" && fail "run $robot: a raw filesystem error: $(cat "$TMP/err")"
  [[ $(grep -cF "$warning" "$TMP/err") -eq 1 ]] || fail "run $robot: not one line '$warning': $(cat "$TMP/err")"
  grep -q "stopped (end of the input)" "$TMP/err" || fail "run $robot did not run to the end: $(cat "$TMP/err")"
done

# The commands that read no config file need no HOME either.
run_cmd env HOME="$TMP/home" "${as_user[@]}" "$BIN" check "$TMP/hd1.yaml"
[[ $code -eq 0 && $(cat "$TMP/out") == "$TMP/hd1.yaml: ok" ]] || fail "check with HOME unreadable: $code $(cat "$TMP/out" "$TMP/err")"
run_cmd env HOME="$TMP/home" "${as_user[@]}" "$BIN" sheet --robot hd1 --format text
[[ $code -eq 0 ]] || fail "sheet --robot hd1 with HOME unreadable exited $code: $(cat "$TMP/err")"

# A HOME that is a file: nothing to say, nothing to stop.
touch "$TMP/file-home"
run_cmd env HOME="$TMP/file-home" "$BIN" run --mapping "$TMP/hd1.yaml" --port sim --input "$TMP/drive.events"
[[ $code -eq 0 ]] || fail "run with HOME a file exited $code: $(cat "$TMP/err")"
grep -q "config: cannot look" "$TMP/err" && fail "a HOME that is a file warned: $(cat "$TMP/err")"
finish
