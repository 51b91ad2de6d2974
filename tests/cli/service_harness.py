#!/usr/bin/env python3
"""`andros-bridge run` as a service manager sees it: a fake NOTIFY_SOCKET (a
unix datagram socket bound here), a pseudo-terminal as the port, the run's
flight recorder session (service_lib.py, session_lib.py).

  service_harness.py BIN TMPDIR SCENARIO
      (notify | deaf | stall | reload | fifo_reload | pipe_reload)

Prints one FAIL line per broken check and exits 1 if there was any. What
follows a request is counted from the tick at which the run recorded it (its
session), never from the moment the harness sent the signal: a loaded machine
delays the harness and the signal, not the tick's answer. The port's frames
are the session's, byte for byte. What stays in real time (the watchdog's
pings, a thread held stopped) has a margin of a whole ping period or more
(docs/testing.md, "Real-time tests"). Every wait is bounded.
"""
import ctypes, os, signal, sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
from service_lib import LoopThreadStop, Run, check, failures, thread_states, write
from session_lib import Catalogue, records, ticks

BIN, TMP, SCENARIO = sys.argv[1:4]
SIGNALS = Catalogue(BIN)
neutral = SIGNALS.neutral


def start(args, **options):
    return Run(BIN, TMP, args, **options)


def script(*lines):
    path = os.path.join(TMP, "drive.events")
    write(path, "0 connect Test pad\n" + "".join(f"{t} {e}\n" for t, e in lines))
    return path


def watchdog_gaps(run, start, end):
    times = [t for t, _, _ in run.with_text("WATCHDOG=1") if start <= t <= end]
    return times, [b - a for a, b in zip(times, times[1:])]


def sent(run):
    """The session's frames the link took; checked to be the port's, in order."""
    frames = [t for t in ticks(run.session()) if t.result == "sent"]
    port = run.frames()
    check([t.data for t in frames] == port,
          f"the port got {len(port)} frames, the session says {len(frames)} were sent (or others)")
    return frames


def scenario_notify():
    """READY after the first frame, pings every half period, STATUS on change, STOPPING last."""
    events = script((100, "button leftshoulder 1"), (200, "axis lefty -32768"), (2500, "axis lefty 0"),
                    (2600, "button leftshoulder 0"), (3000, "end"))
    run = start(["--input", events], watchdog_usec=2_000_000)
    code, err = run.finish()
    check(code == 0, f"exit {code}: {err}")
    frames = sent(run)
    order = [m for _, m, _ in run.messages]
    ready = run.with_text("READY=1")
    check(len(ready) == 1, f"READY=1 {len(ready)} times")
    check(ready and len(run.frames(0, ready[0][2])) >= 1, "READY=1 before the first frame reached the port")
    stopping = run.with_text("STOPPING=1")
    check(len(stopping) == 1 and order[-1] == "STOPPING=1", "STOPPING=1 is not the last message, once")
    if not (ready and stopping):
        return
    # The first tick pings before it says READY (the pings come from the loop's ticks).
    check(order[0] == "WATCHDOG=1", f"the first message is not a ping: {order[:3]}")
    times, gaps = watchdog_gaps(run, 0, stopping[0][0])
    # Every half period (1 s): at 0, 1, 2 (and 3) s of a 3 s run; a gap over the period would get the
    # service killed. The bounds leave half a period each way for a loaded machine's delays.
    check(len(times) >= 3, f"{len(times)} WATCHDOG=1 in a 3 s run with WATCHDOG_USEC=2 s")
    check(all(0.5 <= g <= 2.0 for g in gaps), f"WATCHDOG=1 gaps {gaps}: expected about 1 s, never over 2 s")
    statuses = [m for _, m, _ in run.with_text("STATUS=")]
    check(2 <= len(statuses) <= 15, f"{len(statuses)} STATUS= messages over 75 ticks: sent on change only")
    check(any("HD1; not enabled:" in s for s in statuses), f"no 'not enabled' STATUS: {statuses}")
    check(any("HD1; enabled" in s for s in statuses), f"no 'enabled' STATUS: {statuses}")
    check(all(f"link {run.link}" in s and s.endswith("; 25 Hz") for s in statuses if "stopping" not in s),
          f"STATUS without link or rate: {statuses}")
    check(any(SIGNALS.value(f.data, "drive") != 128 for f in frames), "no driving frame")
    check(len(frames) >= 3 and all(neutral(f.data) for f in frames[-3:]), "the run did not end on 3 neutral frames")
    check(stopping[0][2] == len(run.capture), "frames after STOPPING=1")


