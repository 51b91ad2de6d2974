#!/usr/bin/env python3
"""Says what in an output file is raw text from outside, as issue 34 asks no
output to hold: a control byte (but the newline that ends a line, and the
tab, CR or ESC the format itself allows when given), invalid UTF-8, a C1
control, a bidirectional override or another invisible formatting character.

  check_text.py FILE [ALLOWED...]   exit 1 and the first such thing, with where it is

ALLOWED: tab, cr, esc (a format's own: an SVG's indentation is none of them).
Written apart from base/text.cpp: the oracle is the issue's words.
"""
import sys

INVISIBLE = {0x00AD, 0x061C, 0x180E, 0xFEFF} | set(range(0x200B, 0x2010)) | set(range(0x2028, 0x202F)) | \
    set(range(0x2060, 0x2070))
ALLOW = {"tab": 0x09, "cr": 0x0D, "esc": 0x1B}


def first_raw(data, allowed):
    try:
        text = data.decode("utf-8", errors="strict")
    except UnicodeDecodeError as e:
        return f"invalid UTF-8 at byte {e.start}: {data[max(0, e.start - 20):e.start + 5]!r}"
    for i, c in enumerate(text):
        o = ord(c)
        if c == "\n" or o in allowed:
            continue
        if o < 0x20 or o == 0x7F or 0x80 <= o <= 0x9F or o in INVISIBLE:
            return f"U+{o:04X} at character {i}: {text[max(0, i - 30):i + 5]!r}"
    return None


def main():
    allowed = {ALLOW[a] for a in sys.argv[2:]}
    problem = first_raw(open(sys.argv[1], "rb").read(), allowed)
    if problem:
        print(problem)
        sys.exit(1)


main()
