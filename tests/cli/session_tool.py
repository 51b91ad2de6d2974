#!/usr/bin/env python3
"""Crafts flight recorder sessions for the tests (docs/recording.md).

  session_tool.py rehash FILE     recompute every record's hash, so that an
                                  edited session verifies as intact again
  session_tool.py renumber FILE   number the records 0, 1, 2... again (after a
                                  line was added or removed), then rehash
  session_tool.py settings FILE PYTHON
                                  edit the first settings record's JSON with
                                  PYTHON (an expression statement on `s`), then rehash
  session_tool.py grow FILE MB OUT
                                  FILE's records, then a stick moving on every
                                  tick (an event and a frame record a tick, as
                                  a drive records) until OUT holds MB megabytes,
                                  then an end: a big session to measure reading

  session_tool.py long FILE HOURS HZ FORMAT OUT
                                  FILE's records to its first frame record,
                                  the header's format FORMAT and the rate HZ,
                                  then an end HOURS later: a few kB that ask
                                  for HOURS x HZ x 3600 ticks
  session_tool.py flaps FILE HOURS OUT
                                  FILE's records before its input-end, then the
                                  link down and up again every second for HOURS
                                  (a frame record a minute), then an end
  session_tool.py reloads FILE N MB OUT
                                  as grow, with N reloads (a settings record
                                  and `reload T ok`) spread over it

A record is `SEQ KIND FIELDS... HASH`: HASH is the SHA-256 of the previous
record's hash (32 zero bytes before the first) and the line up to the space
before HASH. Lines are kept as bytes; a last line without its newline stays so.
"""
import hashlib, json, sys


def records(data):
    lines = data.split(b"\n")
    ended = lines[-1] == b""
    if ended:
        lines.pop()
    return lines, ended


def payload(line):
    head, _, tail = line.rpartition(b" ")
    return head if len(tail) == 64 else line


def rehash(lines):
    prev = bytes(32)
    out = []
    for line in lines:
        p = payload(line)
        prev = hashlib.sha256(prev + p).digest()
        out.append(p + b" " + prev.hex().encode())
    return out


