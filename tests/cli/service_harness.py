#!/usr/bin/env python3
"""`andros-bridge run` as a service manager sees it: a fake NOTIFY_SOCKET (a
unix datagram socket bound here) and a pseudo-terminal as the port.

  service_harness.py BIN TMPDIR SCENARIO
      (notify | deaf | stall | reload | fifo_reload | pipe_reload)

Prints one FAIL line per broken check and exits 1 if there was any. Every
wait is bounded.
"""
import ctypes, json, os, pty, select, signal, socket, subprocess, sys, time, tty

BIN, TMP, SCENARIO = sys.argv[1:4]
LINK = os.path.join(TMP, "port")
failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAIL:", what)


def write(path, text):
    with open(path, "w") as f:
        f.write(text)


def script(*lines):
    path = os.path.join(TMP, "drive.events")
    write(path, "0 connect Test pad\n" + "".join(f"{t} {e}\n" for t, e in lines))
    return path


class Run:
    """The bridge, its port (a pty behind LINK) and its notify socket."""

    def __init__(self, args, watchdog_usec=1_000_000, read_notify=True, pass_fds=()):
        self.master, slave = pty.openpty()
        tty.setraw(self.master)
        os.symlink(os.ttyname(slave), LINK)
        self.slave = slave
        self.sock = socket.socket(socket.AF_UNIX, socket.SOCK_DGRAM)
        self.sock.bind(os.path.join(TMP, "notify"))
        self.read_notify = read_notify
        env = dict(os.environ, NOTIFY_SOCKET=os.path.join(TMP, "notify"), WATCHDOG_USEC=str(watchdog_usec),
                   XDG_CONFIG_HOME=os.path.join(TMP, "xdg"))
        env.pop("WATCHDOG_PID", None)
        self.err = open(os.path.join(TMP, "err"), "w+")
        self.t0 = time.monotonic()
        self.proc = subprocess.Popen([BIN, "run", "--port", LINK] + args, env=env, stderr=self.err,
                                     stdout=subprocess.DEVNULL, pass_fds=pass_fds)
        self.capture = bytearray()
        self.messages = []  # (time, message, capture length then)

    def now(self):
        return time.monotonic() - self.t0

    def pump(self, seconds, until=lambda: False):
        """Reads the port, then the socket, for at most `seconds` or until until()."""
        deadline = time.monotonic() + seconds
        while time.monotonic() < deadline and not until():
            fds = [self.master] + ([self.sock] if self.read_notify else [])
            ready = select.select(fds, [], [], 0.02)[0]
            if self.master in ready:
                self.capture += os.read(self.master, 4096)
            if self.sock in ready:
                # The port first: whatever the bridge wrote before this message is counted.
                while select.select([self.master], [], [], 0)[0]:
                    self.capture += os.read(self.master, 4096)
                msg = self.sock.recv(4096).decode()
                self.messages.append((self.now(), msg, len(self.capture)))
            if self.proc.poll() is not None and not ready:
                break

    def finish(self, timeout=10):
        self.pump(timeout, lambda: self.proc.poll() is not None)
        code = self.proc.poll()
        if code is None:
            self.proc.kill()
        self.pump(0.3)
        self.err.seek(0)
        return code, self.err.read()

    def frames(self, start=0, end=None):
        """The frames in capture[start:end], decoded by the binary."""
        path = os.path.join(TMP, "cap")
        with open(path, "wb") as f:
            f.write(self.capture[start:end])
        out = subprocess.run([BIN, "frame", "decode", path], capture_output=True, text=True).stdout
        return [json.loads(line)["signals"] for line in out.splitlines()]

    def with_text(self, text):
        return [m for m in self.messages if text in m[1]]


CATALOGUE = [json.loads(l) for l in subprocess.check_output([BIN, "frame", "signals", "--json"]).splitlines()]
ZEROED = {s["name"] for s in CATALOGUE if s["kind"] in ("motion", "weapon", "interlock")}


def neutral(s):
    return s["drive"] == 128 and s["pivot"] == 128 and all(s[k] == 0 for k in ZEROED)


def watchdog_gaps(run, start, end):
    times = [t for t, m, _ in run.with_text("WATCHDOG=1") if start <= t <= end]
    return times, [b - a for a, b in zip(times, times[1:])]


