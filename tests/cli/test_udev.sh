# The udev rules: group + 0660 or uaccess, never world-writable; the symlink
# and ModemManager exclusion on every serial adapter line.
source "$(dirname "$0")/lib.sh"
rules=$(dirname "$0")/../../udev/70-andros-bridge.rules
[[ -f $rules ]] || fail "no udev rules"
grep -Eq 'MODE="0?666"' "$rules" && fail "a rule is world-writable"
grep -v '^#' "$rules" | grep -E 'MODE=' | grep -vq 'MODE="0660"' && fail "a MODE other than 0660"
serial=$(grep -c '^SUBSYSTEM=="tty"' "$rules")
[[ $serial -ge 4 ]] || fail "$serial serial adapter rules, expected FTDI, Prolific, CP210x, CH340"
for want in 'GROUP="dialout"' 'MODE="0660"' 'SYMLINK+="andros-switchbox"' 'ENV{ID_MM_DEVICE_IGNORE}="1"'; do
  n=$(grep '^SUBSYSTEM=="tty"' "$rules" | grep -cF "$want")
  [[ $n -eq $serial ]] || fail "$want on $n of $serial serial rules"
done
for vendor in 0403 067b 10c4 1a86; do grep -q "idVendor}==\"$vendor\"" "$rules" || fail "vendor $vendor"; done
grep -q 'ENV{ID_INPUT_JOYSTICK}=="1", TAG+="uaccess"' "$rules" || fail "no uaccess for controllers"
# Every rule line is KEY==VALUE / KEY=VALUE pairs separated by commas.
grep -v '^#' "$rules" | grep -v '^$' | grep -Ev '^([A-Za-z_{}]+(==|\+=|=)"[^"]*"(, |$))+$' && fail "a malformed rule line"
if command -v udevadm >/dev/null && udevadm verify --help >/dev/null 2>&1; then
  udevadm verify "$rules" >"$TMP/out" 2>&1 || fail "udevadm verify: $(cat "$TMP/out")"
fi
finish
