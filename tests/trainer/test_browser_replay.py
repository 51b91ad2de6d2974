"""A session replayed in the trainer's page in a real browser (issue 38):
headless Chromium, through chromedriver and Selenium, opens the page of
`trainer --session` for a recorded drive, seeks with the time slider, plays
at 8x, pauses, and reads back the pose the page drew (the #vehicle element's
data-x, data-y, data-heading, data-t-ms). Judged by data only: each pose the
page drew, seeking or playing, is the one GET /motion gives for its time; a
paused page's time stays; playing moves it on to the end. No bound on how
fast the browser goes. Keeps a screenshot.

  /usr/bin/python3 test_browser_replay.py BIN DATA_DIR SCREENSHOT.png"""
import json
import os
import subprocess
import sys
import tempfile
import time
import urllib.request

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from browser_lib import fail, failures, free_port, headless_chrome  # noqa: E402

binary, data, shot = sys.argv[1:4]
WAIT = 120  # seconds: only a bound on a stuck page, never a verdict on speed


def get(port, path):
    with urllib.request.urlopen(f"http://127.0.0.1:{port}{path}", timeout=5) as r:
        return json.loads(r.read())


def until(what, check):
    deadline = time.monotonic() + WAIT
    while time.monotonic() < deadline:
        got = check()
        if got:
            return got
        time.sleep(0.05)
    raise SystemExit(f"FAIL: {what} never came")


tmp = tempfile.mkdtemp()
env = dict(os.environ, XDG_STATE_HOME=tmp, XDG_CONFIG_HOME=tmp)
drive = os.path.join(data, "trainer", "browser_drive.events")
# The session: a live trainer run on the drive, recorded.
subprocess.run([binary, "trainer", "--listen", f"127.0.0.1:{free_port()}", "--input", drive, "--exit-at-end"],
               env=env, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
folder = os.path.join(tmp, "andros-bridge")
session = os.path.join(folder, next(f for f in os.listdir(folder) if f.endswith(".andros-session")))

port = free_port()
driver = None
trainer = subprocess.Popen([binary, "trainer", "--session", session, "--listen", f"127.0.0.1:{port}"],
                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env)
try:
    def replay_data():
        try:
            return get(port, "/replay")
        except OSError:
            if trainer.poll() is not None:
                raise SystemExit("FAIL: trainer --session ended")
            return None

    rep = until("the replay's page", replay_data)
    length = rep["length_ms"]
    driver = headless_chrome()
    driver.get(f"http://127.0.0.1:{port}/")

    def drawn():
        return driver.execute_script(
            "const v = document.getElementById('vehicle').dataset;"
            "return [Number(v.tMs), Number(v.x), Number(v.y), Number(v.heading)];")

    def server_pose(t_ms):
        p = get(port, f"/motion?t={t_ms / 1000:.3f}")["pose"]
        return [p["x"], p["y"], p["heading"]]

    until("the page in replay mode at 0", lambda: driver.execute_script(
        "return document.body.classList.contains('replay')") and drawn()[0] == 0)

    # The state lane: the plot's colours, enabled's green among them.
    lane = driver.execute_script(
        "return [...document.querySelectorAll('#lane rect')].map(r => [r.dataset.state, r.getAttribute('fill')]);")
    if ["enabled", "#4caf50"] not in lane:
        fail(f"the state lane has no enabled span in the plot's green: {lane}")

    # Seek: the slider moved to a time; the page draws the pose /motion gives then.
    for t in (length // 2, 1234, length):
        driver.execute_script(
            "const s = document.getElementById('slider'); s.value = arguments[0];"
            "s.dispatchEvent(new Event('input'));", t)
        got = until(f"the page at {t} ms after a seek", lambda: (lambda d: d if d[0] == t else None)(drawn()))
        if got[1:] != server_pose(t):
            fail(f"seek to {t} ms: the page drew {got[1:]}, /motion says {server_pose(t)}")
    driver.save_screenshot(shot)

    # Play at 8x from the start (play at the end starts again): every pose drawn is /motion's for its time.
    driver.execute_script("document.getElementById('speed').value = '8';")
    driver.execute_script("document.getElementById('slider').value = 0;"
                          "document.getElementById('slider').dispatchEvent(new Event('input'));")
    until("the page at 0", lambda: drawn()[0] == 0)
    driver.find_element("id", "play").click()
    seen = []
    deadline = time.monotonic() + WAIT
    while time.monotonic() < deadline:
        d = drawn()
        if not seen or d[0] != seen[-1][0]:
            seen.append(d)
        if d[0] == length:
            break
        time.sleep(0.02)
    times = [d[0] for d in seen]
    if times[-1] != length or times != sorted(times) or len(set(times)) < 3:
        fail(f"playing did not move on to the end in order: {times}")
    for d in seen:
        if d[1:] != server_pose(d[0]):
            fail(f"playing, at {d[0]} ms the page drew {d[1:]}, /motion says {server_pose(d[0])}")
    if driver.find_element("id", "play").text != "play":
        fail("at the end the button does not offer play again")

    # Pause: at 0.25x from the start, paused once it has moved; its time then stays.
    driver.execute_script("document.getElementById('speed').value = '0.25';")
    driver.find_element("id", "play").click()  # at the end: from the start again
    until("the page playing from the start", lambda: 0 < drawn()[0] < length)
    driver.find_element("id", "play").click()
    paused = int(driver.execute_script("return document.getElementById('slider').value"))
    until(f"the page at the paused time {paused}", lambda: drawn()[0] == paused)
    time.sleep(1)
    if drawn()[0] != paused or int(driver.execute_script("return document.getElementById('slider').value")) != paused:
        fail(f"paused at {paused} ms, the page moved on to {drawn()[0]}")
    print(f"replay page: {len(seen)} poses drawn playing at 8x over {length} ms, each /motion's; paused at {paused} ms")
finally:
    if driver:
        driver.quit()
    trainer.terminate()
    trainer.wait()
if failures:
    sys.exit(1)