def scenario_deaf():
    """A notify socket nobody reads: messages are dropped, the frames never wait. A send that
    waited would hold the loop for good (the run never ends: the exit is awaited 20 s, a
    ceiling) or for a while each tick (a ping every tick here: most ticks would be skipped)."""
    events = script((100, "button leftshoulder 1"), (3000, "end"))
    run = start(["--input", events], watchdog_usec=20_000, read_notify=False)
    code, err = run.finish()
    check(code == 0, f"exit {code} (a run of 3 s to a notify socket nobody reads): {err}")
    frames = sent(run)
    check(len(frames) >= 50, f"{len(frames)} frames of 75 ticks to a notify socket nobody reads")


def scenario_stall():
    """The loop's thread stopped for 3 s while the process's other threads run: no frame
    and no WATCHDOG=1 until it goes on (the pings come from the loop itself, so that
    systemd restarts a loop that is stuck)."""
    run = start(["--input", script((20000, "end"))], watchdog_usec=2_000_000)
    run.pump(20, lambda: run.with_text("READY=1"))
    run.pump(2.5)
    loop = LoopThreadStop(run.proc.pid)
    if not loop.stop():
        print(f"SKIP: ptrace is not permitted here ({os.strerror(ctypes.get_errno())}): the stall is not checked")
        run.proc.send_signal(signal.SIGTERM)
        run.finish()
        return
    # Every message the loop sent before it stopped is queued by now (a datagram is queued
    # when it is sent); what arrives from here on was sent during the stall.
    run.pump(0.3)
    stalled = run.drain_socket()
    run.pump(3.0)
    states = thread_states(run.proc.pid)
    released = run.drain_socket()
    t_release = run.now()
    loop.release()
    run.pump(3.0)
    run.proc.send_signal(signal.SIGTERM)
    code, err = run.finish()
    check(code == 0, f"exit {code}: {err}")
    others = [st for tid, st in states.items() if tid != run.proc.pid]
    check(states.get(run.proc.pid) == "t" and others and all(st in "SR" for st in others),
          f"thread states during the stall {states}: expected the loop's stopped, the others running or sleeping")
    during = [m for _, m, _ in run.messages[stalled:released] if "WATCHDOG=1" in m]
    check(not during, f"{len(during)} WATCHDOG=1 during the stall")
    # No tick ran while the thread was stopped (3.3 s): the session's first tick after it
    # skipped at least 3 s of them; the port got no frame the session does not have.
    frames = sent(run)
    gap, gap_tick = max((int(text.split()[4][len("gap="):]), int(text.split()[0]))
                        for kind, text in records(run.session()) if kind == "frame")
    check(gap >= 75, f"no tick skipped for the stall: the largest gap {gap} ticks")
    _, gaps_before = watchdog_gaps(run, 0, run.messages[stalled - 1][0] if stalled else 0)
    after, _ = watchdog_gaps(run, t_release, t_release + 3.0)
    check(gaps_before and max(gaps_before) <= 2.0, f"pings before the stall: gaps {gaps_before}")
    check(len(after) >= 2, f"pings in the 3 s after the stall (one a second): {after}")
    resumed = [f for f in frames if f.tick >= gap_tick]
    check(len(resumed) >= 25, f"{len(resumed)} frames in the 3 s after the stall")


