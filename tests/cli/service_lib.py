"""What the service scenarios (service_harness.py) share: the bridge run as a
service manager sees it (a fake NOTIFY_SOCKET, a pseudo-terminal as the
port, its flight recorder session in its own folder), the frames decoded
here (no process started per look: a look must cost the harness nothing
while the bridge runs on), and the checks. Every wait is bounded."""
import ctypes, os, pty, select, socket, subprocess, time, tty

failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAIL:", what)


def write(path, text):
    with open(path, "w") as f:
        f.write(text)


def decode(capture):
    """The 16 data bytes of each whole frame in capture (F1 F1, 32 hex digits, a 2-byte checksum)."""
    frames = []
    for i in range(0, len(capture) - 35, 36):
        if capture[i:i + 2] != b"\xf1\xf1":
            raise ValueError(f"the port's bytes at {i} do not start a frame")
        frames.append(bytes.fromhex(capture[i + 2:i + 34].decode()))
    return frames


class Run:
    """The bridge, its port (a pty behind TMP/port), its notify socket and its session."""

    def __init__(self, bin_, tmp, args, watchdog_usec=1_000_000, read_notify=True, pass_fds=()):
        self.link = os.path.join(tmp, "port")
        self.master, slave = pty.openpty()
        tty.setraw(self.master)
        os.symlink(os.ttyname(slave), self.link)
        self.slave = slave
        self.sock = socket.socket(socket.AF_UNIX, socket.SOCK_DGRAM)
        self.sock.bind(os.path.join(tmp, "notify"))
        self.read_notify = read_notify
        self.state = os.path.join(tmp, "state")
        env = dict(os.environ, NOTIFY_SOCKET=os.path.join(tmp, "notify"), WATCHDOG_USEC=str(watchdog_usec),
                   XDG_CONFIG_HOME=os.path.join(tmp, "xdg"), XDG_STATE_HOME=self.state)
        env.pop("WATCHDOG_PID", None)
        self.err = open(os.path.join(tmp, "err"), "w+")
        self.proc = subprocess.Popen([bin_, "run", "--port", self.link] + args, env=env, stderr=self.err,
                                     stdout=subprocess.DEVNULL, pass_fds=pass_fds)
        self.t0 = time.monotonic()
        self.capture = bytearray()
        self.messages = []  # (time, message, capture length then)

    def now(self):
        return time.monotonic() - self.t0

    def read_port(self):
        while select.select([self.master], [], [], 0)[0]:
            self.capture += os.read(self.master, 4096)

    def pump(self, seconds, until=lambda: False):
        """Reads the port, then the socket, until until() or for at most `seconds` (a ceiling)."""
        deadline = time.monotonic() + seconds
        while time.monotonic() < deadline and not until():
            fds = [self.master] + ([self.sock] if self.read_notify else [])
            ready = select.select(fds, [], [], 0.02)[0]
            if self.master in ready:
                self.capture += os.read(self.master, 4096)
            if self.sock in ready:
                self.read_port()  # whatever the bridge wrote before this message is counted
                self.messages.append((self.now(), self.sock.recv(4096).decode(), len(self.capture)))
            if self.proc.poll() is not None and not ready:
                break

    def drain_socket(self):
        """Every message already sent (a unix datagram is queued when sent): their count."""
        while select.select([self.sock], [], [], 0)[0]:
            self.messages.append((self.now(), self.sock.recv(4096).decode(), len(self.capture)))
        return len(self.messages)

    def finish(self, timeout=20):
        """Waits for the exit (a ceiling), then reads what is left: (exit code, stderr)."""
        self.pump(timeout, lambda: self.proc.poll() is not None)
        code = self.proc.poll()
        if code is None:
            self.proc.kill()
        # The last frames and messages, until the port has been quiet for 0.3 s (at most 5 s).
        deadline = time.monotonic() + 5
        fds = [self.master] + ([self.sock] if self.read_notify else [])
        while time.monotonic() < deadline and select.select(fds, [], [], 0.3)[0]:
            self.read_port()
            self.drain_socket()
        self.err.seek(0)
        return code, self.err.read()

    def frames(self, start=0, end=None):
        return decode(self.capture[start:end])

    def with_text(self, text, start=0, end=None):
        """(time, message, capture length) of the messages from index `start` to `end` that hold text."""
        return [m for m in self.messages[start:end] if text in m[1]]

    def session(self):
        """The run's session: the one file in its folder."""
        folder = os.path.join(self.state, "andros-bridge")
        names = [n for n in os.listdir(folder) if n.endswith(".andros-session")]
        if len(names) != 1:
            raise ValueError(f"{len(names)} sessions in {folder}")
        return os.path.join(folder, names[0])


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
