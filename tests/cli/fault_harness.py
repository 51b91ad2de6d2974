#!/usr/bin/env python3
"""The bridge under faults from the process around it: its log pipe closed or
stuck, SIGTERM's timing, Ctrl-Z and SIGCONT, a paused terminal.

  fault_harness.py BIN DATA_DIR SCENARIO CAPTURE

Each scenario runs `andros-bridge run --port PTY ...` (or `monitor`), plays
its part (with the helpers of fault_lib.py), writes what arrived on the port
to CAPTURE (for check_frames.py) and exits 0, or prints what went wrong and
exits 1. Every wait is bounded (a ceiling); what follows a request is judged
from the run's session, and the times still compared have half a period or
more of margin (docs/testing.md, "Real-time tests").
"""
import os, signal, subprocess, sys, tempfile, time

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
from fault_lib import (STARTED, Port, driving, fail, full_pipe, long_drive, proc_state, read_some, start, terminal,
                       wait_exit, wait_reading, wait_stopped)
from session_lib import Catalogue, records, ticks


def closed_log(bin_, data, port):
    """stdout and stderr into a pipe whose reader reads one byte and goes (`2>&1 | head -c 1`)."""
    r, w = os.pipe()
    proc = start(long_drive(bin_, data, port), stdout=w, stderr=w, stdin=subprocess.DEVNULL)
    os.close(w)
    os.read(r, 1)
    os.close(r)
    if not port.wait(lambda f: driving(f) >= 5, 20):
        fail("no driving frames")
    n = len(port.received())
    if not port.wait(lambda f: len(f) >= n + 5, 10):  # frames go on with the log gone
        fail(f"frames stopped after the log pipe closed (exit {proc.poll()})")
    proc.send_signal(signal.SIGTERM)  # its "stopping" line is the next log write
    code = wait_exit(proc, 10)
    if code != 0:
        fail(f"exit {code} after SIGTERM with the log pipe closed, expected 0")


def stuck_log(bin_, data, port):
    """stdout and stderr into a full pipe nobody reads (a stuck `| tee`, a paused reader)."""
    r, w = full_pipe()
    proc = start(long_drive(bin_, data, port), stdout=w, stderr=w, stdin=subprocess.DEVNULL)
    os.close(w)
    ok = port.wait(lambda f: driving(f) >= 10, 20)
    proc.send_signal(signal.SIGTERM)
    code = wait_exit(proc, 10)
    os.close(r)
    if not ok:
        fail(f"frames did not flow with the log pipe full: {len(port.received())} frames")
    if code != 0:
        fail(f"exit {code} after SIGTERM with the log pipe full, expected 0 within 10 s")


def stop_tick(bin_, data, port):
    """At 1 Hz, SIGTERM just after a driving frame: the tick that took it (the session's
    request) sends the first neutral frame, the tick before it drove; and that tick is the
    next one after the signal: its frame arrives within 1.5 s of it (one period is 1 s;
    the old behaviour took two: the half period left is the margin for a loaded machine)."""
    script = os.path.join(port.dir, "stop.events")
    with open(script, "w") as f:  # enabled at the tick of 1 s, the stick pushed after it
        f.write("0 connect Test pad\n100 button leftshoulder 1\n1500 axis lefty -32768\n60000 end\n")
    proc = start([bin_, "run", "--rate", "1", "--port", port.path, "--input", script], stdout=subprocess.DEVNULL,
                 stderr=subprocess.DEVNULL, stdin=subprocess.DEVNULL)
    if not port.wait(lambda f: driving(f) >= 2, 20):
        fail("no driving frames")
    proc.send_signal(signal.SIGTERM)
    sent = time.monotonic()
    code = wait_exit(proc, 20)
    frames = port.settled()
    if code != 0:
        fail(f"exit {code} after SIGTERM, expected 0")
    asked, ran = recorded("stop")  # (a stop stays asked for: recorded at each of its ticks)
    at = [i for i, t in enumerate(ran) if t.t_ms == asked[0]] if asked else []
    if not at or at[0] == 0 or not SIGNALS.neutral(ran[at[0]].data) or drive(ran[at[0] - 1]) == 128:
        fail(f"the tick that took the stop (asked at {asked} ms) does not send the first neutral frame")
    first_neutral = next((t for t, d, _ in frames if t > sent and d == 128), None)
    after_signal = None if first_neutral is None else first_neutral - sent
    print(f"stop taken at {asked[0]} ms; signal -> first neutral frame "
          f"{'none' if after_signal is None else f'{after_signal * 1000:.0f} ms'}")
    if after_signal is None or after_signal > 1.5:
        fail("the first neutral frame did not leave on the tick after the signal")