def scenario_notify():
    """READY after the first frame, pings every half period, STATUS on change, STOPPING last."""
    events = script((100, "button leftshoulder 1"), (200, "axis lefty -32768"), (2500, "axis lefty 0"),
                    (2600, "button leftshoulder 0"), (3000, "end"))
    run = Run(["--input", events])
    code, err = run.finish(15)
    check(code == 0, f"exit {code}: {err}")
    ready = run.with_text("READY=1")
    check(len(ready) == 1, f"READY=1 {len(ready)} times")
    check(ready and len(run.frames(0, ready[0][2])) >= 1, "READY=1 before the first frame reached the port")
    stopping = run.with_text("STOPPING=1")
    check(len(stopping) == 1 and run.messages[-1][1] == "STOPPING=1", "STOPPING=1 is not the last message, once")
    if not (ready and stopping):
        return
    times, gaps = watchdog_gaps(run, 0, stopping[0][0])
    check(len(times) >= 4, f"{len(times)} WATCHDOG=1 in a 3 s run with WATCHDOG_USEC=1 s")
    check(times and times[0] <= ready[0][0] + 0.1, "no WATCHDOG=1 from the first ticks")
    check(all(0.3 <= g <= 1.0 for g in gaps), f"WATCHDOG=1 gaps {gaps}: expected about 0.5 s, never over 1 s")
    statuses = [m for _, m, _ in run.with_text("STATUS=")]
    check(2 <= len(statuses) <= 15, f"{len(statuses)} STATUS= messages over 75 ticks: sent on change only")
    check(any("HD1; not enabled:" in s for s in statuses), f"no 'not enabled' STATUS: {statuses}")
    check(any("HD1; enabled" in s for s in statuses), f"no 'enabled' STATUS: {statuses}")
    check(all(f"link {LINK}" in s and s.endswith("; 25 Hz") for s in statuses if "stopping" not in s),
          f"STATUS without link or rate: {statuses}")
    before_stop = run.frames(0, stopping[0][2])
    check(len(before_stop) >= 60 and all(neutral(f) for f in before_stop[-3:]),
          "the last 3 frames before STOPPING=1 are not neutral")
    check(stopping[0][2] == len(run.capture), "frames after STOPPING=1")


def scenario_deaf():
    """A notify socket nobody reads: messages are dropped, the frames never wait."""
    events = script((100, "button leftshoulder 1"), (3000, "end"))
    run = Run(["--input", events], watchdog_usec=20_000, read_notify=False)
    start = time.monotonic()
    code, err = run.finish(15)
    frames = run.frames()
    check(code == 0, f"exit {code}: {err}")
    check(len(frames) >= 70, f"{len(frames)} frames in a 3 s run to a notify socket nobody reads")
    check(time.monotonic() - start < 8, "the run took too long behind a full notify socket")


class LoopThreadStop:
    """Stops one thread of the bridge, the loop's (the main one), with ptrace:
    its other threads (log writer, simulated vehicle) run on, as they would
    beside a loop stuck in a call. A signal would stop them all."""
    PTRACE_DETACH, PTRACE_SEIZE, PTRACE_INTERRUPT, WALL = 17, 0x4206, 0x4207, 0x40000000

    def __init__(self, tid):
        self.libc = ctypes.CDLL(None, use_errno=True)
        self.libc.ptrace.argtypes = [ctypes.c_long, ctypes.c_long, ctypes.c_void_p, ctypes.c_void_p]
        self.libc.ptrace.restype = ctypes.c_long
        self.tid = tid

    def stop(self):
        """True once the thread is stopped; False where ptrace is not permitted."""
        if self.libc.ptrace(self.PTRACE_SEIZE, self.tid, None, None) != 0:
            return False
        self.libc.ptrace(self.PTRACE_INTERRUPT, self.tid, None, None)
        os.waitpid(self.tid, self.WALL)  # the stop, taken here before Popen.poll() could take it for an exit
        return True

    def release(self):
        self.libc.ptrace(self.PTRACE_DETACH, self.tid, None, None)


def thread_states(pid):
    states = {}
    for tid in os.listdir(f"/proc/{pid}/task"):
        with open(f"/proc/{pid}/task/{tid}/stat") as f:
            states[int(tid)] = f.read().rsplit(")", 1)[1].split()[0]
    return states


