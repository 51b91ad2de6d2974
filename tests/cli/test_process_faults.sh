# `run` and `monitor` under faults from the process around them: a log pipe
# closed or full, the stop's timing, Ctrl-Z and SIGCONT (also one that comes
# during the Ctrl-Z's neutral frames), a paused terminal
# (docs/running.md, "Logs, pipes and job control").
source "$(dirname "$0")/lib.sh"
HERE=$(dirname "$0")
export XDG_CONFIG_HOME=$TMP/xdg
# scenario NAME CHECK_ARGS...: the harness passes, and the port's frames pass check_frames.py.
scenario() {
  local name=$1; shift
  python3 "$HERE/fault_harness.py" "$BIN" "$DATA" "$name" "$TMP/$name.cap" >"$TMP/$name.out" 2>&1 ||
    { fail "$name: $(cat "$TMP/$name.out")"; return; }
  (($# == 0)) && return
  "$BIN" frame decode "$TMP/$name.cap" 2>/dev/null | python3 "$HERE/check_frames.py" --bin "$BIN" "$@" >"$TMP/check" ||
    fail "$name: $(cat "$TMP/check")"
}

scenario closed-log --min 10 --driving --neutral-tail 3
scenario stuck-log --min 10 --driving --neutral-tail 3
scenario stop-tick --driving --neutral-tail 3
scenario job-control --driving --enabled --neutral-tail 3
scenario continue-early --driving --neutral-tail 3
scenario background-stop --driving --neutral-tail 3
scenario paused-terminal --min 25 --driving --neutral-tail 3
scenario monitor-zero
finish
