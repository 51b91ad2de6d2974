# `run` on a terminal: the status screen at 80x24 (header first, fits, colour
# only without NO_COLOR), resized; off a terminal, the first log line names
# the robot, mapping file, port and code.
source "$(dirname "$0")/lib.sh"
export XDG_CONFIG_HOME=$TMP/xdg  # no user config file may change these runs
screen() { python3 "$(dirname "$0")/screen_tty.py" "$BIN" "$DATA" "$@" >"$TMP/screen" 2>&1 || fail "screen $*: $(cat "$TMP/screen")"; }

screen
screen --weapons
screen --no-color

run_cmd "$BIN" run --port sim --code 3C --input "$DATA/live/drive.events"
[[ $code -eq 0 ]] || fail "run exited $code: $(cat "$TMP/err")"
first=$(grep -v "^info: config:" "$TMP/err" | head -1)
[[ $first =~ ^info:\ robot\ HD1,\ mapping\ .*/hd1\.yaml,\ port\ sim,\ code\ 3C$ ]] || fail "first log line: $first"
finish
