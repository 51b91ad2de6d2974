# Helpers for the CLI tests: each test script is run as `bash test_X.sh BIN DATA_DIR`.
set -uo pipefail
BIN=$1
DATA=$2
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
# `run` keeps a flight recorder session per run (docs/recording.md): in the test's folder, never ~/.local/state.
export XDG_STATE_HOME=$TMP/state
unset STATE_DIRECTORY
failures=0

fail() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }

# run_cmd CMD...: runs it, keeping stdout in $TMP/out, stderr in $TMP/err, code in $code.
run_cmd() {
  "$@" >"$TMP/out" 2>"$TMP/err"
  code=$?
}

# expect_exit CODE CMD...
expect_exit() {
  local want=$1; shift
  run_cmd "$@"
  [[ $code -eq $want ]] || fail "'$*' exited $code, expected $want; stderr: $(head -c 400 "$TMP/err")"
}

# expect_stdout TEXT: the last command printed exactly TEXT (and a newline).
expect_stdout() {
  local got; got=$(cat "$TMP/out")
  [[ $got == "$1" ]] || fail "stdout was '$got', expected '$1'"
}

# expect_stderr_matches REGEX
expect_stderr_matches() {
  grep -Eq -- "$1" "$TMP/err" || fail "stderr '$(cat "$TMP/err")' does not match /$1/"
}

# expect_one_line_stderr: errors are one line.
expect_one_line_stderr() {
  local n; n=$(wc -l <"$TMP/err")
  [[ $n -eq 1 ]] || fail "stderr has $n lines, expected 1: $(cat "$TMP/err")"
}

finish() {
  if ((failures)); then echo "$failures check(s) failed" >&2; exit 1; fi
  echo "all checks passed"
}

# frames FILE.jsonl: "t drive pivot safety" per delivered frame.
frames() { python3 -c '
import json, sys
for l in open(sys.argv[1]):
    f = json.loads(l); s = f["signals"]
    print(f["t"], s["drive"], s["pivot"], s["safety"])' "$1"; }
