#!/usr/bin/env python3
"""Writes mixed_capture.bin and mixed_capture.expected: a serial capture that
mixes good frames with every kind of damage the decoder must survive.
Run from tests/data/ to regenerate (the output is committed)."""
import random

def encode(data):
    digits = data.hex().upper().encode()
    s = sum(digits) & 0xFFFF
    return b"\xF1\xF1" + digits + bytes([s & 0xFF, s >> 8])

def valid_data(rng, **fixed):
    d = bytearray(rng.randrange(256) for _ in range(16))
    d[2] |= 0x18; d[3] = (d[3] | 0x20) & ~0x50 & 0xFF; d[5] = (d[5] | 0x90) & ~0x60 & 0xFF; d[15] = 2
    for k, v in fixed.items(): d[int(k[1:])] = v
    return bytes(d)

def with_f1_checksum(rng):
    while True:
        d = valid_data(rng)
        f = encode(d)
        if f[34] == 0xF1:
            return d

rng = random.Random(2004)
out = bytearray(); expected = []
def frame(d, verdict, raw=None):
    expected.append((len(out), d.hex().upper(), verdict))
    out.extend(raw if raw is not None else encode(d))

out += b"\x00\x13garb"                                  # garbage
frame(valid_data(rng), "valid")
out += b"\xF1\xF1Z0123"                                 # false start: F1 F1 then a non-digit
out += b"\xF1\xF1" + b"0123456789"                      # truncated frame...
frame(valid_data(rng), "valid")                          # ...and the frame right after it
out += b"\xF1"                                          # a lone F1
frame(with_f1_checksum(rng), "valid")                    # checksum low byte F1
lost = valid_data(rng)
frame(lost, "bad_checksum", encode(lost)[:34])           # lost its checksum...
frame(valid_data(rng), "valid")                          # ...the next frame is still found
bad15 = bytearray(valid_data(rng)); bad15[15] = 3
frame(bytes(bad15), "invalid")                           # checksum right, byte 15 wrong
corrupt = valid_data(rng)
raw = bytearray(encode(corrupt)); raw[34] ^= 0x01
frame(corrupt, "bad_checksum", bytes(raw))               # corrupted checksum
out += b"\xF1"                                          # F1 F1 F1: the start is the second pair
frame(with_f1_checksum(rng), "valid")
frame(with_f1_checksum(rng), "valid")                    # F1 checksum right before a frame
frame(valid_data(rng), "valid")
out += b"\xF1\xF1" + b"ABCDEF0123456789ABCD"            # truncated at the end of the capture

open("mixed_capture.bin", "wb").write(out)
with open("mixed_capture.expected", "w") as f:
    f.write("# offset data verdict (written by make_mixed_capture.py)\n")
    for o, d, v in expected:
        f.write(f"{o} {d} {v}\n")
