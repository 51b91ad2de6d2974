# A CPU-time limit is met with neutral frames (issue 34, docs/running.md,
# "Signals"). bash's `ulimit -t N` sets the soft and the hard limit to N: the
# kernel's SIGKILL would come with no SIGXCPU before it, mid-drive. run lowers
# its own soft limit under the hard one, so SIGXCPU (a stop: the shutdown's
# neutral frames, the session closed) comes first; here it is sent as the
# kernel sends it at the soft limit.
source "$(dirname "$0")/lib.sh"
cd "$TMP"

printf '0 connect pad\n40 button leftshoulder 1\n100 axis lefty -20000\n60000 end\n' >drive.events
bash -c 'ulimit -t 6; exec "$0" run --input drive.events --port sim --record-dir rec' "$BIN" 2>"$TMP/log" &
pid=$!
for _ in $(seq 100); do grep -q 'enabled' "$TMP/log" && break; sleep 0.1; done
limits=$(grep 'Max cpu time' "/proc/$pid/limits" | tr -s ' ' | sed 's/ $//')
[[ $limits == "Max cpu time 4 6 seconds" ]] || fail "limits while running: '$limits' (want soft 4, hard 6)"
grep -q 'CPU-time limit: soft 6 s lowered to 4 s, under the hard 6 s' "$TMP/log" || fail "log: $(cat "$TMP/log")"
kill -XCPU "$pid"
wait "$pid"
code=$?
[[ $code -eq 0 ]] || fail "exit $code after SIGXCPU, expected 0"
grep -q 'stopped (SIGXCPU)' "$TMP/log" || fail "no 'stopped (SIGXCPU)': $(cat "$TMP/log")"
expect_exit 0 "$BIN" verify rec/*.andros-session
grep -q '^closed' "$TMP/out" || fail "the session is not closed: $(cat "$TMP/out")"
grep -q 'end [0-9]* tick [0-9]* frames [0-9]* "SIGXCPU"' rec/*.andros-session || fail "no end record for SIGXCPU"

exit $((failures > 0))
