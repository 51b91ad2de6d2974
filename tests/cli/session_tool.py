#!/usr/bin/env python3
"""Crafts flight recorder sessions for the tests (docs/recording.md).

  session_tool.py rehash FILE     recompute every record's hash, so that an
                                  edited session verifies as intact again
  session_tool.py settings FILE PYTHON
                                  edit the first settings record's JSON with
                                  PYTHON (an expression statement on `s`), then rehash
  session_tool.py grow FILE MB OUT
                                  FILE's records, then a stick moving on every
                                  tick (an event and a frame record a tick, as
                                  a drive records) until OUT holds MB megabytes,
                                  then an end: a big session to measure reading

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
    elif verb != "rehash":
        sys.exit("unknown verb " + verb)
    write(path, rehash(lines), ended)


main()
