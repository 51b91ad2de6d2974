#!/usr/bin/env python3
"""clang-tidy over the src/ files of a compile database, one file per core at
a time, each file's output kept in a cache (scripts/lint.sh --tidy runs it).
A unity group of src/ files (CMake's BUILD_DIR/src/CMakeFiles/*/Unity/*.cxx,
which #includes them) is checked as one file, each finding named by the
src/ file it is in.

    scripts/lint_tidy.py BUILD_DIR SOURCE_DIR LOG

A file's output is looked up by a key made of what it depends on: clang-tidy's
version and arguments, .clang-tidy, the file's compile command, and the text
of the file and of every header it includes (project and system headers alike,
as the compiler lists them with -M). Any change to one of them runs the file
again; nothing else does. Paths inside the source tree are keyed and kept
relative to it, so that another clone of it finds the same results. Files
not in the cache go to clang-tidy longest first (by the bytes the compiler
reads for them), so that the run does not end on one long file alone. The
cache is ANDROS_TIDY_CACHE (default ~/.cache/andros-bridge/clang-tidy;
'none': no cache); an entry not used for 30 days is removed. Every file's
output goes to LOG, in the database's order.
"""

import concurrent.futures
import hashlib
import json
import os
import shlex
import signal
import subprocess
import sys
import time
from pathlib import Path

TIDY_ARGS = ["--quiet"]
# A unity group's own lines #include .cpp files, which is what it is for.
UNITY_ARGS = ["--checks=-bugprone-suspicious-include"]
MAX_AGE_DAYS = 30


def dependencies(entry):
    """The files the compiler reads for entry (its -M list), or None when it cannot say."""
    args = shlex.split(entry["command"]) if "command" in entry else list(entry["arguments"])
    out, skip = [], False
    for a in args:
        if skip:
            skip = False
        elif a == "-o":
            skip = True
        elif a != "-c":
            out.append(a)
    run = subprocess.run(out + ["-M"], cwd=entry["directory"], capture_output=True, text=True)
    if run.returncode != 0:
        return None
    words = run.stdout.replace("\\\n", " ").split()
    return [os.path.join(entry["directory"], w) for w in words[1:]]  # words[0] is "TARGET:"


class Hasher:
    """A file's SHA-256, the source tree's folder in it made relative (a unity
    group names its files by their whole path)."""

    def __init__(self, relative):
        self.known = {}
        self.relative = relative

    def file(self, path):
        if path not in self.known:
            self.known[path] = hashlib.sha256(self.relative(Path(path).read_bytes())).hexdigest()
        return self.known[path]


def main():
    build, source, log = Path(sys.argv[1]), Path(sys.argv[2]).resolve(), Path(sys.argv[3])
    jobs = os.cpu_count() or 1
    unity = (build / "src" / "CMakeFiles").resolve()

    def is_unity(entry):
        path = Path(entry["file"]).resolve()
        return path.is_relative_to(unity) and path.parent.name == "Unity"

    entries = [e for e in json.loads((build / "compile_commands.json").read_text())
               if Path(e["file"]).resolve().is_relative_to(source / "src") or is_unity(e)]
    cache_dir = os.environ.get("ANDROS_TIDY_CACHE",
                               os.path.join(os.environ.get("XDG_CACHE_HOME", Path.home() / ".cache"),
                                            "andros-bridge", "clang-tidy"))
    cache = None if cache_dir == "none" else Path(cache_dir)
    if cache:
        cache.mkdir(parents=True, exist_ok=True)
        now = time.time()
        for old in cache.iterdir():
            if now - old.stat().st_mtime > MAX_AGE_DAYS * 86400:
                old.unlink(missing_ok=True)

    prefix = str(source).encode() + b"/"

    def relative(text):
        # The tree as a folder (SOURCE/...) and as a flag's value (-fdebug-prefix-map=SOURCE=.).
        return text.replace(prefix, b"@SOURCE@/").replace(str(source).encode() + b"=", b"@SOURCE@=")

    common = hashlib.sha256()
    common.update(subprocess.run(["clang-tidy", "--version"], capture_output=True, check=True).stdout)
    common.update(" ".join(TIDY_ARGS).encode())
    common.update((source / ".clang-tidy").read_bytes())
    hasher = Hasher(relative)

    def key_of(entry):
        """The entry's cache key (None: no cache for it) and the bytes it reads (its cost)."""
        deps = dependencies(entry)
        if deps is None:
            return None, 0
        h = common.copy()
        h.update(" ".join(UNITY_ARGS if is_unity(entry) else []).encode() + b"\0")
        h.update(relative((entry["directory"] + "\0" + entry.get("command", " ".join(entry.get("arguments", [])))).encode()))
        for d in deps:
            h.update(relative(d.encode()) + b"\0" + hasher.file(d).encode())
        return h.hexdigest(), sum(os.path.getsize(d) for d in deps)

    running = set()

    def tidy(entry, key):
        extra = UNITY_ARGS if is_unity(entry) else []
        proc = subprocess.Popen(["clang-tidy", "-p", str(build), *TIDY_ARGS, *extra, entry["file"]],
                                stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        running.add(proc)
        out = proc.communicate()[0]
        running.discard(proc)
        # Kept only when clang-tidy ran to its end (an error in the file is not cached).
        if cache and key and proc.returncode == 0:
            tmp = cache / f"{key}.{os.getpid()}.tmp"
            tmp.write_bytes(relative(out))
            tmp.replace(cache / key)
        return out

    def stop(*_):
        for proc in list(running):
            proc.kill()
        os._exit(1)

    signal.signal(signal.SIGTERM, stop)
    signal.signal(signal.SIGINT, stop)

    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        keys = list(pool.map(key_of, entries))
        outputs, missed = [None] * len(entries), []
        for i, (entry, (key, cost)) in enumerate(zip(entries, keys)):
            hit = cache / key if cache and key else None
            if hit and hit.exists():
                hit.touch()
                outputs[i] = hit.read_bytes().replace(b"@SOURCE@/", prefix)
            else:
                missed.append((cost, i))
        for _, i in sorted(missed, reverse=True):
            outputs[i] = pool.submit(tidy, entries[i], keys[i][0])
        checked = len(missed)
        with log.open("wb") as f:
            for out in outputs:
                f.write(out if isinstance(out, bytes) else out.result())
    print(f"tidy: {checked} of {len(entries)} files checked, the others' results taken from the cache ({cache})"
          if cache else f"tidy: {checked} files checked (no cache)")


if __name__ == "__main__":
    main()
