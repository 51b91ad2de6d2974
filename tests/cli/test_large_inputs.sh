# Large inputs finish, exit as they should, and stay in bounded memory: the
# peak RSS with a large input is compared with the same command on a tiny
# one, so the check holds under sanitizers too.
source "$(dirname "$0")/lib.sh"

# peak_kb CMD...: runs CMD (stdout discarded), prints its peak RSS in KiB; exit code in $TMP/code.
# Under AddressSanitizer freed memory waits in a quarantine (256 MB by default)
# before reuse: a small one keeps the measure about the program, not ASan.
# peak_kb CMD...: runs it, keeping stdout in $TMP/out and stderr in $TMP/err
# (as run_cmd does) and its exit code in $TMP/code; prints its peak RSS in KiB.
peak_kb() {
  python3 - "$TMP" "$@" <<'PY'
import os, resource, subprocess, sys
tmp = sys.argv[1]
env = dict(os.environ)
env["ASAN_OPTIONS"] = ":".join(filter(None, [env.get("ASAN_OPTIONS"), "quarantine_size_mb=1"]))
with open(os.path.join(tmp, "out"), "wb") as out, open(os.path.join(tmp, "err"), "wb") as err:
    code = subprocess.call(sys.argv[2:], stdout=out, stderr=err, env=env)
open(os.path.join(tmp, "code"), "w").write(str(code))
print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)
PY
}

# expect_bounded NAME LIMIT_KB WANT_CODE SMALL_CMD... -- LARGE_CMD...
expect_bounded() {
  local name=$1 limit=$2 want=$3; shift 3
  local small=() large=()
  while [[ $1 != -- ]]; do small+=("$1"); shift; done
  shift
  large=("$@")
  local small_kb large_kb
  small_kb=$(peak_kb "${small[@]}")
  large_kb=$(peak_kb "${large[@]}")
  code=$(cat "$TMP/code")  # the large input's run: its output stays in $TMP/out and $TMP/err
  [[ $code -eq $want ]] || fail "$name: exit $code, expected $want"
  (( large_kb - small_kb < limit )) ||
    fail "$name: peak RSS grew by $((large_kb - small_kb)) KiB over a tiny input (limit $limit KiB)"
  echo "$name: peak RSS $small_kb KiB small, $large_kb KiB large"
}

# A 100 MB capture of random bytes with good frames sprinkled in.
python3 - "$TMP/big.bin" <<'PY'
import os, sys
frame = bytes.fromhex("F1F13030303031433230303039303746374533453030303046464646323043433032F206")
with open(sys.argv[1], "wb") as f:
    for _ in range(100):
        f.write(os.urandom(1_000_000 - 36 * 10) + frame * 10)
PY
head -c 1000 "$TMP/big.bin" >"$TMP/small.bin"
expect_bounded "decode 100 MB capture" 16384 0 \
  "$BIN" frame decode "$TMP/small.bin" -- "$BIN" frame decode "$TMP/big.bin"
expect_stderr_matches '^frames: [0-9]+, valid: 1000, '

# A million-line event script: the deadman pumped, a stick swept.
python3 - "$TMP/long.events" <<'PY'
import sys
with open(sys.argv[1], "w") as f:
    f.write("0 connect Big Pad\n")
    t = 1
    for i in range(499_999):
        f.write(f"{t} button leftshoulder {i % 2}\n{t} axis lefty {(i * 131) % 65536 - 32768}\n")
        t += 1
    f.write(f"{t} end\n")
PY
printf '0 connect\n100 end\n' >"$TMP/short.events"
expect_bounded "replay 1,000,000-line script" 16384 0 \
  "$BIN" replay "$TMP/short.events" --robot hd1 -- "$BIN" replay "$TMP/long.events" --robot hd1
[[ $(wc -l <"$TMP/out") -eq 12501 ]] || fail "million-line replay wrote $(wc -l <"$TMP/out") frames, expected 12501"

# A 1 MB mapping: rejected (an input bound twice) with the line, in bounded memory.
python3 - "$TMP/big.yaml" <<'PY'
import sys
with open(sys.argv[1], "w") as f:
    f.write("robot: HD1\ndeadman: leftshoulder\nbindings:\n")
    while f.tell() < 1_000_000:
        f.write("  - signal: front_art_up   # " + "x" * 60 + "\n    button: dpup\n")
PY
expect_bounded "check 1 MB mapping" 262144 2 \
  "$BIN" check "$TMP/short.events" -- "$BIN" check "$TMP/big.yaml"
expect_stderr_matches 'big.yaml:[0-9]+:[0-9]+: error: '
finish