def scenario_stall():
    """The loop's thread stopped for 3 s while the process's other threads run:
    no frame and no WATCHDOG=1 until it goes on (the pings come from the loop
    itself, so that systemd restarts a loop that is stuck)."""
    run = Run(["--input", script((20000, "end"))])
    run.pump(10, lambda: run.with_text("READY=1"))
    run.pump(1.5)
    loop = LoopThreadStop(run.proc.pid)
    if not loop.stop():
        print(f"SKIP: ptrace is not permitted here ({os.strerror(ctypes.get_errno())}): the stall is not checked")
        run.proc.send_signal(signal.SIGTERM)
        run.finish()
        return
    t_stop = run.now()
    run.pump(0.3)  # frames written before the stop are read by then
    cap_stalled = len(run.capture)
    run.pump(2.7)
    states = thread_states(run.proc.pid)
    t_release, cap_release = run.now(), len(run.capture)
    loop.release()
    run.pump(2.0)
    run.proc.send_signal(signal.SIGTERM)
    code, err = run.finish()
    check(code == 0, f"exit {code}: {err}")
    others = [st for tid, st in states.items() if tid != run.proc.pid]
    check(states.get(run.proc.pid) == "t" and others and all(st in "SR" for st in others),
          f"thread states during the stall {states}: expected the loop's stopped, the others running or sleeping")
    during, _ = watchdog_gaps(run, t_stop + 0.1, t_release)
    check(not during, f"WATCHDOG=1 during the stall at {during}")
    check(cap_release - cap_stalled < 36, f"{cap_release - cap_stalled} bytes of frames during the stall")
    _, gaps_before = watchdog_gaps(run, 0, t_stop)
    after, _ = watchdog_gaps(run, t_release, t_release + 2.0)
    check(gaps_before and max(gaps_before) <= 1.0, f"pings before the stall: gaps {gaps_before}")
    check(len(after) >= 2 and after[0] - t_release <= 1.0, f"pings after the stall: {after}")
    check(len(run.frames(cap_release)) >= 25, "frames did not resume after the stall")


def scenario_fifo_reload():
    """SIGHUP once the config file has been replaced by a FIFO whose writer
    sends nothing: refused at once (never read), the old settings stay, frames
    and pings go on, and SIGTERM still ends the run."""
    conf = os.path.join(TMP, "bridge.conf")
    write(conf, f"serialport={LINK}\nrobot=wolverine\n")
    run = Run(["--config", conf, "--input", script((20000, "end"))])
    run.pump(10, lambda: run.with_text("READY=1"))
    run.pump(1.0)
    os.unlink(conf)
    os.mkfifo(conf)
    writer = os.open(conf, os.O_RDWR)  # a writer that sends nothing
    cap_hup, t_hup = len(run.capture), run.now()
    run.proc.send_signal(signal.SIGHUP)
    run.pump(3.0)
    t_term = run.now()
    run.proc.send_signal(signal.SIGTERM)
    code, err = run.finish()
    os.close(writer)
    check(code == 0, f"exit {code} (SIGTERM after a reload of a FIFO): {err}")
    check(f"reload (SIGHUP) failed, the old settings stay: {conf}: error: is a pipe, not a regular file" in err,
          f"the refusal does not say why: {err}")
    check("mapping" in err and "wolverine.yaml" in err and "hd1.yaml" not in err, f"the settings changed: {err}")
    check(any("reload failed: " in m and "not a regular file" in m for _, m, _ in run.with_text("STATUS=")),
          "no STATUS= for the refused reload")
    check(len(run.frames(cap_hup)) >= 60, f"{len(run.frames(cap_hup))} frames in the 3 s after the SIGHUP")
    times, gaps = watchdog_gaps(run, t_hup - 1.0, t_term)
    check(len(times) >= 6 and max(gaps) <= 1.0, f"WATCHDOG=1 around the reload at {times}")


def scenario_pipe_reload():
    """`--config <(...)`: the pipe is read at start; a reload does not read it
    again (drained, it would be an empty file and the defaults would take
    over), says so, and reloads the mapping with the start's settings."""
    read_end, write_end = os.pipe()
    os.write(write_end, f"serialport={LINK}\nrobot=wolverine\nweapons=enabled\n".encode())
    os.close(write_end)
    config = f"/dev/fd/{read_end}"
    run = Run(["--config", config, "--input", script((20000, "end"))], pass_fds=(read_end,))
    os.close(read_end)
    run.pump(10, lambda: run.with_text("READY=1"))
    run.proc.send_signal(signal.SIGHUP)
    run.pump(10, lambda: len(run.with_text("READY=1")) >= 2)
    run.proc.send_signal(signal.SIGTERM)
    code, err = run.finish()
    check(code == 0, f"exit {code}: {err}")
    check(f"config {config} was a pipe at start: not read again; mapping reread" in err, f"no pipe line: {err}")
    check("reloaded (SIGHUP): mapping " in err and "wolverine.yaml, WEAPONS ENABLED;" in err,
          f"the reload did not keep the start's robot and weapons: {err}")
    check("hd1.yaml" not in err, f"the reload fell back to the default robot: {err}")


