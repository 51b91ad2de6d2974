"""The trainer's page in a real browser (issue 37): headless Chromium, driven
through chromedriver and Selenium (Debian's chromium, chromium-driver and
python3-selenium), opens the page while a scripted drive runs, reads the pose
of the vehicle it drew (the #vehicle element's data-x, data-y, data-heading,
data-tick, data-time) and checks that it follows the stream: each pose it
drew is the one GET /events gave in the object it drew (its time), the ticks it drew move on while
the vehicle drives, and at rest it is /state's. No bound on how far behind a
busy machine lets the page fall: the verdict is the same on any machine.
Keeps a screenshot.

  /usr/bin/python3 test_browser.py BIN DATA_DIR SCREENSHOT.png [DOCS_PNG]

DOCS_PNG (docs/trainer.png) must be a 1280x720 screenshot of the page as the
binary serves it now, from the drive as committed: it carries (a PNG text
chunk) the SHA-256 of the page and the drive it was taken from, which must be
those of this run. With ANDROS_DOCS_SCREENSHOT=1 this run's screenshot, with
that digest, replaces it (how the docs' picture is made again after the page
or the drive changes)."""
import hashlib
import json
import os
import shutil
import signal
import subprocess
import http.client
import sys
import tempfile
import threading
import time
import urllib.request
import zlib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from browser_lib import fail, failures, free_port, headless_chrome  # noqa: E402

binary, data, shot = sys.argv[1:4]
docs_png = sys.argv[4] if len(sys.argv) > 4 else None


def state(port):
    with urllib.request.urlopen(f"http://127.0.0.1:{port}/state", timeout=2) as r:
        return json.loads(r.read())


def cpu_seconds(pids):
    """User and system CPU of these processes so far (their own, /proc)."""
    total = 0
    for pid in pids:
        try:
            with open(f"/proc/{pid}/stat") as f:
                fields = f.read().rsplit(")", 1)[1].split()
            total += int(fields[11]) + int(fields[12])
        except OSError:
            pass
    return total / os.sysconf("SC_CLK_TCK")


def descendants(pid):
    """Every process under pid (chromedriver's browser and its helpers), from /proc."""
    parent = {}
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                with open(f"/proc/{entry}/stat") as f:
                    parent[int(entry)] = int(f.read().rsplit(")", 1)[1].split()[1])
            except OSError:
                pass
    out, todo = [], [pid]
    while todo:
        p = todo.pop()
        kids = [k for k, v in parent.items() if v == p]
        out += kids
        todo += kids
    return out


def read_stream(port, poses):
    """Every object of GET /events, as {time: (x, y, heading)}, until the stream ends."""
    conn = http.client.HTTPConnection("127.0.0.1", port, timeout=60)
    try:
        conn.request("GET", "/events", headers={"Host": f"127.0.0.1:{port}"})
        resp = conn.getresponse()
        for line in resp:
            if line.startswith(b"data: "):
                o = json.loads(line[6:])
                poses[round(o["time"], 6)] = (o["pose"]["x"], o["pose"]["y"], o["pose"]["heading"])
    except (OSError, ValueError, http.client.HTTPException):
        pass  # the trainer ended, or dropped this reader: the ticks it saw are checked


DIGEST_KEY = b"andros-trainer-page-sha256"


def png_chunks(blob):
    """(type, data) of each chunk of a PNG file."""
    at, out = 8, []
    while at + 8 <= len(blob):
        size = int.from_bytes(blob[at:at + 4], "big")
        out.append((blob[at + 4:at + 8], blob[at + 8:at + 8 + size]))
        at += 12 + size
    return out


def png_digest(path):
    """The page digest a screenshot carries (its tEXt chunk), None when none."""
    with open(path, "rb") as f:
        for kind, data in png_chunks(f.read()):
            if kind == b"tEXt" and data.startswith(DIGEST_KEY + b"\0"):
                return data[len(DIGEST_KEY) + 1:].decode()
    return None


def with_digest(source, target, digest):
    """Copies the PNG source to target with the digest as a tEXt chunk after its header."""
    with open(source, "rb") as f:
        blob = f.read()
    header_end = 8 + 12 + int.from_bytes(blob[8:12], "big")
    data = DIGEST_KEY + b"\0" + digest.encode()
    chunk = len(data).to_bytes(4, "big") + b"tEXt" + data + zlib.crc32(b"tEXt" + data).to_bytes(4, "big")
    with open(target, "wb") as f:
        f.write(blob[:header_end] + chunk + blob[header_end:])