def scenario_fifo_reload():
    """SIGHUP once the config file has been replaced by a FIFO whose writer
    sends nothing: refused at once (never read), the old settings stay, frames
    and pings go on, and SIGTERM still ends the run."""
    conf = os.path.join(TMP, "bridge.conf")
    write(conf, f"serialport={os.path.join(TMP, 'port')}\nrobot=wolverine\n")
    run = start(["--config", conf, "--input", script((20000, "end"))], watchdog_usec=2_000_000)
    run.pump(20, lambda: run.with_text("READY=1"))
    run.pump(1.0)
    os.unlink(conf)
    os.mkfifo(conf)
    writer = os.open(conf, os.O_RDWR)  # a writer that sends nothing
    t_hup = run.now()
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
    # Frames go on from the tick that took the SIGHUP to the one that took the SIGTERM, 3 s
    # (75 ticks) apart: a reload that waited on the FIFO would hold the loop for good.
    recs = records(run.session())
    asked = [int(text.split()[0]) for kind, text in recs if kind == "request" and text.endswith(" reload")]
    frames = [f for f in sent(run) if asked and f.t_ms >= asked[0]]
    check(len(asked) == 1 and len(frames) >= 25, f"{len(frames)} frames after the reload's request at {asked} ms")
    # Pings every second (WATCHDOG_USEC=2 s) over the 4 s around it; a gap over 2 s would get
    # the service killed (a margin of a second for a loaded machine's delays).
    times, gaps = watchdog_gaps(run, t_hup - 1.0, t_term)
    check(len(times) >= 3 and max(gaps, default=9) <= 2.0, f"WATCHDOG=1 around the reload at {times}")


def scenario_pipe_reload():
    """`--config <(...)`: the pipe is read at start; a reload does not read it
    again (drained, it would be an empty file and the defaults would take
    over), says so, and reloads the mapping with the start's settings."""
    read_end, write_end = os.pipe()
    os.write(write_end, f"serialport={os.path.join(TMP, 'port')}\nrobot=wolverine\nweapons=enabled\n".encode())
    os.close(write_end)
    config = f"/dev/fd/{read_end}"
    run = start(["--config", config, "--input", script((20000, "end"))], pass_fds=(read_end,))
    os.close(read_end)
    run.pump(20, lambda: run.with_text("READY=1"))
    run.proc.send_signal(signal.SIGHUP)
    run.pump(20, lambda: len(run.with_text("READY=1")) >= 2)
    run.proc.send_signal(signal.SIGTERM)
    code, err = run.finish()
    check(code == 0, f"exit {code}: {err}")
    check(f"config {config} was a pipe at start: not read again; mapping reread" in err, f"no pipe line: {err}")
    check("reloaded (SIGHUP): mapping " in err and "wolverine.yaml, WEAPONS ENABLED;" in err,
          f"the reload did not keep the start's robot and weapons: {err}")
    check("hd1.yaml" not in err, f"the reload fell back to the default robot: {err}")


