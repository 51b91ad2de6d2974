"""What the fault scenarios (fault_harness.py) share: the pty standing in for
the switchbox, starting the bridge and waiting on it, a full pipe, a terminal.
Every wait is bounded."""
import os, pty, select, shutil, subprocess, sys, tempfile, threading, time, tty


class Port:
    """A pty standing in for the switchbox; records each whole frame with its arrival time."""

    def __init__(self):
        self.master, self.slave = pty.openpty()
        tty.setraw(self.master)
        tty.setraw(self.slave)
        # A symlink, as udev makes: a bridge still retrying this path after the
        # test cannot write into a later test's pty that reuses the number.
        self.dir = tempfile.mkdtemp(prefix="andros-fault-")
        self.path = os.path.join(self.dir, "andros-switchbox")
        os.symlink(os.ttyname(self.slave), self.path)
        self.data = bytearray()
        self.frames = []  # (arrival, drive byte, safety bit)
        self.lock = threading.Lock()
        self.done = False
        self.thread = threading.Thread(target=self._read, daemon=True)
        self.thread.start()

    def _read(self):
        pending = bytearray()
        while not self.done:
            if not select.select([self.master], [], [], 0.05)[0]:
                continue
            try:
                chunk = os.read(self.master, 4096)
            except OSError:
                return
            now = time.monotonic()
            with self.lock:
                self.data += chunk
                pending += chunk
                while True:
                    i = pending.find(b"\xf1\xf1")
                    if i < 0 or len(pending) < i + 36:
                        break
                    digits = pending[i + 2:i + 34]
                    try:
                        drive = int(digits[14:16], 16)
                        safety = (int(digits[0:2], 16) >> 1) & 1
                    except ValueError:
                        drive, safety = -1, -1
                    self.frames.append((now, drive, safety))
                    del pending[:i + 36]

    def received(self):
        with self.lock:
            return list(self.frames)

    def settled(self, quiet=0.3, timeout=5):
        """The frames once none has arrived for `quiet` seconds (at most `timeout`): what a
        stopped process sent, with the last frames read off the pty too."""
        deadline = time.monotonic() + timeout
        last, since = self.received(), time.monotonic()
        while time.monotonic() < deadline:
            time.sleep(0.02)
            now = self.received()
            if len(now) != len(last):
                last, since = now, time.monotonic()
            elif time.monotonic() - since >= quiet:
                break
        return last

    def wait(self, what, timeout):
        """Waits until what(frames) is true; False after timeout seconds."""
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if what(self.received()):
                return True
            time.sleep(0.01)
        return False

    def close(self, capture):
        time.sleep(0.3)  # the last frames in flight
        self.done = True
        self.thread.join()
        with open(capture, "wb") as f:
            f.write(self.data)
        os.close(self.master)
        os.close(self.slave)
        shutil.rmtree(self.dir)  # the link, and the session of the scenario's run


def driving(frames):
    return sum(1 for _, d, _ in frames if d != 128)


def wait_exit(proc, timeout):
    try:
        return proc.wait(timeout=timeout)
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.wait()
        return None


STARTED = []  # every process started, killed if a scenario gives up on it


def start(argv, **kwargs):
    proc = subprocess.Popen(argv, **kwargs)
    STARTED.append(proc)
    return proc


def fail(why):
    print(why)
    sys.exit(1)


def full_pipe():
    """A pipe whose reader never reads, already full: every blocking write to it blocks."""
    r, w = os.pipe()
    os.set_blocking(w, False)
    try:
        while True:
            os.write(w, b"x" * 4096)
    except BlockingIOError:
        pass
    os.set_blocking(w, True)
    return r, w


def proc_state(pid):
    with open(f"/proc/{pid}/stat") as f:
        return f.read().rsplit(")", 1)[1].split()[0]


def bytes_read(pid):
    """What the process has read so far (rchar of /proc/PID/io: every read(), whatever the file)."""
    with open(f"/proc/{pid}/io") as f:
        return int(next(line.split()[1] for line in f if line.startswith("rchar:")))


def wait_reading(proc, count, timeout=30):
    """True once proc has read `count` bytes: past its start-up and in its loop. A signal
    sent before a program has set up its handling meets the signal's default action (a
    SIGTERM ends it with -15), so a test signals only a process seen at work. The bound
    is a ceiling for a start-up under ASan on a loaded machine, not a measure."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline and proc.poll() is None:
        if bytes_read(proc.pid) >= count:
            return True
        time.sleep(0.01)
    return False


def wait_stopped(proc):
    """True once proc is stopped (state T), False after 5 s."""
    for _ in range(500):
        if proc_state(proc.pid) == "T":
            return True
        time.sleep(0.01)
    return False


def long_drive(bin_, data, port, *options):
    """The argv of `run` on port, driving from the long drive script."""
    return [bin_, "run", *options, "--port", port.path, "--input", f"{data}/live/long_drive.events"]


def terminal(argv, env_extra=None):
    """Runs argv with stdout on a pty (the display on), stderr to /dev/null; returns (proc, master)."""
    m, s = pty.openpty()
    env = dict(os.environ, TERM="xterm", **(env_extra or {}))
    proc = start(argv, stdout=s, stderr=subprocess.DEVNULL, stdin=subprocess.DEVNULL, env=env)
    os.close(s)
    return proc, m


def read_some(m, seconds):
    end = time.monotonic() + seconds
    out = b""
    while time.monotonic() < end:
        if select.select([m], [], [], 0.05)[0]:
            try:
                out += os.read(m, 65536)
            except OSError:
                break
    return out
