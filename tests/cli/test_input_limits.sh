# Every text input goes through one bounded reader (docs/running.md, "Input
# files and their limits"): a directory, an over-long line or an oversize
# file is a one-line error and exit 2; a FIFO or a pipe that stays open does
# not keep `run` from a stop signal; replay checks the whole script before it
# writes anything.
source "$(dirname "$0")/lib.sh"
cd "$TMP"
export XDG_CONFIG_HOME=$TMP/xdg SDL_VIDEODRIVER=dummy

# expect_error WANT_STDERR_LINE CMD...: exit 2 and exactly that one line (log lines aside).
expect_error() {
  local want=$1; shift
  run_cmd timeout 30 "$@"
  [[ $code -eq 2 ]] || fail "'$*' exited $code, expected 2"
  local got; got=$(grep -v '^info: ' "$TMP/err")
  [[ $got == "$want" ]] || fail "'$*': stderr was '$got', expected '$want'"
}

# lines COUNT LENGTH: COUNT comment lines of LENGTH bytes each (and a newline).
lines() { awk -v n="$1" -v len="$2" 'BEGIN { l = "#"; while (length(l) < len) l = l "x"; for (i = 0; i < n; i++) print l }'; }
long_line() { lines 1 "$1"; }
# filler BYTES: 100-byte lines (newline included), at least BYTES in all.
filler() { lines $((($1 + 99) / 100)) 99; }

printf '0 connect\n100 end\n' >ok.events

# Directories: all three ran with defaults (exit 0) or failed as I/O (exit 1).
mkdir dir
expect_error "dir: error: is a directory, not a config file" "$BIN" run --config dir --input ok.events
expect_error "dir: error: is a directory, not an event script" "$BIN" run --input dir
expect_error "dir: error: is a directory, not an event script" "$BIN" replay dir
expect_error "dir: error: is a directory, not a controller database" "$BIN" controllers --controller-db dir

# Over-long lines: 4 KiB at most, in every kind of text input.
{ echo robot=HD1; long_line 4097; } >long.conf
expect_error "long.conf:2: error: line longer than 4 KiB (the limit for a config file)" \
  "$BIN" run --config long.conf --input ok.events
{ printf 'robot: HD1\ndeadman: leftshoulder\n'; long_line 4097; } >long.yaml
expect_error "long.yaml:3: error: line longer than 4 KiB (the limit for a mapping file)" "$BIN" check long.yaml
{ echo '# mine'; long_line 5000; } >long.txt
expect_error "long.txt:2: error: line longer than 4 KiB (the limit for a controller database)" \
  "$BIN" controllers --controller-db long.txt
{ echo '0 connect'; printf '1 connect %*s\n' 5000 ''; } >long.events
expect_error "long.events:2: error: line longer than 4 KiB (the limit for an event script)" "$BIN" replay long.events
expect_error "long.events:2: error: line longer than 4 KiB (the limit for an event script)" "$BIN" run --input long.events

# Oversize files: the error names the line that goes past the limit.
{ echo robot=HD1; filler $((64 * 1024)); } >big.conf
expect_error "big.conf:657: error: more than 64 KiB (the limit for a config file)" \
  "$BIN" run --config big.conf --input ok.events
{ printf 'robot: HD1\ndeadman: leftshoulder\n'; filler $((1024 * 1024)); } >big.yaml
expect_error "big.yaml:10488: error: more than 1 MiB (the limit for a mapping file)" "$BIN" check big.yaml
filler $((8 * 1024 * 1024)) >big.txt
expect_error "big.txt:83887: error: more than 8 MiB (the limit for a controller database)" \
  "$BIN" controllers --controller-db big.txt

# An endless stream: refused at its first line, in bounded memory (2 GB of
# address space; the old reader grew without limit). AddressSanitizer
# reserves terabytes of address space for itself: there, no ulimit. (Its
# runtime is linked in by clang, a library to gcc: its entry named either way.)
limit="ulimit -v 2000000;"
grep -qa __asan_init "$BIN" && limit=""
run_cmd bash -c "$limit exec timeout 60 '$BIN' run --input /dev/zero"
[[ $code -eq 2 ]] || fail "run --input /dev/zero exited $code, expected 2: $(head -c 300 "$TMP/err")"
expect_stderr_matches '^/dev/zero:1: error: line longer than 4 KiB \(the limit for an event script\)$'

