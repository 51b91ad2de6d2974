# `run` under a service manager: sd_notify messages on a fake NOTIFY_SOCKET,
# the watchdog from the loop itself, reload on SIGHUP (docs/running.md "As a service").
source "$(dirname "$0")/lib.sh"
HERE=$(dirname "$0")
for scenario in notify deaf stall reload; do
  rm -rf "$TMP/$scenario" && mkdir -p "$TMP/$scenario/xdg"
  python3 "$HERE/service_harness.py" "$BIN" "$TMP/$scenario" "$scenario" || fail "scenario $scenario"
done
finish
