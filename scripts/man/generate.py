#!/usr/bin/env python3
"""Generates the man pages and the bash completion (docs/architecture.md).

usage: generate.py ANDROS_BRIDGE_BINARY SOURCE_DIR OUTPUT_DIR

One source each, so nothing can drift: andros-bridge(1) and the completion
come from the program's own command line (`andros-bridge help-data`, walked
from the CLI11 definitions that print --help); the keys of
andros-bridge.conf(5) from the settings table (through help-data), its prose
from docs/running.md; andros-bridge-mapping(5) and andros-bridge-events(5)
from the docs/ pages that users read.
"""
import datetime
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import completion  # noqa: E402
import md2man  # noqa: E402

SEE_ALSO = ["andros-bridge.conf(5)", "andros-bridge-mapping(5)", "andros-bridge-events(5)"]

FILES = [
    ("/etc/andros-bridge/andros-bridge.conf, ~/.config/andros-bridge/andros-bridge.conf",
     "the configuration file; see andros-bridge.conf(5)"),
    ("/usr/share/andros-bridge/mappings/", "the shipped mapping of each robot type; see andros-bridge-mapping(5)"),
    ("~/.config/andros-bridge/mappings/", "your own mappings, found first by --robot"),
    ("/usr/share/andros-bridge/demos/drive.events", "the demonstration drive; see andros-bridge-events(5)"),
]


def option_tag(opt):
    if opt["positional"]:
        return "\\fI" + md2man.escape(opt["positional"]) + "\\fR"
    names = ["\\fB\\-" + md2man.escape(s) + "\\fR" for s in opt["short"]]
    names += ["\\fB\\-\\-" + md2man.escape(n) + "\\fR" for n in opt["names"]]
    tag = ", ".join(names)
    if opt["value"]:
        tag += " \\fI" + md2man.escape(opt["value"]) + "\\fR"
    return tag


def text_lines(text):
    """Help text as roff: its lines joined into one paragraph that man fills to the terminal."""
    return md2man.escape(" ".join(line.strip() for line in text.splitlines() if line.strip()))


def command_section(cmd, prefix):
    out = []
    name = prefix + " " + cmd["name"]
    positionals = " ".join(o["positional"] for o in cmd["options"] if o["positional"])
    usage = name + (" [OPTIONS]" if any(not o["positional"] for o in cmd["options"]) else "")
    if cmd["commands"]:
        usage += " COMMAND"
    out += ['.SS "' + md2man.escape(usage + (" " + positionals if positionals else "")) + '"']
    if cmd["description"]:
        out += [text_lines(cmd["description"])]
    for opt in cmd["options"]:
        if opt["names"] == ["help"]:
            continue
        help_text = opt["help"]
        if opt["default"] and "default" not in help_text.lower():
            help_text += " (default: " + opt["default"] + ")"
        out += [".TP", option_tag(opt), text_lines(help_text)]
    for sub in cmd["commands"]:
        out += command_section(sub, name)
    return out


def manual_1(data, date):
    out = [
        '.TH "ANDROS\\-BRIDGE" "1" "%s" "andros-bridge %s" "andros-bridge"' % (date, data["version"]),
        ".SH NAME",
        "andros\\-bridge \\- drive an Andros robot's switchbox link from a gamepad",
        ".SH SYNOPSIS",
        "\\fBandros\\-bridge\\fR \\fICOMMAND\\fR [\\fIOPTIONS\\fR]",
        ".br",
        "\\fBandros\\-bridge\\fR \\fB\\-\\-help\\fR | \\fB\\-\\-version\\fR",
        ".SH DESCRIPTION",
        text_lines(data["description"]),
        ".PP",
        "Robot types: " + ", ".join(data["robots"]) + ".",
        ".SH COMMANDS",
    ]
    for cmd in data["commands"]:
        out += command_section(cmd, "andros-bridge")
    out += [".SH EXIT STATUS", text_lines(data["footer"].split("\n")[0])]
    out += [".SH FILES"]
    for path, what in FILES:
        out += [".TP", "\\fI" + md2man.escape(path) + "\\fR", md2man.escape(what)]
    out += [".SH SEE ALSO", ", ".join("\\fB" + md2man.escape(p.split("(")[0]) + "\\fR(" + p.split("(")[1]
                                     for p in SEE_ALSO)]
    return "\n".join(out) + "\n"


def config_keys(data):
    """KEYS of andros-bridge.conf(5), from the settings table."""
    out = [".SH KEYS"]
    for row in data["config_keys"]:
        tag = "\\fB" + md2man.escape(row["key"]) + "\\fR=\\fI" + md2man.escape(row["value"] or "enabled") + "\\fR"
        text = row["help"]
        if row["default"]:
            text += " (default: " + row["default"] + ")"
        if row["file_relative"]:
            text += "; a relative path is taken from the config file's folder"
        text += "; on the command line: " + row["flag"] + "."
        out += [".TP", tag, text_lines(text)]
    return "\n".join(out) + "\n"


def without_tables(markdown):
    """The page without its tables (a table the man page makes from the program instead)."""
    out = []
    for line in markdown.splitlines():
        if not line.lstrip().startswith("|"):
            out.append(line)
        else:
            prose = [i for i, l in enumerate(out) if l.strip()]
            if prose and out[prose[-1]].endswith(":"):
                out[prose[-1]] += " see KEYS below."
    return "\n".join(out)


def section(markdown, heading):
    """The '## heading' section of a page, its heading made the page's title."""
    lines = markdown.splitlines()
    start = lines.index("## " + heading)
    end = next((i for i in range(start + 1, len(lines)) if lines[i].startswith("## ")), len(lines))
    return "\n".join(["# " + heading] + lines[start + 1:end])


def main():
    binary, source, out_dir = sys.argv[1:4]
    data = json.loads(subprocess.run([binary, "help-data"], check=True, capture_output=True, text=True).stdout)
    # The date of the release, not of the build: pages built twice are identical.
    stamp = os.environ.get("SOURCE_DATE_EPOCH")
    date = datetime.datetime.fromtimestamp(int(stamp), datetime.timezone.utc) if stamp else None
    date = date.strftime("%Y-%m-%d") if date else "andros-bridge " + data["version"]
    docs = os.path.join(source, "docs")

    def read(name):
        with open(os.path.join(docs, name), encoding="utf-8") as f:
            return f.read()

    pages = {
        "andros-bridge.1": manual_1(data, date),
        "andros-bridge.conf.5": md2man.page(
            "andros-bridge.conf", "5", "the andros-bridge configuration file",
            md2man.convert(without_tables(section(read("running.md"), "The configuration file")))
            + config_keys(data), date, data["version"]),
        "andros-bridge-mapping.5": md2man.page(
            "andros-bridge-mapping", "5", "andros-bridge mapping files",
            md2man.convert(read("mapping.md")), date, data["version"]),
        "andros-bridge-events.5": md2man.page(
            "andros-bridge-events", "5", "andros-bridge event scripts",
            md2man.convert(read("event-scripts.md")), date, data["version"]),
    }
    os.makedirs(out_dir, exist_ok=True)
    for name, text in pages.items():
        with open(os.path.join(out_dir, name), "w", encoding="utf-8") as f:
            f.write(text)
    with open(os.path.join(out_dir, "andros-bridge.bash"), "w", encoding="utf-8") as f:
        f.write(completion.script(data))


if __name__ == "__main__":
    main()