# A script longer than a day is refused at once, not played for years.
printf '0 connect\n10 button leftshoulder 1\n99999999999 end\n' >years.events
want="years.events:3:1: error: time 99999999999 ms is past 24 h (86400000 ms), the longest an event script may last"
# (Through head, so that a replay that streams instead stops at 1 MB.)
run_cmd bash -c "timeout 60 '$BIN' replay years.events --robot hd1 | head -c 1000000 | wc -c; exit \${PIPESTATUS[0]}"
[[ $code -eq 2 && $(cat "$TMP/out") -eq 0 ]] || fail "replay years.events: exit $code, $(cat "$TMP/out") bytes out"
[[ $(cat "$TMP/err") == "$want" ]] || fail "replay years.events: stderr was '$(cat "$TMP/err")'"
expect_error "$want" "$BIN" run --input years.events

# replay: text after `end`, or a bad line at the very end, and nothing is written.
printf '0 connect\n100 end\n200 button a 1\n' >after.events
expect_error "after.events:3:1: error: event after 'end'" "$BIN" replay after.events --output after.out
[[ ! -e after.out ]] || fail "replay created its output for a script with text after end"
run_cmd timeout 60 "$BIN" replay - --robot hd1 <after.events
[[ $code -eq 2 && ! -s $TMP/out ]] || fail "replay - with text after end: exit $code, $(wc -c <"$TMP/out") bytes out"
expect_stderr_matches "^<stdin>:3:1: error: event after 'end'$"
python3 - <<'PY'
with open("late.events", "w") as f:
    f.write("0 connect\n10 button leftshoulder 1\n")
    for t in range(20, 60000, 20):
        f.write(f"{t} axis lefty {-(t % 32768)}\n")
    f.write("60000 button trigger 1\n")
PY
expect_error "late.events:3002:14: error: unknown button 'trigger'" "$BIN" replay late.events --output late.out
[[ ! -e late.out ]] || fail "replay left a partial output file for a bad last line"
[[ ! -s $TMP/out ]] || fail "replay wrote frames to stdout before its bad last line"
echo "kept" >kept.out
expect_error "late.events:3002:14: error: unknown button 'trigger'" "$BIN" replay late.events --output kept.out
[[ $(cat kept.out) == kept ]] || fail "replay touched an existing output file for a bad script"
expect_exit 0 "$BIN" replay ok.events --output kept.out
[[ $(wc -l <kept.out) -eq 4 ]] || fail "replay --output over an existing file: $(cat kept.out)"

# A stop signal while `run` waits on its input (signals are blocked by then):
# a FIFO whose writer writes nothing, and a pipe that stays open.
# stop_while_reading NAME CMD...: CMD is started, given SIGTERM once it has
# blocked the stop signals (from then on only its own stop check can see
# one), and must exit 0 within 10 s having sent nothing.
stop_while_reading() {
  local name=$1; shift
  "$@" 2>"$TMP/err" &
  local pid=$! i mask
  for ((i = 0; i < 100; i++)); do  # bounded: 10 s
    mask=$(awk '/^SigBlk:/ { print $2 }' "/proc/$pid/status" 2>/dev/null)
    [[ -n $mask ]] && (((16#$mask >> 14) & 1)) && break  # SIGTERM (15) blocked
    sleep 0.1
  done
  sleep 0.2  # let it reach the read: a signal before it is seen there too
  kill -TERM "$pid"
  for ((i = 0; i < 100; i++)); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
  if kill -0 "$pid" 2>/dev/null; then
    fail "$name: still running 10 s after SIGTERM"
    kill -KILL "$pid"
  fi
  wait "$pid"
  local got=$?
  [[ $got -eq 0 ]] || fail "$name: exited $got after SIGTERM, expected 0; stderr: $(cat "$TMP/err")"
  grep -q 'stopped (SIGTERM) while reading the input, before the first frame' "$TMP/err" ||
    fail "$name: no closing line: $(cat "$TMP/err")"
}
# The writers are killed afterwards: ctest waits for whatever holds its pipes.
mkfifo fifo
sleep 60 >fifo 2>/dev/null &
writer=$!
stop_while_reading "run --input FIFO" "$BIN" run --input fifo
kill "$writer"
exec 7< <(exec sleep 60 2>/dev/null)  # a pipe whose writer stays and writes nothing
writer=$!
stop_while_reading "run --input PIPE" "$BIN" run --input /dev/fd/7
exec 7<&-
kill "$writer"
finish
