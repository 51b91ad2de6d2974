#!/usr/bin/env python3
"""A TCP serial server on 127.0.0.1 for the CLI tests, well or badly behaved.

  tcp_server.py MODE PORT_FILE OUT [--seconds S]

Writes the port it listens on to PORT_FILE (atomically), then serves until S
seconds pass (default 20), PORT_FILE is removed or, in `read` mode, the
first client closes.

  read   reads everything until the client closes; the bytes go to OUT
  stall  a 4 kB receive buffer (as an embedded serial server has), accepts
         every connection and never reads until S seconds pass; then reads
         what each connection holds and writes one line per connection to
         OUT: the number of frames it held, and how many of them drive
         (drive byte not 0x80)
  close  accepts and at once closes every connection; writes one line per
         accept to OUT: its time in seconds since the first
"""
import os, select, socket, sys, time

FRAME_START = b"\xf1\xf1"


def main():
    mode, port_file, out = sys.argv[1:4]
    seconds = float(sys.argv[sys.argv.index("--seconds") + 1]) if "--seconds" in sys.argv else 20
    lst = socket.socket()
    if mode == "stall":
        lst.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
    lst.bind(("127.0.0.1", 0))
    lst.listen(16)
    with open(port_file + ".tmp", "w") as f:
        f.write(str(lst.getsockname()[1]))
    os.rename(port_file + ".tmp", port_file)
    deadline = time.monotonic() + seconds
    conns, accepts = [], []
    while time.monotonic() < deadline and os.path.exists(port_file):
        if not select.select([lst], [], [], 0.02)[0]:
            continue
        c, _ = lst.accept()
        accepts.append(time.monotonic())
        if mode == "close":
            c.close()
        elif mode == "stall":
            conns.append(c)
        else:
            c.settimeout(seconds)
            data = b""
            while True:
                d = c.recv(4096)
                if not d:
                    break
                data += d
            open(out, "wb").write(data)
            return
    with open(out, "w") as f:
        if mode == "close":
            f.writelines(f"{t - accepts[0]:.3f}\n" for t in accepts)
        for c in conns:
            c.setblocking(False)
            data = b""
            try:
                while True:
                    d = c.recv(65536)
                    if not d:
                        break
                    data += d
            except OSError:
                pass
            starts = [i for i in range(len(data) - 17) if data.startswith(FRAME_START, i)]
            driving = sum(1 for i in starts if data[i + 16:i + 18] != b"80")
            f.write(f"{len(starts)} {driving}\n")


main()