def job_control(bin_, data, port):
    """Ctrl-Z mid-drive: neutral frames, then stopped; SIGCONT: neutral while the deadman is
    still held from before; the script's fresh press (at 4.1 s) drives again. What follows
    the SIGCONT is judged from the session: the time the run went on, the press."""
    script = os.path.join(port.dir, "tstp.events")
    with open(script, "w") as f:
        # The stick is centred for the fresh press and pushed after it: a stick held through an
        # enable is held back until it is seen at rest (docs/mapping.md).
        f.write("0 connect Test pad\n100 button leftshoulder 1\n200 axis lefty -32768\n"
                "4000 button leftshoulder 0\n4000 axis lefty 0\n4100 button leftshoulder 1\n"
                "4200 axis lefty -32768\n6000 end\n")
    proc = start([bin_, "run", "--port", port.path, "--input", script],
                 stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, stdin=subprocess.DEVNULL)
    if not port.wait(lambda f: driving(f) >= 5, 20):
        fail("no driving frames")
    proc.send_signal(signal.SIGTSTP)
    stopped = wait_stopped(proc)
    before = port.settled()
    if not stopped:
        fail("not stopped after SIGTSTP")
    tail = [d for _, d, _ in before[-3:]]
    if len(before) < 3 or tail != [128, 128, 128] or any(s for _, _, s in before[-3:]):
        fail(f"the frames before the stop do not end neutral: drive {[d for _, d, _ in before[-6:]]}")
    time.sleep(0.5)
    if len(port.received()) != len(before):
        fail("frames while stopped")
    proc.send_signal(signal.SIGCONT)
    code = wait_exit(proc, 20)
    _, ran = recorded("suspend")
    went_on = [int(text.split()[0]) for kind, text in records(session_file()) if kind == "pause"]
    # The run must go on while the old press is held (until 4.0 s of the script): the harness
    # continues it at about 1.5 s, a margin of over 2 s for a loaded machine.
    if len(went_on) != 1 or went_on[0] >= 4000:
        fail(f"too slow to tell: went on at {went_on} ms of a script that re-presses at 4.1 s")
    held = [t for t in ran if went_on[0] <= t.t_ms < 4100 and t.result == "sent"]
    pressed = [t for t in ran if t.t_ms >= 4100 and t.result == "sent"]
    print(f"after SIGCONT: {len(held)} frames with the old press held, "
          f"{sum(drive(t) != 128 for t in pressed)} driving after the fresh press; exit {code}")
    if not held or not all(SIGNALS.neutral(t.data) for t in held):
        fail(f"moved after SIGCONT without a fresh press: {[drive(t) for t in held]}")
    if not any(drive(t) != 128 for t in pressed):
        fail("a fresh press after SIGCONT did not drive")
    if code != 0:
        fail(f"exit {code}")


def background_stop(bin_, data, port):
    """SIGTTOU (as a terminal sends a background job that writes to it) is a stop request like
    Ctrl-Z: neutral frames first, then stopped; continued, it runs on and stops as usual."""
    proc = start(long_drive(bin_, data, port), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                 stdin=subprocess.DEVNULL)
    if not port.wait(lambda f: driving(f) >= 5, 20):
        fail("no driving frames")
    proc.send_signal(signal.SIGTTOU)
    if not wait_stopped(proc):
        fail("not stopped after SIGTTOU")
    before = port.settled()
    if [d for _, d, _ in before[-3:]] != [128, 128, 128]:
        fail(f"the frames before the stop do not end neutral: drive {[d for _, d, _ in before[-6:]]}")
    proc.send_signal(signal.SIGCONT)
    if not port.wait(lambda f: len(f) >= len(before) + 5, 10):
        fail("no frames after SIGCONT")
    proc.send_signal(signal.SIGTERM)
    code = wait_exit(proc, 10)
    if code != 0:
        fail(f"exit {code}")


def continue_early(bin_, data, port):
    """`kill -TSTP; sleep 0.08; kill -CONT`: the SIGCONT lands during the Ctrl-Z's neutral
    frames, before the process stops itself. It must not stop then (a SIGCONT already spent
    would leave it stopped for good, deaf to SIGTERM): it runs on, neutral until a fresh
    press, and SIGTERM ends it as usual."""
    log = tempfile.TemporaryFile()  # unnamed: nothing to remove, whichever way the scenario ends
    proc = start(long_drive(bin_, data, port), stdout=subprocess.DEVNULL, stderr=log, stdin=subprocess.DEVNULL)
    if not port.wait(lambda f: driving(f) >= 5, 20):
        fail("no driving frames")
    proc.send_signal(signal.SIGTSTP)
    time.sleep(0.08)  # the neutral frames take 3 periods (120 ms at 25 Hz) and a drain
    proc.send_signal(signal.SIGCONT)
    n = len(port.received())
    going = port.wait(lambda f: len(f) >= n + 10, 10)  # frames after the neutral ones
    state = proc_state(proc.pid)
    after = port.received()[n:]
    print(f"after SIGCONT: state {state}, {len(after)} frames, {driving(after)} driving")
    if not going or state == "T":
        fail(f"stopped for good after a SIGCONT during the neutral frames (state {state}, "
             f"{len(after)} frames after it)")
    if driving(after):
        fail("drove after the SIGCONT without a fresh deadman press")
    proc.send_signal(signal.SIGTERM)
    code = wait_exit(proc, 10)
    log.seek(0)
    lines = [line.strip() for line in log.read().decode(errors="replace").splitlines()
             if "SIGCONT" in line or "resumed" in line]
    print("\n".join(lines))  # which way it went: continued before it stopped (or, late, resumed)
    if code != 0:
        fail(f"exit {code} after SIGTERM, expected 0")


