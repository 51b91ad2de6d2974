# `run` under a service manager: sd_notify messages on a fake NOTIFY_SOCKET,
# the watchdog from the loop itself, reload on SIGHUP (docs/running.md "As a service").
source "$(dirname "$0")/lib.sh"
HERE=$(dirname "$0")
for scenario in notify deaf stall reload fifo_reload pipe_reload; do
  rm -rf "$TMP/$scenario" && mkdir -p "$TMP/$scenario/xdg"
  python3 "$HERE/service_harness.py" "$BIN" "$TMP/$scenario" "$scenario" || fail "scenario $scenario"
done

# Under systemd, stderr is the journal's stream (JOURNAL_STREAM=DEV:INODE of
# it): every line carries its syslog priority, <6> info, <3> error.
: >"$TMP/journal"
stream=$(stat -c '%d:%i' "$TMP/journal")
JOURNAL_STREAM=$stream XDG_CONFIG_HOME=$TMP/xdg "$BIN" run --input "$DATA/live/drive.events" 2>>"$TMP/journal"
grep -q '^<6>streaming to ' "$TMP/journal" || fail "no <6> info line in the journal: $(head -3 "$TMP/journal")"
grep -Eqv '^<[0-7]>' "$TMP/journal" && fail "a journal line without its priority: $(grep -Ev '^<[0-7]>' "$TMP/journal" | head -2)"
: >"$TMP/journal"
JOURNAL_STREAM=$(stat -c '%d:%i' "$TMP/journal") "$BIN" run --config "$TMP/missing.conf" 2>>"$TMP/journal"
grep -q '^<3>.*missing.conf: error: cannot read the config file' "$TMP/journal" || fail "no <3> error line: $(cat "$TMP/journal")"
# Another file's stream (stderr is not the journal's): the usual level words.
JOURNAL_STREAM=$stream "$BIN" run --config "$TMP/missing.conf" 2>"$TMP/other"
grep -q '^.*missing.conf: error: ' "$TMP/other" && ! grep -q '^<' "$TMP/other" || fail "priorities off the journal: $(cat "$TMP/other")"
finish
