#!/usr/bin/env bash
# The generated man pages and bash completion (build/man/, scripts/man/):
# every page renders without a groff warning, andros-bridge(1) names every
# command and every option the program has, and the completion completes
# commands, flags, robots, fixed values, ports and files.
source "$(dirname "$0")/lib.sh"
MAN=$(dirname "$BIN")/../man
[[ -d $MAN ]] || { echo "FAIL: no generated pages in $MAN (python3 missing at configure time?)"; exit 1; }

for page in andros-bridge.1 andros-bridge.conf.5 andros-bridge-mapping.5 andros-bridge-events.5; do
  [[ -s $MAN/$page ]] || { fail "$page was not generated"; continue; }
  warnings=$(groff -man -Tutf8 -ww -z "$MAN/$page" 2>&1)
  [[ -z $warnings ]] || fail "$page: groff warns: $warnings"
done

# Every command and every long option of help-data is in andros-bridge(1).
text=$(groff -man -Tutf8 -P-c -P-b -P-u "$MAN/andros-bridge.1" 2>/dev/null)
"$BIN" help-data >"$TMP/help.json" || fail "help-data failed"
python3 - "$TMP/help.json" >"$TMP/expected" <<'PY'
import json, sys
def walk(cmd, path):
    for o in cmd["options"]:
        for n in o["names"]:
            if n != "help": print(" ".join(path) + "\t--" + n)
    for s in cmd["commands"]:
        print(" ".join(path + [s["name"]]) + "\t")
        walk(s, path + [s["name"]])
walk(json.load(open(sys.argv[1])), ["andros-bridge"])
PY
[[ $(wc -l <"$TMP/expected") -gt 30 ]] || fail "help-data lists too little: $(wc -l <"$TMP/expected") lines"
while IFS=$'\t' read -r path flag; do
  grep -qF -- "$path" <<<"$text" || fail "andros-bridge(1) has no section for '$path'"
  [[ -z $flag ]] || grep -qF -- "$flag" <<<"$text" || fail "andros-bridge(1) does not name $flag of '$path'"
done <"$TMP/expected"
grep -q "WOLVERINE" <<<"$text" || fail "andros-bridge(1) does not list the robot types"
# andros-bridge.conf(5) describes every key of the settings table, and
# docs/running.md's table of keys lists exactly those.
conf=$(groff -man -Tutf8 -P-c -P-b -P-u "$MAN/andros-bridge.conf.5" 2>/dev/null)
keys=$(python3 -c 'import json,sys; print(" ".join(r["key"] for r in json.load(open(sys.argv[1]))["config_keys"]))' "$TMP/help.json")
[[ $(wc -w <<<"$keys") -ge 8 ]] || fail "help-data lists too few config keys: $keys"
for key in $keys; do
  grep -q "^ *$key=" <<<"$conf" || fail "andros-bridge.conf(5) does not describe the key $key"
done
docs_keys=$(sed -n '/^## The configuration file/,/^## /p' "$(dirname "$0")/../../docs/running.md" |
  sed -n 's/^| `\([a-z_]*\)` |.*/\1/p' | tr '\n' ' ')
[[ $docs_keys == "$keys " ]] || fail "docs/running.md lists the keys '$docs_keys', the program '$keys'"

# complete WORDS...: what the completion offers for the last word.
complete_words() {
  bash -c 'source "$1"; shift; COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1)); _andros_bridge; printf "%s\n" "${COMPREPLY[@]}"' \
    _ "$MAN/andros-bridge.bash" "$@"
}
expect_offers() {  # WANTED WORDS...: WANTED is among the offers
  local want=$1; shift
  local offers; offers=$(complete_words "$@")  # whole, then searched: grep -q on a pipe would cut it short (SIGPIPE)
  grep -qxF -- "$want" <<<"$offers" || fail "completing '$*' does not offer '$want': $(tr '\n' ' ' <<<"$offers")"
}
expect_not_offered() {
  local unwanted=$1; shift
  local offers; offers=$(complete_words "$@")
  ! grep -qxF -- "$unwanted" <<<"$offers" || fail "completing '$*' offers '$unwanted'"
}
expect_offers run andros-bridge r
expect_offers replay andros-bridge r
expect_not_offered help-data andros-bridge h
expect_offers --robot andros-bridge run --r
expect_offers HD1 andros-bridge run --robot H
expect_offers wolverine andros-bridge replay --robot w
expect_offers sim andros-bridge run --port s
expect_offers tcp: andros-bridge run --port t
expect_offers sdl andros-bridge run --input s
expect_offers encode andros-bridge frame e
expect_offers --raw andros-bridge frame encode --r
touch "$TMP/drive.events"
expect_offers "$TMP/drive.events" andros-bridge replay "$TMP/dr"
expect_offers --weapons andros-bridge run --robot hd1 --w
expect_offers jsonl andros-bridge replay --format j
expect_offers text andros-bridge sheet --format t
exit $((failures > 0))
