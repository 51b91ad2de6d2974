# `check FILE...`: ok per good file on stdout, errors on stderr, exit 2 if any is bad.
source "$(dirname "$0")/lib.sh"

shipped="$DATA/../../mappings"
expect_exit 0 "$BIN" check "$shipped"/*.yaml
[[ $(grep -c ': ok' "$TMP/out") -eq 8 ]] || fail "shipped: $(cat "$TMP/out")"
grep -q "hd1.yaml: ok$" "$TMP/out" || fail "hd1 line: $(cat "$TMP/out")"
grep -q "common.yaml: ok (a base mapping: no robot)$" "$TMP/out" || fail "common line"
[[ -s "$TMP/err" ]] && fail "stderr on success: $(cat "$TMP/err")"

printf 'robot: HD1\ndeadman: leftshoulder\nbindings:\n  - signal: tool_on\n    button: a\n  - signal: zoom_up\n    button: a\n' >"$TMP/twice.yaml"
printf 'robot: HD1\ndeadman: leftshoulder\nbindings:\n  - signal: weapon_3\n    button: a\n' >"$TMP/unarmed.yaml"
expect_exit 2 "$BIN" check "$shipped/hd1.yaml" "$TMP/twice.yaml" "$TMP/unarmed.yaml"
grep -q "hd1.yaml: ok$" "$TMP/out" || fail "good file among bad ones: $(cat "$TMP/out")"
[[ $(wc -l <"$TMP/err") -eq 2 ]] || fail "two errors expected: $(cat "$TMP/err")"
expect_stderr_matches "twice.yaml:7:13: error: 'a' is bound twice in this layer \(first at line 5\)"
expect_stderr_matches "unarmed.yaml:4:5: error: weapon binding for 'weapon_3' needs 'arm'"

# A stick on drive with no deadzone loads, with a warning: after an enable it
# acts only once it reads exactly 0 (the rest rule, docs/mapping.md).
printf 'robot: HD1\ndeadman: leftshoulder\nbindings:\n  - analog: drive\n    axis: lefty\n  - analog: pivot\n    axis: leftx\n    deadzone: 0.1\n' >"$TMP/nodz.yaml"
expect_exit 0 "$BIN" check "$TMP/nodz.yaml"
grep -q "nodz.yaml: ok$" "$TMP/out" || fail "no ok line: $(cat "$TMP/out")"
[[ $(wc -l <"$TMP/err") -eq 1 ]] || fail "one warning expected: $(cat "$TMP/err")"
expect_stderr_matches "nodz.yaml:4:5: warning: no deadzone on the stick driving 'drive'"

# Speed levels (docs/mapping.md, `scale`): a good one loads over the shipped
# layout on guide once the stop moves off it (a paddle); a bad one is one line
# at its FILE:LINE:COL, exit 2.
printf 'robot: HD1\nextends: %s/common.yaml\nestop: paddle1\nscale: {button: guide, levels: [0.25, 0.5, 1.0]}\n' "$shipped" >"$TMP/speed.yaml"
expect_exit 0 "$BIN" check "$TMP/speed.yaml"
printf 'robot: HD1\nextends: %s/common.yaml\nscale: {button: guide, levels: [0.25, 0.5, 1.0]}\n' "$shipped" >"$TMP/onstop.yaml"
expect_exit 2 "$BIN" check "$TMP/onstop.yaml"
expect_stderr_matches "onstop.yaml:3:17: error: 'guide' is the stop button \\(line [0-9]+ of [^)]*/common.yaml\\); it cannot also step the speed level"
printf 'robot: HD1\nextends: %s/common.yaml\nscale: {button: dpup, levels: [0.5, 0.25]}\n' "$shipped" >"$TMP/slow.yaml"
expect_exit 2 "$BIN" check "$TMP/slow.yaml"
[[ $(wc -l <"$TMP/err") -eq 1 ]] || fail "one error expected: $(cat "$TMP/err")"
expect_stderr_matches "slow.yaml:3:37: error: levels go from the slowest to the fastest: 0.25 is not above the one before it"
printf 'robot: HD1\nextends: %s/common.yaml\nscale: {button: dpup, levels: [0.25, 1]}\n' "$shipped" >"$TMP/taken.yaml"
expect_exit 2 "$BIN" check "$TMP/taken.yaml"
expect_stderr_matches "taken.yaml:3:17: error: 'dpup' steps the speed level in every layer; it is also bound at line [0-9]+ of .*common.yaml"

expect_exit 2 "$BIN" check "$TMP/missing.yaml"
expect_stderr_matches "missing.yaml: error: cannot open mapping file"
expect_exit 2 "$BIN" check
expect_exit 0 "$BIN" check --help
finish
