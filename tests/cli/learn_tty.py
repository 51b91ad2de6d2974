#!/usr/bin/env python3
"""Runs `andros-bridge learn` on a pseudo-terminal as its keyboard.

  learn_tty.py KEYS|--term -- CMD ...

Waits for the first prompt, then types KEYS (Python escapes: '\\x03' is
Ctrl-C) or, with --term, sends SIGTERM. Prints what the program wrote and
exits with its exit code, or 3 when the terminal's settings after it ended
differ from before it started (it must restore them), 124 on a timeout.
"""
import os, pty, select, signal, subprocess, sys, termios, time


def main():
    split = sys.argv.index("--")
    what, cmd = sys.argv[1], sys.argv[split + 1:]
    master, slave = pty.openpty()
    before = termios.tcgetattr(slave)
    proc = subprocess.Popen(cmd, stdin=slave, stdout=slave, stderr=slave, start_new_session=True)
    out = bytearray()
    deadline = time.monotonic() + 20
    sent = False
    while time.monotonic() < deadline and proc.poll() is None:
        r, _, _ = select.select([master], [], [], 0.05)
        if r:
            out += os.read(master, 4096)
        if not sent and b"(Enter keeps" in out:
            if what == "--term":
                proc.send_signal(signal.SIGTERM)
            else:
                os.write(master, what.encode().decode("unicode_escape").encode("latin-1"))
            sent = True
    if proc.poll() is None:
        proc.kill()
        proc.wait()
        sys.stdout.write(out.decode(errors="replace"))
        return 124
    while select.select([master], [], [], 0.1)[0]:
        try:
            out += os.read(master, 4096)
        except OSError:
            break
    sys.stdout.write(out.decode(errors="replace"))
    if termios.tcgetattr(slave) != before:
        print("terminal settings not restored", file=sys.stderr)
        return 3
    return proc.returncode


if __name__ == "__main__":
    sys.exit(main())
