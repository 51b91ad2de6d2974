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
# The hidraw rules reach game pads only (issue 19, finding 12): the rules
# matched as udev does (KERNEL on the node; KERNELS and ATTRS together on one
# of its parents), over USB and Bluetooth; a vendor's keyboard, mouse or
# headset gets nothing. The service (group input) opens the pads too.
python3 - "$rules" >"$TMP/hidraw" 2>&1 <<'PY' || fail "hidraw rules: $(cat "$TMP/hidraw")"
import fnmatch, re, sys
rules = []
for line in open(sys.argv[1]):
    if line.startswith("#") or not line.strip():
        continue
    rules.append(re.findall(r'([A-Za-z_]+(?:\{[^}]*\})?)(==|\+=|=)"([^"]*)"', line))
def match(pattern, value):
    return value is not None and any(fnmatch.fnmatchcase(value, p) for p in pattern.split("|"))
def applies(rule, node, parents):
    own = [(k, v) for k, op, v in rule if op == "==" and not (k == "KERNELS" or k.startswith("ATTRS"))]
    up = [(k, v) for k, op, v in rule if op == "==" and (k == "KERNELS" or k.startswith("ATTRS"))]
    if not all(match(v, node.get(k)) for k, v in own):
        return False
    return not up or any(all(match(v, p.get(k)) for k, v in up) for p in parents)
def assigned(node, parents):
    got = {}
    for rule in rules:
        if applies(rule, node, parents):
            got.update({k: v for k, op, v in rule if op != "=="})
    return got
def usb(vendor, product):
    return [{"KERNELS": f"0003:{vendor.upper()}:{product.upper()}.0001"}, {"KERNELS": "1-1:1.0"},
            {"KERNELS": "1-1", "ATTRS{idVendor}": vendor, "ATTRS{idProduct}": product}]
def bluetooth(vendor, product):
    return [{"KERNELS": f"0005:{vendor.upper()}:{product.upper()}.0002"}, {"KERNELS": "hci0:256"}, {"KERNELS": "hci0"}]
pads = {"DualShock 4 (USB)": usb("054c", "05c4"), "DualShock 4 (Bluetooth)": bluetooth("054c", "05c4"),
        "DualSense (USB)": usb("054c", "0ce6"), "DualSense (Bluetooth)": bluetooth("054c", "0ce6"),
        "Switch Pro (USB)": usb("057e", "2009"), "Switch Pro (Bluetooth)": bluetooth("057e", "2009"),
        "Xbox Series pad (Bluetooth)": bluetooth("045e", "0b13"), "Steam Controller (USB)": usb("28de", "1102"),
        "Steam Deck": usb("28de", "1205")}
others = {"Microsoft keyboard (USB)": usb("045e", "07a5"), "Microsoft mouse (Bluetooth)": bluetooth("045e", "0916"),
          "Sony headset (USB)": usb("054c", "0ce7"), "Valve Index headset (USB)": usb("28de", "2000"),
          "Logitech keyboard (USB)": usb("046d", "c31c")}
bad = 0
for name, parents in pads.items():
    got = assigned({"KERNEL": "hidraw3", "SUBSYSTEM": "hidraw"}, parents)
    if got.get("TAG") != "uaccess" or got.get("GROUP") != "input" or got.get("MODE") != "0660":
        print(f"{name}: not given to the seat and group input: {got}"); bad += 1
for name, parents in others.items():
    got = assigned({"KERNEL": "hidraw3", "SUBSYSTEM": "hidraw"}, parents)
    if got:
        print(f"{name}: a hidraw device that is no pad gets {got}"); bad += 1
sys.exit(1 if bad else 0)
PY
# The service may write to the pads (rumble to evdev, light to hidraw), as SDL opens them.
unit=$(dirname "$0")/../../service/andros-bridge.service
grep -qx 'DeviceAllow=char-input rw' "$unit" || fail "the unit does not let the service write to evdev (rumble)"
grep -qx 'DeviceAllow=char-hidraw rw' "$unit" || fail "the unit does not let the service write to hidraw (light)"

if command -v udevadm >/dev/null && udevadm verify --help >/dev/null 2>&1; then
  udevadm verify "$rules" >"$TMP/out" 2>&1 || fail "udevadm verify: $(cat "$TMP/out")"
fi
finish