def grow(lines, size):
    """The records up to the end, then ticks at the recorded rate until size bytes."""
    rate = None
    kept = []
    last_tick = 0
    for line in lines:
        seq, kind, rest = payload(line).split(b" ", 2)
        if kind == b"settings":
            s = json.loads(rest)
            rate = s.get("rate_millihertz", s.get("rate_mhz"))
        if kind == b"frame":
            last_tick = int(rest.split(b" ")[0])
            data = rest.split(b" ")[3]
        if kind == b"end":
            break
        if kind == b"input-end":
            continue  # the input goes on: replay runs every tick grown
        kept.append(b" ".join(payload(line).split(b" ")[1:]))
    out = kept
    total = sum(len(l) + 67 for l in out)
    tick = last_tick + 1
    while total < size:
        t = tick * 1_000_000 // rate
        drive = 0x30 + tick % 10  # a byte that changes every tick
        frame_data = data[:14] + b"%02x" % drive + data[16:]
        for rec in (b"event %d axis lefty %d" % (t, -2000 - tick % 30000),
                    b"frame %d %d sent %s gap=0" % (tick, t, frame_data)):
            out.append(rec)
            total += len(rec) + 75
        tick += 1
    out.append(b'end %d tick %d frames %d "SIGINT"' % ((tick - 1) * 1_000_000 // rate, tick - 1, tick))
    return [b"%d %s" % (i, r) for i, r in enumerate(out)]


def head(lines, stop_kinds):
    """The payloads (no SEQ) before the first record of a kind in stop_kinds, the settings' JSON and the last frame's data."""
    out, settings, data, last_tick = [], None, None, 0
    for line in lines:
        seq, kind, rest = payload(line).split(b" ", 2)
        if kind in stop_kinds:
            break
        if kind == b"settings" and settings is None:
            settings = json.loads(rest)
        if kind == b"frame":
            last_tick, data = int(rest.split(b" ")[0]), rest.split(b" ")[3]
        out.append(kind + b" " + rest)
    return out, settings, data, last_tick


def numbered(payloads):
    return [b"%d %s" % (i, r) for i, r in enumerate(payloads)]


def long_session(lines, hours, hz, fmt):
    out, _, _, _ = head(lines, {b"event"})
    out[0] = b"andros-session %d" % fmt
    for i, rec in enumerate(out):
        if rec.startswith(b"settings "):
            s = json.loads(rec[9:])
            s.pop("rate_mhz", None)
            s["rate_millihertz"] = hz * 1000
            out[i] = b"settings " + json.dumps(s, separators=(",", ":")).encode()
    out += [b"state 0 not enabled", b'layer 0 ""', b'link 0 up motion ""',
            b"frame 0 0 sent 0000182000908080000000010020CC02 gap=0"]
    last = int(hours * 3600 * hz) - 1
    out.append(b'end %d tick %d frames %d "SIGINT"' % (last * 1000 // hz, last, last + 1))
    return numbered(out)


def flaps(lines, hours):
    out, settings, data, tick = head(lines, {b"input-end", b"end"})
    rate = settings.get("rate_millihertz", settings.get("rate_mhz"))
    t0 = tick * 1_000_000 // rate
    up = True
    for second in range(1, int(hours * 3600) + 1):
        t = t0 + second * 1000
        up = not up
        out.append(b'link %d up motion ""' % t if up else b'link %d connecting neutral-only "flap"' % t)
        if second % 60 == 0:
            k = (t * rate + 999_999) // 1_000_000
            out.append(b"frame %d %d sent %s gap=0" % (k, k * 1_000_000 // rate, data))
            tick = k
    out.append(b'end %d tick %d frames %d "SIGINT"' % (tick * 1_000_000 // rate, tick, tick + 1))
    return numbered(out)


def with_reloads(lines, n):
    """Grown lines with n reloads: a settings record and `reload T ok` after every len/n-th frame record."""
    settings = next(payload(l).split(b" ", 2)[2] for l in lines if payload(l).split(b" ", 2)[1] == b"settings")
    frames = [i for i, l in enumerate(lines) if payload(l).split(b" ", 2)[1] == b"frame"]
    at = set(frames[len(frames) * (k + 1) // (n + 1)] for k in range(n))
    out = []
    for i, line in enumerate(lines):
        seq, kind, rest = payload(line).split(b" ", 2)
        out.append(kind + b" " + rest)
        if i in at:
            t = int(rest.split(b" ")[1])
            out += [b"settings " + settings, b'reload %d ok "reloaded"' % t]
    return numbered(out)


def write(path, lines, ended):
    with open(path, "wb") as f:
        f.write(b"\n".join(lines) + (b"\n" if ended else b""))


def main():
    verb, path = sys.argv[1], sys.argv[2]
    lines, ended = records(open(path, "rb").read())
    if verb == "settings":
        for i, line in enumerate(lines):
            seq, kind, rest = payload(line).split(b" ", 2)
            if kind == b"settings":
                s = json.loads(rest)
                exec(sys.argv[3], {"s": s, "hashlib": hashlib})
                lines[i] = seq + b" settings " + json.dumps(s, separators=(",", ":")).encode()
                break
    elif verb == "grow":
        lines = grow(lines, int(sys.argv[3]) * 1_000_000)
        path = sys.argv[4]
        ended = True
    elif verb == "renumber":
        lines = numbered([payload(l).split(b" ", 1)[1] for l in lines])
    elif verb == "long":
        lines = long_session(lines, float(sys.argv[3]), int(sys.argv[4]), int(sys.argv[5]))
        path, ended = sys.argv[6], True
    elif verb == "flaps":
        lines = flaps(lines, float(sys.argv[3]))
        path, ended = sys.argv[4], True
    elif verb == "reloads":
        lines = with_reloads(grow(lines, int(sys.argv[4]) * 1_000_000), int(sys.argv[3]))
        path, ended = sys.argv[5], True
    elif verb != "rehash":
        sys.exit("unknown verb " + verb)
    write(path, rehash(lines), ended)


main()
