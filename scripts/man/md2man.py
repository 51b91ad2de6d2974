"""Markdown (the subset docs/ uses) to man(7) roff, so that a man page made
from a docs/ page says exactly what the page says.

Headings, paragraphs, fenced code, lists, tables, inline code, bold, italics
and links. A table becomes a tagged list (first column as the tag): it stays
readable in 80 columns, which a wide tbl table would not.
"""
import re

_INLINE = [
    (re.compile(r"\[([^\]]+)\]\(#[^)]*\)"), r"\1"),  # in-page link: its text
    (re.compile(r"\[([^\]]+)\]\(([^)]+)\)"), r"\1 (\2)"),
    (re.compile(r"\*\*([^*]+)\*\*"), r"\\fB\1\\fR"),
    (re.compile(r"(?<![\w*])\*([^*\s][^*]*)\*(?![\w*])"), r"\\fI\1\\fR"),
]


def escape(text):
    """Roff-safe text: backslashes, and a leading dot or quote."""
    text = text.replace("\\", "\\e").replace("-", "\\-")
    if text.startswith((".", "'")):
        text = "\\&" + text
    return text


def inline(text):
    text = re.sub(r"\[([^\]]+)\]\(#[^)]*\)", r"\1", text)  # before code spans: [`extends`](#extends)
    parts = re.split(r"(`[^`]*`)", text)
    out = []
    for part in parts:
        if part.startswith("`") and part.endswith("`") and len(part) >= 2:
            out.append("\\fB" + escape(part[1:-1]) + "\\fR")
        else:
            part = escape(part)
            for rx, rep in _INLINE:
                part = rx.sub(rep, part)
            out.append(part)
    line = "".join(out)
    return "\\&" + line if line.startswith((".", "'")) else line


def _cells(row):
    return [c.strip() for c in row.strip().strip("|").split("|")]


def convert(markdown, skip_title=True):
    """The body of a man page (no .TH) from a markdown document."""
    out = []
    lines = markdown.splitlines()
    i = 0
    para = []

    def flush():
        if para:
            out.append(".PP")
            out.append(inline(" ".join(para)))
            para.clear()

    while i < len(lines):
        line = lines[i]
        stripped = line.strip()
        if stripped.startswith("```"):
            flush()
            i += 1
            out += [".PP", ".RS 4", ".nf"]
            while i < len(lines) and not lines[i].strip().startswith("```"):
                out.append(escape(lines[i]) if lines[i] else "")
                i += 1
            out += [".fi", ".RE"]
        elif stripped.startswith("#"):
            flush()
            level = len(stripped) - len(stripped.lstrip("#"))
            title = stripped[level:].strip()
            if level == 1:
                if not skip_title:
                    out += [".SH " + inline(title).upper()]
            elif level == 2:
                out.append('.SH "' + inline(title).upper().replace('"', "") + '"')
            else:
                out.append('.SS "' + inline(title).replace('"', "") + '"')
        elif stripped.startswith("|"):
            flush()
            rows = []
            while i < len(lines) and lines[i].strip().startswith("|"):
                rows.append(_cells(lines[i]))
                i += 1
            i -= 1
            header, body = rows[0], [r for r in rows[1:] if not all(set(c) <= set("-: ") for c in r)]
            for row in body:
                out += [".TP", inline(row[0]) or "\\&"]
                rest = [(header[k] if k < len(header) else "", c) for k, c in enumerate(row) if k > 0 and c]
                if len(rest) == 1:
                    out.append(inline(rest[0][1]))
                else:
                    out.append(inline("; ".join(f"{h}: {c}" if h else c for h, c in rest)))
        elif re.match(r"^\s*[-*]\s+\[[^\]]+\]\(#", line):
            flush()  # a list of in-page links: a table of contents the man page's sections replace
            while i + 1 < len(lines) and re.match(r"^\s*[-*]\s+\[[^\]]+\]\(#", lines[i + 1]):
                i += 1
        elif re.match(r"^\s*([-*]|\d+\.)\s+", line):
            flush()
            m = re.match(r"^(\s*)([-*]|\d+\.)\s+(.*)$", line)
            indent, mark, text = len(m.group(1)), m.group(2), m.group(3)
            item = [text]
            while i + 1 < len(lines) and lines[i + 1].strip() and not re.match(r"^\s*([-*]|\d+\.)\s+", lines[i + 1]) \
                    and not lines[i + 1].strip().startswith(("#", "|", "```")):
                i += 1
                item.append(lines[i].strip())
            tag = "\\(bu" if mark in "-*" else mark
            if indent:
                out.append(".RS 4")
            out += [".IP " + tag + " 4", inline(" ".join(item))]
            if indent:
                out.append(".RE")
        elif not stripped:
            flush()
        else:
            para.append(stripped)
        i += 1
    flush()
    return "\n".join(out) + "\n"


def page(name, section, title, body, date, version):
    """A whole page: .TH, NAME, then body."""
    head = [
        f'.TH "{name.upper()}" "{section}" "{date}" "andros-bridge {version}" "andros-bridge"',
        ".SH NAME",
        f"{escape(name)} \\- {escape(title)}",
    ]
    if body.startswith(".PP"):
        head.append(".SH DESCRIPTION")
    return "\n".join(head) + "\n" + body
