# `inputs` without --robot or --mapping reads the mapping `run` would use
# (issue 19, finding 8): the config file's, else HD1's, and says which.
source "$(dirname "$0")/lib.sh"
export SDL_VIDEODRIVER=dummy
MAPPINGS=$(cd "$DATA/../../mappings" && pwd)

# header FILE ARGS...: runs inputs off a terminal until its two header lines are out.
header() {
  local out=$1; shift
  "$@" >"$out" 2>"$TMP/err" &
  local pid=$!
  for _ in $(seq 600); do [[ $(wc -l <"$out") -ge 2 ]] && break; sleep 0.05; done  # bounded: 30 s (a ceiling: ASan on a loaded machine)
  # Out line by line while it runs (the signal goes once it is, past the start-up).
  [[ $(wc -l <"$out") -ge 2 ]] || fail "inputs $*: the header is not out while it runs: $(cat "$out")"
  kill -TERM "$pid"
  wait "$pid" || fail "inputs $*: exit $?: $(cat "$TMP/err")"
}

export XDG_CONFIG_HOME=$TMP/xdg
header "$TMP/plain" "$BIN" inputs --controller "no such pad"
grep -qx "# deadzones and thresholds of $MAPPINGS/hd1.yaml (run's default: no --robot or --mapping given)" "$TMP/plain" ||
  fail "inputs without a mapping does not read HD1's: $(cat "$TMP/plain")"

mkdir -p "$TMP/xdg/andros-bridge"
printf 'robot=PROWLER\n' >"$TMP/xdg/andros-bridge/andros-bridge.conf"
header "$TMP/conf" "$BIN" inputs --controller "no such pad"
grep -qx "# deadzones and thresholds of $MAPPINGS/prowler.yaml (run's, from $TMP/xdg/andros-bridge/andros-bridge.conf: no --robot or --mapping given)" "$TMP/conf" ||
  fail "inputs does not read the config file's robot: $(cat "$TMP/conf")"

header "$TMP/given" "$BIN" inputs --robot rav --controller "no such pad"
grep -qx "# deadzones and thresholds of $MAPPINGS/rav.yaml" "$TMP/given" || fail "--robot rav: $(cat "$TMP/given")"
finish
