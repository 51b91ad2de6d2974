# The session records what the operating-state machine did in words of its
# own (issue 36, item 4; docs/recording.md, format 4): a `transition T FROM
# EVENT TO WHO` record for each step that changed the state, and a stop
# record for each stop press, two in one tick included; replay makes them
# again and names one altered.
source "$(dirname "$0")/lib.sh"
tool="$(dirname "$0")/session_tool.py"
export XDG_CONFIG_HOME=$TMP/xdg
mkdir -p "$TMP/rec"
expect_exit 0 "$BIN" run --input "$DATA/sessions/format3.events" --mapping "$DATA/../../mappings/examples/supervisor.yaml" \
  --weapons --record-dir "$TMP/rec"
session=$(ls "$TMP/rec"/*.andros-session)
head -1 "$session" | grep -q '^0 andros-session 4 ' || fail "not format 4: $(head -1 "$session")"
cut -d' ' -f2- "$session" | sed 's/ [0-9a-f]*$//' >"$TMP/records"  # without SEQ and hash
has() { grep -qxF -- "$1" "$TMP/records" || fail "no record '$1' in: $(grep -E '^(transition|stop|state)' "$TMP/records")"; }

# Both pads' stops at 800 ms: two presses, two records, the supervisor's last (the stop is the supervisor's).
has 'transition 800 enabled operator-stop stopped operator'
has 'stop 800 operator {"guid":"","name":"Operator pad","path":"","serial":""}'
has 'stop 800 supervisor {"guid":"","name":"Supervisor pad","path":"","serial":""}'
has 'state 800 stopped'
# Who reset it, who asked for the suspend and the reload, what took the link.
has 'transition 3600 stopped supervisor-reset not-enabled supervisor'
has 'transition 4400 enabled suspend suspended script'
has 'transition 5600 enabled reload reloading script'
has 'transition 6600 enabled link-taken no-link script'
has 'transition 7600 enabled controller-down no-controller supervisor'
has 'transition 8000 no-controller controller-up not-enabled supervisor'
has 'transition 200 not-enabled deadman-fresh-press enabled operator'
has 'transition 8440 not-enabled shutdown stopping script'
# Each state record follows a transition to that state at its tick.
awk '$1 == "transition" { to[$2] = $5 } $1 == "state" && $2 > 0 {
  s = $3; for (i = 4; i <= NF; ++i) s = s "-" $i
  if (to[$2] != s) { print "state " $2 " " s " after a transition to " to[$2]; bad = 1 } } END { exit bad }' \
  "$TMP/records" >"$TMP/bad" ||
  fail "$(cat "$TMP/bad")"

expect_exit 0 "$BIN" replay "$session"
grep -Eq '^[0-9]+ frames identical; [0-9]+ records .* made again the same$' "$TMP/out" || fail "replay: $(cat "$TMP/out")"
# An altered transition (whose stop) is found, though its state is the same.
sed 's/ transition 800 enabled operator-stop stopped operator / transition 800 enabled supervisor-stop stopped supervisor /' \
  "$session" >"$TMP/altered.andros-session"
python3 "$tool" renumber "$TMP/altered.andros-session"
expect_exit 0 "$BIN" verify "$TMP/altered.andros-session"
expect_exit 1 "$BIN" replay "$TMP/altered.andros-session"
grep -qF "recorded 'transition 800 enabled supervisor-stop stopped supervisor', the replay makes 'transition 800 enabled operator-stop stopped operator'" "$TMP/out" ||
  fail "an altered transition: $(cat "$TMP/out")"
# A transition in words the session does not have is not read.
sed 's/ transition 800 enabled operator-stop / transition 800 ENABLED operator-stop /' "$session" >"$TMP/bad.andros-session"
python3 "$tool" renumber "$TMP/bad.andros-session"
expect_exit 2 "$BIN" replay "$TMP/bad.andros-session"
expect_stderr_matches "unknown transition"
finish
