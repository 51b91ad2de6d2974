#!/usr/bin/env python3
"""Runs `run` with its stdout on a pseudo-terminal of a given size and checks the screens it draws.

  screen_tty.py BIN DATA [--weapons] [--no-color]

At 80x24: the header lines first, in order (a line too long wraps under
itself), none longer than the width, never
more lines than rows; colour codes only without NO_COLOR. Then the terminal
shrinks to 40x12: the next screens fit it. Every wait is bounded.
"""
import fcntl, os, pty, re, select, signal, struct, subprocess, sys, termios, time

ESCAPE = re.compile(rb"\x1b\[[0-9;?]*[A-Za-z]")


def set_size(fd, cols, rows):
    fcntl.ioctl(fd, termios.TIOCSWINSZ, struct.pack("HHHH", rows, cols, 0, 0))


def screens(data):
    """The whole screens drawn so far (the last may still be arriving), each as its plain lines."""
    out = []
    for chunk in data.split(b"\x1b[H")[1:-1]:
        text = ESCAPE.sub(b"", chunk).replace(b"\r", b"").decode("utf-8", "replace")
        out.append(text.rstrip("\n").split("\n"))
    return out


def main():
    bin_, data = sys.argv[1:3]
    weapons, no_color = "--weapons" in sys.argv, "--no-color" in sys.argv
    master, slave = pty.openpty()
    set_size(slave, 80, 24)
    env = dict(os.environ, TERM="xterm-256color")
    env.pop("NO_COLOR", None)
    if no_color:
        env["NO_COLOR"] = "1"
    argv = [bin_, "run", "--port", "sim", "--input", f"{data}/live/long_drive.events"] + (["--weapons"] if weapons else [])
    proc = subprocess.Popen(argv, stdout=slave, stderr=subprocess.DEVNULL, stdin=subprocess.DEVNULL, env=env)
    out = bytearray()

    def read_until(done, timeout):
        end = time.monotonic() + timeout
        while time.monotonic() < end and not done():
            if select.select([master], [], [], 0.05)[0]:
                out.extend(os.read(master, 65536))

    problems = []
    # Two screens after the state says ENABLED (the script presses the deadman afresh at 1.5 s).
    read_until(lambda: sum("ENABLED" in " ".join(s) for s in screens(bytes(out))) >= 2, 15)
    full = [s for s in screens(bytes(out)) if "ENABLED" in " ".join(s)]
    if not full:
        problems.append("no screen with ENABLED")
        full = [[""]]
    screen = full[-1]
    want = ["andros-bridge run  robot HD1  code 01  ", "state       ENABLED", "link        sim vehicle on ",
            "controller  ", "mapping     "]
    if weapons:
        want.insert(0, "")
        if "WEAPONS ENABLED" not in screen[0]:
            problems.append("no WEAPONS ENABLED banner on the first line")
    elif any("WEAPONS" in line for line in screen):
        problems.append("a WEAPONS banner without --weapons")
    # A line too long for the terminal wraps under itself: its continuations
    # (indented) are not header lines.
    heads = [line for i, line in enumerate(screen) if (weapons and i == 0) or not line.startswith(" ")]
    for i, prefix in enumerate(want):
        if i >= len(heads) or not heads[i].startswith(prefix):
            problems.append(f"header line {i} does not start with {prefix!r}")
    if not heads[len(want) - 1].endswith("hd1.yaml"):
        problems.append("the mapping line does not end with the file's name")
    if len(screen) > 24 or any(len(line) > 79 for line in screen):
        problems.append("the screen does not fit 80x24 (one column left for the cursor)")
    coloured = re.search(rb"\x1b\[[0-9;]*m", bytes(out)) is not None
    if coloured == no_color:
        problems.append(f"colour codes {'with' if coloured else 'without'} NO_COLOR")
    shown = "\n".join(screen)

    # Resized: the next screens fit the new size, and the header's first lines stay on top.
    set_size(slave, 40, 12)
    mark = len(out)
    read_until(lambda: len(screens(bytes(out[mark:]))) >= 3, 10)
    small = screens(bytes(out[mark:]))
    if len(small) < 3:
        problems.append("no screens after the resize")
    else:
        last = small[-1]
        if len(last) > 12 or any(len(line) > 39 for line in last):
            problems.append("a screen after the resize does not fit 40x12:\n" + "\n".join(last))
        if not (last[1 if weapons else 0].startswith("andros-bridge run") and any(l.startswith("state ") for l in last)):
            problems.append("the header is not on top after the resize:\n" + "\n".join(last))
    proc.send_signal(signal.SIGTERM)
    try:
        code = proc.wait(10)
    except subprocess.TimeoutExpired:
        proc.kill()
        code = "killed"
    if code != 0:
        problems.append(f"exit {code}")
    for p in problems:
        print("FAIL:", p)
    if problems:
        print(shown)
    sys.exit(1 if problems else 0)


main()