port = free_port()
drive_events = os.path.join(data, "trainer", "browser_drive.events")
tmp = tempfile.mkdtemp()
env = dict(os.environ, XDG_STATE_HOME=tmp, XDG_CONFIG_HOME=tmp)
driver = None
trainer = None
digest = None
try:
    # The browser first (its start is the slow part on a busy machine), then
    # the drive, so that the page sees the drive whatever the machine's speed.
    driver = headless_chrome()
    trainer = subprocess.Popen([binary, "trainer", "--listen", f"127.0.0.1:{port}", "--input", drive_events],
                               stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, env=env)
    deadline = time.monotonic() + 60
    while True:
        try:
            state(port)
            break
        except OSError:
            if time.monotonic() > deadline:
                raise SystemExit("FAIL: the trainer's page never answered")
            time.sleep(0.05)
    # What the screenshot shows: the page as served, the drive as committed.
    with urllib.request.urlopen(f"http://127.0.0.1:{port}/", timeout=2) as r, open(drive_events, "rb") as f:
        digest = hashlib.sha256(r.read() + b"\0" + f.read()).hexdigest()
    stream = {}
    threading.Thread(target=read_stream, args=(port, stream), daemon=True).start()
    driver.get(f"http://127.0.0.1:{port}/")
    browser = descendants(driver.service.process.pid)
    cpu0, wall0 = cpu_seconds(browser), time.monotonic()

    drawn = lambda: driver.execute_script(
        "const v = document.getElementById('vehicle').dataset;"
        "return [Number(v.x), Number(v.y), Number(v.heading), Number(v.tick), Number(v.time)];")
    samples = []
    shot_taken = False
    # Sample the page while the drive (12.8 s) runs, to its end.
    ended = False
    while not ended and time.monotonic() - wall0 < 120:
        samples.append(drawn())
        s = state(port)
        ended = s["state_name"] == "ended"
        if not shot_taken and s["tick"] >= 300:  # 12 s into the drive
            driver.save_screenshot(shot)
            shot_taken = True
        time.sleep(0.2)
    cpu = cpu_seconds(browser) - cpu0
    wall = time.monotonic() - wall0
    print(f"chromium: {cpu:.2f} s of CPU in {wall:.1f} s ({100 * cpu / wall:.0f}% of a core) drawing the page")

    # The page follows: each pose it drew is the stream's in the object it drew.
    moving = [p for p in samples if p[3] >= 0]
    checked = [p for p in moving if round(p[4], 6) in stream]
    if len({p[3] for p in moving}) < 3:
        fail(f"the page drew {len({p[3] for p in moving})} different ticks in {len(samples)} samples of a 12.8 s drive")
    if len(checked) < 3:
        fail(f"the stream gave {len(checked)} of the {len(moving)} objects the page drew")
    for p in checked:
        want = stream[round(p[4], 6)]
        if any(abs(a - b) > 1e-3 for a, b in zip(p[:3], want)):
            fail(f"the page drew {p[:3]} at tick {p[3]}, the stream's pose there is {want}")
    if max((p[0] for p in moving), default=0) < 3.0:
        fail("the drawn vehicle never moved 3 m forward")
    # At rest after the drive: the page comes to /state's pose exactly (as
    # soon as it has drawn the last frame: waited for, not timed).
    deadline = time.monotonic() + 60
    while True:
        page, s = drawn(), state(port)
        at_rest = [round(page[0], 3), round(page[1], 3), round(page[2], 3)] == \
            [s["pose"]["x"], s["pose"]["y"], s["pose"]["heading"]]
        if at_rest or time.monotonic() > deadline:
            break
        time.sleep(0.2)
    if not at_rest:
        fail(f"at rest, the page drew {page} and /state says {s['pose']}")
    if s["state_name"] != "ended":
        fail(f"after the script: state {s['state_name']!r}, expected 'ended' (the page kept up)")
    if not shot_taken:
        driver.save_screenshot(shot)
    if docs_png and os.environ.get("ANDROS_DOCS_SCREENSHOT") == "1":
        with_digest(shot, docs_png, digest)
finally:
    if driver:
        driver.quit()
    err = b""
    if trainer:
        trainer.send_signal(signal.SIGINT)
        try:
            _, err = trainer.communicate(timeout=30)
        except subprocess.TimeoutExpired:
            trainer.kill()
            _, err = trainer.communicate()
    shutil.rmtree(tmp, ignore_errors=True)
if trainer is None or trainer.returncode != 0:
    fail(f"the trainer exited {trainer.returncode if trainer else '(never started)'}: "
         f"{err.decode(errors='replace')[-600:]}")
print(f"screenshot: {shot}")
for png in [shot] + ([docs_png] if docs_png else []):
    with open(png, "rb") as f:
        head = f.read(24)
    size = (int.from_bytes(head[16:20], "big"), int.from_bytes(head[20:24], "big"))
    if not head.startswith(b"\x89PNG") or size != (1280, 720):
        fail(f"{png}: not a 1280x720 PNG ({size})")
if docs_png and png_digest(docs_png) != digest:
    fail(f"{docs_png} was taken from another page or drive than this run's (its digest {png_digest(docs_png)}, "
         f"this run's {digest}): ANDROS_DOCS_SCREENSHOT=1 ctest -R trainer.browser makes it again; look at it")
if failures:
    sys.exit(1)
print("all checks passed")
