# `run --port tcp:...` against servers on 127.0.0.1: a good one, one that stops
# reading, one that accepts and closes; and TCP port spellings that are bad input.
source "$(dirname "$0")/lib.sh"
HERE=$(dirname "$0")
LIVE=$DATA/live
export XDG_CONFIG_HOME=$TMP/xdg  # no user config file may change these runs

# server MODE NAME [SECONDS]: starts tcp_server.py in the background; $server_pid, $port.
server() {
  rm -f "$TMP/$2.port"
  python3 "$HERE/tcp_server.py" "$1" "$TMP/$2.port" "$TMP/$2.out" --seconds "${3:-20}" &
  server_pid=$!
  for _ in $(seq 200); do [[ -f $TMP/$2.port ]] && break; sleep 0.05; done
  port=$(cat "$TMP/$2.port")
}
# wait_for_log REGEX COUNT SECONDS: until $TMP/err has COUNT lines matching REGEX.
wait_for_log() {
  for _ in $(seq $(($3 * 20))); do
    (($(grep -Ec -- "$1" "$TMP/err") >= $2)) && return 0
    sleep 0.05
  done
  return 1
}

# Bad spellings are bad input (exit 2) at the place they were written.
expect_exit 2 "$BIN" run --port tcp:127.0.0.1:99999999999999999999 --input "$LIVE/drive.events"
expect_one_line_stderr
expect_stderr_matches "^--port: error: 'tcp:127.0.0.1:99999999999999999999' is not tcp:HOST:PORT \(PORT 1..65535\)"
for spec in tcp:127.0.0.1:0 tcp:127.0.0.1:65536 tcp:127.0.0.1:-1 tcp:127.0.0.1:4x tcp::4001; do
  printf '# TCP serial server\nserialport = %s\n' "$spec" >"$TMP/tcp.conf"
  expect_exit 2 "$BIN" run --config "$TMP/tcp.conf" --input "$LIVE/drive.events"
  expect_stderr_matches "^$TMP/tcp.conf:2:14: error: '$spec' is not tcp:"
done
printf 'serialport=tcp:no-such-host.invalid:4001\n' >"$TMP/tcp.conf"
expect_exit 2 "$BIN" run --config "$TMP/tcp.conf" --input "$LIVE/drive.events"
expect_stderr_matches "^$TMP/tcp.conf:1:12: error: cannot resolve 'no-such-host.invalid'"

# A good server: every frame, and at least 3 neutral frames at the end, exit 0.
server read good
run_cmd "$BIN" run --port "tcp:127.0.0.1:$port" --input "$LIVE/drive.events"
[[ $code -eq 0 ]] || fail "run to a good server exited $code: $(cat "$TMP/err")"
wait $server_pid || fail "the good server failed"
"$BIN" frame decode "$TMP/good.out" 2>/dev/null | python3 "$HERE/check_frames.py" --bin "$BIN" \
  --min 20 --enabled --driving --neutral-tail 3 >"$TMP/check" || fail "good server: $(cat "$TMP/check")"

# A server that accepts and never reads (its 4 kB buffer fills): the bridge
# notices within a bounded time, drops the connection and reconnects; no
# connection ever holds more than a few frames (docs/running.md: at most 32).
server stall stall 30
"$BIN" run --port "tcp:127.0.0.1:$port" --input "$LIVE/long_drive.events" >/dev/null 2>"$TMP/err" &
bridge=$!
wait_for_log "link tcp .*: lost \(stalled: the server took nothing for 2000 ms\)" 1 15 ||
  fail "no stall reported: $(cat "$TMP/err")"
wait_for_log "link tcp .*: up" 2 10 || fail "no reconnection after the stall: $(cat "$TMP/err")"
kill -TERM $bridge
wait $bridge
code=$?
rm -f "$TMP/stall.port"
wait $server_pid
# SIGTERM on the new connection to the server that stalled: it acknowledges
# the neutral frames, but has not been seen reading since, so they do not count.
[[ $code -eq 1 ]] || fail "SIGTERM against a stalled server exited $code, expected 1: $(cat "$TMP/err")"
grep -Eq "^error: (only [0-2] of 3 neutral frames could be handed to the link|the neutral frames were not seen to reach the far end before the link closed) \(tcp 127.0.0.1:$port\): the vehicle may still be acting on the last command it got" "$TMP/err" ||
  fail "no error line for the lost neutral frames: $(cat "$TMP/err")"
(($(grep -c "^error:" "$TMP/err") == 1)) || fail "not one error line: $(cat "$TMP/err")"
(($(wc -l <"$TMP/stall.out") >= 2)) || fail "fewer than 2 connections: $(cat "$TMP/stall.out")"
connection=0
while read -r held driving; do
  ((held <= 32)) || fail "a stalled connection held $held frames (bound 32): $(tr '\n' ' ' <"$TMP/stall.out")"
  # After the stall the server is sent nothing that moves until it is seen reading.
  ((connection == 0 || driving == 0)) ||
    fail "connection $connection to the server that stalled held $driving driving frames: $(tr '\n' ' ' <"$TMP/stall.out")"
  connection=$((connection + 1))
done <"$TMP/stall.out"
((driving_first = $(head -1 "$TMP/stall.out" | cut -d' ' -f2), driving_first > 0)) ||
  fail "the first connection held no driving frame: the check above proves nothing"
grep -q "neutral frames only: the server stalled and has not been seen reading since" "$TMP/err" ||
  fail "the neutral-only state is not logged: $(cat "$TMP/err")"

# A server that accepts and at once closes: retried with the back-off
# (250 ms doubling to 4 s), not every few ticks.
# 8 s from the start: 0, 0.25, 0.75, 1.75, 3.75, 7.75 s, 6 attempts, fewer when the
# start-up (ASan, a loaded machine) takes some of it: at least 3 leaves it 4 s (a
# connection closed at once used to be retried every ~300 ms: 26).
server close close 10
run_cmd timeout -s TERM 8 "$BIN" run --port "tcp:127.0.0.1:$port" --input "$LIVE/long_drive.events"
rm -f "$TMP/close.port"
wait $server_pid
attempts=$(wc -l <"$TMP/close.out")
((attempts >= 3 && attempts <= 9)) || fail "$attempts connections in 8 s from an accept-then-close server: $(tr '\n' ' ' <"$TMP/close.out")"
finish
