# The hostile-input catalogue: one case per class of bad input, each run
# through the real binary, with its exact one-line error and exit code 2.
# (The loaders' own tests cover many more cases in-process; these pin what a
# user sees.)
source "$(dirname "$0")/lib.sh"
cd "$TMP"

# expect_error WANT_STDERR_LINE CMD...: exit 2 and exactly that one line (log lines aside).
expect_error() {
  local want=$1; shift
  run_cmd "$@"
  [[ $code -eq 2 ]] || fail "'$*' exited $code, expected 2"
  local got; got=$(grep -v '^info: ' "$TMP/err")
  [[ $got == "$want" ]] || fail "'$*': stderr was '$got', expected '$want'"
}

w() { printf "$2" >"$1"; }
printf '0 connect\n100 end\n' >ok.events
head='robot: HD1\ndeadman: leftshoulder\nbindings:\n'

# Mapping files.
w syntax.yaml "$head"'  - signal: tool_on\n    button: [a\n'
expect_error "syntax.yaml:6:1: error: YAML syntax: end of sequence flow not found" "$BIN" check syntax.yaml
w unknown_key.yaml 'robot: HD1\ndeadman: leftshoulder\ncentre: 128\n'
expect_error "unknown_key.yaml:3:1: error: unknown key 'centre' in a mapping file (expected robot, extends, center, constants, deadman, deadman_panic, estop, stop_reset, stop_reset_hold, enable_timeout, supervisor, brake, scale, feedback, bindings, layers)" "$BIN" check unknown_key.yaml
w unknown_signal.yaml "$head"'  - signal: front_art_upp\n    button: a\n'
expect_error "unknown_signal.yaml:4:13: error: unknown signal 'front_art_upp' (expected one of: $("$BIN" frame signals --json | sed 's/^{"name":"\([^"]*\)".*/\1/' | tr '\n' ' ' | sed 's/ $//'))" "$BIN" check unknown_signal.yaml
w unknown_input.yaml "$head"'  - signal: tool_on\n    button: trigger\n'
expect_error "unknown_input.yaml:5:13: error: unknown button 'trigger' (an SDL game-controller button such as a, leftshoulder, dpup; a joystick button number; or a hat direction such as hat0up)" "$BIN" check unknown_input.yaml
w out_of_range.yaml "$head"'  - analog: drive\n    axis: lefty\n    deadzone: 1.5\n'
expect_error "out_of_range.yaml:6:15: error: deadzone 1.5 is out of range 0..1 (excluded)" "$BIN" check out_of_range.yaml
w duplicate.yaml "$head"'  - signal: tool_on\n    button: a\n  - signal: zoom_up\n    button: a\n'
expect_error "duplicate.yaml:7:13: error: 'a' is bound twice in this layer (first at line 5)" "$BIN" check duplicate.yaml
w unarmed.yaml "$head"'  - signal: weapon_1\n    button: b\n'
expect_error "unarmed.yaml:4:5: error: weapon binding for 'weapon_1' needs 'arm': a second button held to fire" "$BIN" check unarmed.yaml
w cycle_a.yaml 'robot: HD1\ndeadman: leftshoulder\nextends: cycle_b.yaml\n'
w cycle_b.yaml 'extends: cycle_a.yaml\n'
expect_error "cycle_b.yaml:1:10: error: 'extends' makes a cycle: cycle_a.yaml -> cycle_b.yaml -> cycle_a.yaml" "$BIN" check cycle_a.yaml
w missing_base.yaml 'robot: HD1\nextends: nowhere.yaml\n'
expect_error "missing_base.yaml:2:10: error: cannot open mapping file 'nowhere.yaml': No such file or directory" "$BIN" check missing_base.yaml
expect_error "missing_base.yaml:2:10: error: cannot open mapping file 'nowhere.yaml': No such file or directory" "$BIN" replay ok.events --mapping missing_base.yaml

# Event scripts.
w unknown_event.events '0 connect\n10 jump\n'
expect_error "unknown_event.events:2:4: error: unknown event 'jump' (expected connect, disconnect, button, axis, hat, end, link, suspend, resume, reload, stop or supervisor)" "$BIN" replay unknown_event.events --robot hd1
w backwards.events '0 connect\n100 button a 1\n50 button a 0\n'
expect_error "backwards.events:3:1: error: time 50 ms goes backwards (previous event at 100 ms)" "$BIN" replay backwards.events --robot hd1
w button.events '0 connect\n1 button trigger 1\n'
expect_error "button.events:2:10: error: unknown button 'trigger'" "$BIN" replay button.events --robot hd1
w axis.events '0 connect\n1 axis leftz 0\n'
expect_error "axis.events:2:8: error: unknown axis 'leftz'" "$BIN" replay axis.events --robot hd1
w range.events '0 connect\n1 axis leftx 40000\n'
expect_error "range.events:2:14: error: axis value 40000 is out of range -32768..32767" "$BIN" replay range.events --robot hd1
expect_error "range.events:2:14: error: axis value 40000 is out of range -32768..32767" "$BIN" run --input range.events

# Configuration files.
w baud.conf 'baudrate=9601\n'
expect_error "baud.conf:1:10: error: baud 9601 is not one of 9600, 19200, 38400, 57600, 115200" "$BIN" run --config baud.conf --input ok.events
w robot.conf '# legacy file\nrobot=HD2\n'
expect_error "robot.conf:2:7: error: unknown robot 'HD2' (one of F6A, VA1, WOLVERINE, HD1, PROWLER, RAV, RONS)" "$BIN" run --config robot.conf --input ok.events
w code.conf 'code=1FF\n'
expect_error "code.conf:1:6: error: code '1FF' is not a byte in hex (one or two hex digits, e.g. 01 or 3C)" "$BIN" run --config code.conf --input ok.events
w twice.conf 'weapons=disabled\nrobot=hd1\n  Weapons=enabled\n'  # never "last wins"
expect_error "twice.conf:3:3: error: key 'weapons' given twice (first at line 1)" "$BIN" run --config twice.conf --input ok.events
w key.conf 'serialprot=/dev/ttyUSB0\n'
expect_error "key.conf:1:1: error: unknown key 'serialprot' (known: baudrate, serialport, robot, code, rate, mapping, weapons, input, supervisor, record, record_dir, record_max_mb, record_max_days)" "$BIN" run --config key.conf --input ok.events
w noeq.conf 'baudrate 9600\n'
expect_error "noeq.conf:1:1: error: expected key=value, got 'baudrate 9600'" "$BIN" run --config noeq.conf --input ok.events
w rate.conf 'rate=-1920099999999999980\n'
expect_error "rate.conf:1:6: error: rate '-1920099999999999980' is not a number of Hz (such as 25 or 12.5, at most 3 decimals)" "$BIN" run --config rate.conf --input ok.events
w port_file.conf 'serialport=/etc/passwd\n'
expect_error "port_file.conf:1:12: error: serial port '/etc/passwd' is not a serial device (a regular file)" "$BIN" run --config port_file.conf --input ok.events
mkdir -p notatty
w port_dir.conf "serialport=$TMP/notatty\n"
expect_error "port_dir.conf:1:12: error: serial port '$TMP/notatty' is not a serial device (a directory)" "$BIN" run --config port_dir.conf --input ok.events
expect_error "--port: error: serial port '/etc/passwd/x': Not a directory" "$BIN" run --port /etc/passwd/x --input ok.events
expect_error "missing.conf: error: cannot read the config file: No such file or directory" "$BIN" run --config missing.conf --input ok.events

# Command-line flags.
expect_error "andros-bridge: error: The following argument was not expected: --bogus (see --help)" "$BIN" run --bogus
expect_error "--rate: error: rate '0' is below 1 Hz" "$BIN" run --rate 0 --input ok.events
expect_error "--rate: error: rate 'abc' is not a number of Hz (such as 25 or 12.5, at most 3 decimals)" "$BIN" run --rate abc --input ok.events
expect_error "--code: error: code 'XYZ' is not a byte in hex (one or two hex digits, e.g. 01 or 3C)" "$BIN" run --code XYZ --input ok.events
expect_error "--robot: error: unknown robot 'hd2' (one of F6A, VA1, WOLVERINE, HD1, PROWLER, RAV, RONS)" "$BIN" run --robot hd2 --input ok.events
expect_error "--baud: error: baud 9601 is not one of 9600, 19200, 38400, 57600, 115200" "$BIN" run --baud 9601 --input ok.events
expect_error "andros-bridge: error: EVENTS is required (see --help)" "$BIN" replay
expect_error "--format: error: format 'xml' is not one of hex, raw, jsonl" "$BIN" replay ok.events --format xml
expect_error "andros-bridge: error: replay: give --robot or --mapping, not both" "$BIN" replay ok.events --robot hd1 --mapping x.yaml
expect_error "andros-bridge: error: frame encode: expected 32 hex digits (16 data bytes), got 2 characters" "$BIN" frame encode 12
# An output that cannot be made is exit 1 as for every command's --output (docs/running.md, Output files).
expect_exit 1 "$BIN" record --output /nonexistent/dir/x.events
expect_stderr_matches "^andros-bridge: error: cannot open '/nonexistent/dir/x.events' for writing: No such file or directory$"
# Empty values, a device that is not a terminal, directories (each once fell back, retried for ever or exited 1).
expect_error "--mapping: error: empty value (give one, or leave the option out)" timeout 20 "$BIN" run --mapping "" --input ok.events
expect_error "--config: error: empty value (give one, or leave the option out)" timeout 20 "$BIN" run --config "" --input ok.events
expect_error "--mapping: error: empty value (give one, or leave the option out)" "$BIN" replay ok.events --mapping ""
expect_error "--output: error: empty value (give one, or leave the option out)" "$BIN" replay ok.events --output ""
expect_error "--code: error: empty value (give one, or leave the option out)" "$BIN" frame decode --code "" ok.events
expect_error "--port: error: serial port '/dev/null' is not a serial device (a character device that is not a terminal)" timeout 20 "$BIN" run --port /dev/null --input ok.events
mkdir -p adir
expect_error "adir: error: is a directory, not a capture file" "$BIN" frame decode adir
expect_error "adir: error: is a directory, not a port or a capture file" timeout 20 "$BIN" monitor adir

# More mapping files: the bounds of docs/mapping.md.
w second_doc.yaml 'robot: HD1\ndeadman: leftshoulder\n---\nrobot: F6A\n'
expect_error "second_doc.yaml:4:1: error: a second YAML document ('---'): a mapping file holds one" "$BIN" check second_doc.yaml
w comma.yaml ',extends: x.yaml\n'  # once read for ever, memory growing (a fuzz finding)
expect_error "comma.yaml:1:1: error: YAML syntax: unexpected ','" timeout 20 "$BIN" check comma.yaml
w position.yaml "$head"'  - selector: cam\n    next: a\n    positions: [[main_video_2, main_video_3, main_video_2], []]\n'
expect_error "position.yaml:6:46: error: 'main_video_2' is given twice in this position" "$BIN" check position.yaml
for i in $(seq 0 19); do w "deep$i.yaml" "extends: deep$((i + 1)).yaml\n"; done
w deep20.yaml 'bindings: []\n'
expect_error "deep15.yaml:1:10: error: 'extends' chain too long: this base would be file 17 of the chain from 'deep0.yaml' (at most 16 files)" "$BIN" check deep0.yaml
{ printf "$head"'  - selector: cam\n    next: a\n    positions:\n      - &p [main_video_2'
  for _ in $(seq 1000); do printf ',\n        main_video_2'; done; printf ']\n'
  yes '      - *p' | head -80000; } >bomb.yaml  # under the 1 MiB and 4 KiB-line bounds, ~80 million nodes
expect_error "bomb.yaml:7:9: error: the mapping is too large: more than 100000 YAML nodes in this file and the files it extends, counting each alias as a copy of what it names (docs/mapping.md)" timeout 20 "$BIN" check bomb.yaml

# User text in an error is quoted: printable ASCII as is, other bytes (a NUL, a BOM) as \xNN, long text cut short.
printf '0 conn\0ect\n' >nul.events
expect_error "nul.events:1:3: error: unknown event 'conn\\x00ect' (expected connect, disconnect, button, axis, hat, end, link, suspend, resume, reload, stop or supervisor)" "$BIN" replay nul.events
printf '0 %s\n' "$(printf 'x%.0s' $(seq 100))" >long.events
expect_error "long.events:1:3: error: unknown event '$(printf 'x%.0s' $(seq 64))'... (100 bytes) (expected connect, disconnect, button, axis, hat, end, link, suspend, resume, reload, stop or supervisor)" "$BIN" replay long.events
printf '\xEF\xBB\xBFbaudrate=9600\n' >bom.conf
expect_error "bom.conf:1:1: error: unknown key '\\xEF\\xBB\\xBFbaudrate' (known: baudrate, serialport, robot, code, rate, mapping, weapons, input, supervisor, record, record_dir, record_max_mb, record_max_days)" "$BIN" run --config bom.conf --input ok.events
w nul.yaml "$head"'  - signal: "tool\\0on"\n    button: a\n'
expect_error "nul.yaml:4:13: error: unknown signal 'tool\\x00on' (expected one of: $("$BIN" frame signals --json | sed 's/^{"name":"\([^"]*\)".*/\1/' | tr '\n' ' ' | sed 's/ $//'))" "$BIN" check nul.yaml
w bom_robot.yaml 'robot: \xEF\xBB\xBFHD1\ndeadman: a\n'
expect_error "bom_robot.yaml:1:8: error: unknown robot '\\xEF\\xBB\\xBFHD1' (expected F6A, VA1, WOLVERINE, HD1, PROWLER, RAV, RONS)" "$BIN" check bom_robot.yaml
expect_error "--robot: error: unknown robot '\\xEF\\xBB\\xBFhd1' (one of F6A, VA1, WOLVERINE, HD1, PROWLER, RAV, RONS)" "$BIN" run --robot $'\xEF\xBB\xBFhd1' --input ok.events

# A controller's name is one line of printable text: as record writes a name
# holding event lines (escaped), it is one connect line and nothing enables;
# a raw control byte in a name is refused.
printf '0 connect Gamepad\\n500 button leftshoulder 0\\n600 button leftshoulder 1\\n700 axis lefty -32768\\n\\x23\n1000 end\n' >hostile_name.events
printf '0 connect pad\n1000 end\n' >plain.events
expect_exit 0 "$BIN" replay hostile_name.events
cp "$TMP/out" hostile.frames
expect_exit 0 "$BIN" replay plain.events
cmp -s "$TMP/out" hostile.frames || fail "a controller's name changed the frames: $(diff "$TMP/out" hostile.frames | head -3)"
printf '0 connect pad\0name\n100 end\n' >nul_name.events
expect_error "nul_name.events:1:11: error: controller name 'pad\\x00name' is not one line of printable text (a control byte or invalid UTF-8 is written \\xNN)" "$BIN" replay nul_name.events

# Output that cannot be written (a full disk) is exit 1 with one line, not a silent exit 0.
expect_full() {
  "$@" >/dev/full 2>"$TMP/err"
  local code=$?
  [[ $code -eq 1 ]] || fail "'$*' >/dev/full exited $code, expected 1"
  grep -qE '(standard output: (No space left on device|write error)|stdout: write error|cannot write the event script)$' "$TMP/err" ||
    fail "'$*' >/dev/full: stderr was '$(cat "$TMP/err")'"
}
zero=00000000000000000000000000000000
"$BIN" frame encode --raw 00001C2000907F7E3E0000FFFF20CC02 >capture.bin
expect_full "$BIN" frame encode $zero
expect_full "$BIN" frame encode --raw $zero
expect_full "$BIN" frame decode capture.bin
expect_full "$BIN" frame signals
expect_full "$BIN" check "$DATA/mappings/core.yaml"
expect_full "$BIN" monitor capture.bin
expect_full "$BIN" replay ok.events
expect_full env SDL_VIDEODRIVER=dummy timeout 20 "$BIN" record -o -
finish
