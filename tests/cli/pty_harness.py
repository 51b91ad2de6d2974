#!/usr/bin/env python3
"""Runs a command against a pseudo-terminal standing in for the switchbox port.

  pty_harness.py CAPTURE [options] -- CMD ...    ({PTY} in CMD is replaced by the port's path)

The port is a symlink in a temporary directory pointing at a pty, as a udev
symlink points at a USB adapter. Everything the command writes is captured to
CAPTURE (and CAPTURE.2 after a replug). Every wait is bounded; the script
exits with the command's exit code, or 124 when it did not finish in time.

  --replug-after N   after N frames: close the pty (unplug), remove the link,
                     open a new pty and point the link at it (replug)
  --term-after N     after N frames (on the current pty): send SIGTERM
  --driving          count only frames with drive != 128 for --term-after
  --timeout S        give up after S seconds (default 20)
  --link PATH        where to put the symlink (default: a temporary directory)
"""
import argparse, os, pty, select, signal, subprocess, sys, tempfile, time, tty


def frames_in(buf):
    """Count whole frames with a good checksum; return (count, driving_count)."""
    n = driving = 0
    i = 0
    while True:
        i = buf.find(b"\xf1\xf1", i)
        if i < 0 or i + 36 > len(buf):
            return n, driving
        digits = buf[i + 2:i + 34]
        if sum(digits) & 0xFFFF == buf[i + 34] | buf[i + 35] << 8:
            n += 1
            try:
                if int(digits[14:16], 16) != 128:
                    driving += 1
            except ValueError:
                pass
            i += 36
        else:
            i += 1


def open_pty():
    master, slave = pty.openpty()
    tty.setraw(master)
    return master, slave, os.ttyname(slave)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("capture")
    ap.add_argument("--replug-after", type=int)
    ap.add_argument("--term-after", type=int)
    ap.add_argument("--driving", action="store_true")
    ap.add_argument("--timeout", type=float, default=20)
    ap.add_argument("--link")
    split = sys.argv.index("--")
    a = ap.parse_args(sys.argv[1:split])
    cmd = sys.argv[split + 1:]

    tmp = None if a.link else tempfile.mkdtemp(prefix="andros-pty-")
    link = a.link or os.path.join(tmp, "andros-switchbox")
    master, slave, path = open_pty()
    os.symlink(path, link)
    proc = subprocess.Popen([c.replace("{PTY}", link) for c in cmd])
    captures = [bytearray()]
    deadline = time.monotonic() + a.timeout
    replugged = termed = False
    exit_code = None
    while time.monotonic() < deadline:
        r, _, _ = select.select([master], [], [], 0.05)
        if r:
            try:
                captures[-1] += os.read(master, 4096)
            except OSError:
                pass
        n, driving = frames_in(bytes(captures[-1]))
        if a.replug_after and not replugged and n >= a.replug_after:
            os.close(master)
            os.close(slave)
            os.unlink(link)
            master, slave, path = open_pty()
            os.symlink(path, link)
            captures.append(bytearray())
            replugged = True
            continue
        count = driving if a.driving else n
        if a.term_after and not termed and count >= a.term_after and (replugged or not a.replug_after):
            proc.send_signal(signal.SIGTERM)
            termed = True
        if exit_code is None and proc.poll() is not None:
            exit_code = proc.returncode
            # Whatever is still in flight: read until the line is quiet.
            while select.select([master], [], [], 0.2)[0]:
                try:
                    data = os.read(master, 4096)
                except OSError:
                    break
                if not data:
                    break
                captures[-1] += data
            break
    if exit_code is None:
        proc.kill()
        proc.wait()
        exit_code = 124
    with open(a.capture, "wb") as f:
        f.write(captures[0])
    if len(captures) > 1:
        with open(a.capture + ".2", "wb") as f:
            f.write(captures[1])
    os.unlink(link)
    if tmp:
        os.rmdir(tmp)
    sys.exit(exit_code)


main()