def paused_terminal(bin_, data, port):
    """The status view on a terminal paused with Ctrl-S: frames go on, and SIGTERM still
    ends the run through its neutral frames within a bounded time."""
    proc, m = terminal(long_drive(bin_, data, port))
    if not read_some(m, 1.0):
        fail("no status view on the terminal")
    os.write(m, b"\x13")  # Ctrl-S: the terminal stops taking output (IXON)
    read_some(m, 0.3)
    n = len(port.received())
    ok = port.wait(lambda f: len(f) >= n + 25, 10)
    proc.send_signal(signal.SIGTERM)
    sent = time.monotonic()
    code = wait_exit(proc, 10)
    took = time.monotonic() - sent
    os.close(m)
    if not ok:
        fail("frames stopped with the terminal paused")
    print(f"exit {code} {took:.2f} s after SIGTERM with the terminal paused")
    if code != 0 or took > 3:
        fail("a paused terminal held up the exit")


def monitor_zero(bin_, data, port):
    """`monitor /dev/zero` (a source that never runs dry): SIGTERM ends it, off and on a paused
    terminal. The signal goes once it has read 1 MiB of zeros (its loop is running: a SIGTERM
    before its start-up has blocked the signal kills it, -15, as any program), and the exit is
    awaited for 10 s, a ceiling: the stop reads at most 200 ms more, and an unbounded drain
    never ends."""
    proc = start([bin_, "monitor", "/dev/zero"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    if not wait_reading(proc, MONITOR_READ):
        fail(f"monitor /dev/zero: not reading it (exit {proc.poll()})")
    proc.send_signal(signal.SIGTERM)
    code = wait_exit(proc, 10)
    if code != 0:
        fail(f"monitor /dev/zero: exit {code} within 10 s of SIGTERM, expected 0")
    proc, m = terminal([bin_, "monitor", "/dev/zero"])
    if not wait_reading(proc, MONITOR_READ) or not read_some(m, 0.5):
        fail("monitor /dev/zero on a terminal: not reading it, or no screen")
    os.write(m, b"\x13")
    read_some(m, 0.3)
    proc.send_signal(signal.SIGTERM)
    code = wait_exit(proc, 10)
    os.close(m)
    if code != 0:
        fail(f"monitor /dev/zero on a paused terminal: exit {code} within 10 s of SIGTERM, expected 0")


MONITOR_READ = 8 << 20  # zeros read in its loop: far more than its start-up reads (libraries, files; ASan's maps)


SCENARIOS = {"closed-log": closed_log, "stuck-log": stuck_log, "stop-tick": stop_tick,
             "job-control": job_control, "continue-early": continue_early,
             "background-stop": background_stop, "paused-terminal": paused_terminal, "monitor-zero": monitor_zero}


def drive(tick):
    return SIGNALS.value(tick.data, "drive")


def session_file():
    """The one session of this scenario's run (recorded in a folder of the scenario's own)."""
    folder = os.path.join(os.environ["XDG_STATE_HOME"], "andros-bridge")
    names = [n for n in os.listdir(folder) if n.endswith(".andros-session")]
    if len(names) != 1:
        fail(f"{len(names)} sessions in {folder}")
    return os.path.join(folder, names[0])


def recorded(request):
    """The times (ms) of the session's requests of this kind, and every tick that ran."""
    path = session_file()
    return [int(text.split()[0]) for kind, text in records(path) if kind == "request" and
            text.split()[1] == request], ticks(path)


def main():
    bin_, data, scenario, capture = sys.argv[1:5]
    global SIGNALS
    SIGNALS = Catalogue(bin_)
    port = Port()
    os.environ["XDG_STATE_HOME"] = os.path.join(port.dir, "state")
    try:
        SCENARIOS[scenario](bin_, data, port)
    finally:
        for proc in STARTED:
            if proc.poll() is None:
                proc.kill()
                proc.wait()
        port.close(capture)


main()