def scenario_reload():
    """SIGHUP swaps config and mapping between neutral frames; the deadman needs a
    fresh press after it; a bad config keeps the old settings and says why."""
    conf = os.path.join(TMP, "bridge.conf")
    write(conf, f"serialport={LINK}\nrobot=hd1\n")
    write(os.path.join(TMP, "plain.yaml"),  # drive not inverted: stick up is below centre
          "robot: HD1\ndeadman: leftshoulder\nbindings:\n  - analog: drive\n    axis: lefty\n")
    press = lambda t: [(t, "button leftshoulder 1"), (t + 100, "axis lefty -32768"),
                       (t + 2600, "axis lefty 0"), (t + 2700, "button leftshoulder 0")]
    events = script(*press(100), *press(3200), *press(6300), (9500, "end"))
    run = Run(["--config", conf, "--input", events])
    drives = lambda value: lambda: sum(f["drive"] == value for f in run.frames(hup[-1])) >= 10
    hup = [0]
    run.pump(10, drives(255))  # hd1: stick up is 255
    write(conf, f"serialport={LINK}\nrobot=hd1\nmapping=plain.yaml\n")
    hup.append(len(run.capture))
    run.proc.send_signal(signal.SIGHUP)
    run.pump(10, drives(0))  # plain.yaml, after a fresh press
    write(conf, f"serialport={LINK}\nrobot=R2D2\n")
    hup.append(len(run.capture))
    run.proc.send_signal(signal.SIGHUP)
    run.pump(1.0)  # still in the neutral stretch: the next fresh press is at 6.3 s
    write(conf, f"serialport={LINK}\nmapping=plain.yaml\ncode=3C\n")  # the link's code is not changed by a reload
    run.proc.send_signal(signal.SIGHUP)
    code, err = run.finish(15)
    check(code == 0, f"exit {code}: {err}")
    first, second, third = run.frames(0, hup[1]), run.frames(hup[1], hup[2]), run.frames(hup[2])
    check(any(f["drive"] == 255 for f in first), "no hd1 driving before the reload")
    for name, frames in (("the reload", second), ("the failed reload", third)):
        # Frames already on their way when the signal was sent come first (one or two; ten under load).
        start = next((i for i, f in enumerate(frames) if neutral(f)), len(frames))
        check(start <= 10, f"{start} frames before the first neutral one after {name}")
        check(not any(f["drive"] == 255 for f in frames[start:]), f"hd1's mapping after {name}")
        quiet = next((i for i, f in enumerate(frames[start:]) if not neutral(f)), None)
        # The deadman stays held through the reload: 2 s of neutral frames until the script presses it afresh.
        check(quiet is not None and quiet >= 25, f"{quiet} neutral frames after {name}: no fresh press required")
        check(any(f["drive"] == 0 for f in frames), f"plain.yaml does not drive after {name}")
    check(f"reloaded (SIGHUP): mapping {TMP}/plain.yaml;" in err, f"no reload line: {err}")
    check(f"reload (SIGHUP) failed, the old settings stay: {conf}:2" in err and "R2D2" in err,
          f"the failed reload does not say why: {err}")
    check("failed, the old settings stay: code 01 -> 3C: a reload changes the robot" in err,
          f"a code changed by a reload is not refused: {err}")
    check(any("reload failed: " in m and "R2D2" in m for _, m, _ in run.with_text("STATUS=")),
          "no STATUS= for the failed reload")
    check(len(run.with_text("RELOADING=1")) == 3 and len(run.with_text("READY=1")) == 4,
          "RELOADING=1 / READY=1 not once per reload")
    check(all(neutral(f) for f in third[-3:]), "the run did not end on neutral frames")


{"notify": scenario_notify, "deaf": scenario_deaf, "stall": scenario_stall, "reload": scenario_reload,
 "fifo_reload": scenario_fifo_reload, "pipe_reload": scenario_pipe_reload}[SCENARIO]()
sys.exit(1 if failures else 0)
