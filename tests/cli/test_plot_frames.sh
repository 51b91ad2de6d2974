# `plot` never draws what did not happen (docs/recording.md, "Plot"): a
# session recorded by `run` from tests/data/plot/stops.events (a full drive
# stopped by a stop tap shorter than a tick, a second stop close after it,
# a reset, a drive that moves several times a tick) drawn whole and in
# parts, each page read back and compared with the session's records by
# check_plot.py: the lines' points in time order, each a value that held in
# its pixel column, level between columns, broken where nothing was sent;
# the state band from the range's start, the resets where they were; labels
# that overlap none other; every stop press on its lane.
source "$(dirname "$0")/lib.sh"
root="$DATA/../.."
export XDG_CONFIG_HOME=$TMP/xdg

# 100 Hz: on the page's 945 px, the whole session (19.5 s) has two ticks a
# pixel column, and a tenth of a second 94 px a tick: a column holding many
# frames and a frame across many columns, from the same run.
run_cmd "$BIN" run --input "$DATA/plot/stops.events" --mapping "$root/mappings/examples/supervisor.yaml" \
  --port sim --rate 100 --baud 38400
[[ $code -eq 0 ]] || fail "run exited $code: $(head -c 400 "$TMP/err")"
session=$(ls "$XDG_STATE_HOME"/andros-bridge/*.andros-session | tail -1)

# check FROM TO [plot's range flags...]: the page for that range is the session's.
check() {
  local from=$1 to=$2; shift 2
  local svg=$TMP/plot-$from-$to.svg
  expect_exit 0 "$BIN" plot "$session" --output "$svg" "$@"
  python3 "$(dirname "$0")/check_plot.py" "$BIN" "$session" "$svg" "$from" "$to" guide >"$TMP/check" 2>&1 ||
    fail "plot ${*:-(whole)}: $(cat "$TMP/check")"
}
check 0 last                        # the whole: 2 ticks a column, the stop's labels side by side
check 5 7 --from 5 --to 7           # the stop taps: 4.7 px a tick
check 10 16 --from 10 --to 16       # starts inside the band after the reset at 9.2 s
check 14.2 14.3 --from 14.2 --to 14.3 # the moving drive: 94 px a tick
check 6 60 --from 6 --to 60         # ends past the session's end: nothing drawn after its last tick

finish