def scenario_reload():
    """SIGHUP swaps config and mapping between neutral frames; the deadman needs a fresh
    press after it; a bad config keeps the old settings and says why. Each reload is
    judged from the tick at which the run recorded its request: that tick's frame is the
    first neutral one, and the frames stay neutral until the first deadman press after
    the reload's outcome, the deadman held through it."""
    conf = os.path.join(TMP, "bridge.conf")
    link = os.path.join(TMP, "port")
    write(conf, f"serialport={link}\nrobot=hd1\n")
    write(os.path.join(TMP, "plain.yaml"),  # drive not inverted: stick up is below centre
          "robot: HD1\ndeadman: leftshoulder\nbindings:\n  - analog: drive\n    axis: lefty\n")
    # Each press is held 3.9 s: the harness's signal must land while it is held (a margin
    # of over 3 s for a harness a loaded machine holds back).
    press = lambda t, held: [(t, "button leftshoulder 1"), (t + 100, "axis lefty -32768"),
                             (t + held - 100, "axis lefty 0"), (t + held, "button leftshoulder 0")]
    events = script(*press(100, 3900), *press(4200, 3900), *press(8300, 1500), (10500, "end"))
    run = start(["--config", conf, "--input", events])
    drives = lambda value, since: lambda: sum(SIGNALS.value(f, "drive") == value for f in run.frames(since)) >= 10
    run.pump(20, drives(255, 0))  # hd1: stick up is 255
    write(conf, f"serialport={link}\nrobot=hd1\nmapping=plain.yaml\n")
    since = len(run.capture) // 36 * 36
    run.proc.send_signal(signal.SIGHUP)
    run.pump(20, drives(0, since))  # plain.yaml, after a fresh press
    write(conf, f"serialport={link}\nrobot=R2D2\n")
    run.proc.send_signal(signal.SIGHUP)
    run.pump(20, lambda: any("reload failed: " in m for _, m, _ in run.messages))
    write(conf, f"serialport={link}\nmapping=plain.yaml\ncode=3C\n")  # the link's code is not changed by a reload
    run.proc.send_signal(signal.SIGHUP)
    code, err = run.finish()
    check(code == 0, f"exit {code}: {err}")
    frames = sent(run)
    recs = records(run.session())
    asked = [int(text.split()[0]) for kind, text in recs if kind == "request" and text.endswith(" reload")]
    outcomes = [int(text.split()[0]) for kind, text in recs if kind == "reload"]
    deadman = [(int(e[0]), e[3]) for e in (text.split() for kind, text in recs if kind == "event")
               if e[1:3] == ["button", "leftshoulder"]]
    check(len(asked) == 3 and len(outcomes) == 3, f"reloads asked at {asked} ms, taken at {outcomes} ms: expected 3")
    drive = lambda f: SIGNALS.value(f.data, "drive")
    check(any(drive(f) == 255 for f in frames if f.t_ms < asked[0]), "no hd1 driving before the reload")
    for name, at, done in zip(("the reload", "the failed reload", "the refused code"), asked, outcomes):
        before = [f for f in frames if f.t_ms < at]
        after = [f for f in frames if f.t_ms >= at]
        held = [v for t, v in deadman if t <= done]
        check(held and held[-1] == "1", f"the deadman was not held when {name} was taken ({done} ms): no check of "
                                        "a fresh press (the harness's signal came late)")
        pressed = next((t for t, v in deadman if t > done and v == "1"), None)
        check(after and after[0].t_ms == at and neutral(after[0].data),
              f"{name}: the frame of the request's tick ({at} ms) is not neutral")
        if name != "the refused code":  # (asked for within the failed reload's neutral stretch)
            check(before and not neutral(before[-1].data), f"{name}: not driving before the request's tick")
        quiet = [f for f in after if pressed is None or f.t_ms < pressed]
        check(all(neutral(f.data) for f in quiet), f"{name}: motion before the fresh press at {pressed} ms")
        check(not any(drive(f) == 255 for f in after), f"hd1's mapping after {name}")
        check(any(drive(f) == 0 for f in after), f"plain.yaml does not drive after {name}")
    check(f"reloaded (SIGHUP): mapping {TMP}/plain.yaml;" in err, f"no reload line: {err}")
    check(f"reload (SIGHUP) failed, the old settings stay: {conf}:2" in err and "R2D2" in err,
          f"the failed reload does not say why: {err}")
    check("failed, the old settings stay: code 01 -> 3C: a reload changes the robot" in err,
          f"a code changed by a reload is not refused: {err}")
    check(any("reload failed: " in m and "R2D2" in m for _, m, _ in run.with_text("STATUS=")),
          "no STATUS= for the failed reload")
    check(len(run.with_text("RELOADING=1")) == 3 and len(run.with_text("READY=1")) == 4,
          "RELOADING=1 / READY=1 not once per reload")
    check(len(frames) >= 3 and all(neutral(f.data) for f in frames[-3:]), "the run did not end on neutral frames")


{"notify": scenario_notify, "deaf": scenario_deaf, "stall": scenario_stall, "reload": scenario_reload,
 "fifo_reload": scenario_fifo_reload, "pipe_reload": scenario_pipe_reload}[SCENARIO]()
sys.exit(1 if failures else 0)
