"""What the trainer's browser tests share: the failures, a free port, and
headless Chromium at the page's own 1280x720 (Debian's chromium,
chromium-driver and python3-selenium)."""
import socket
import sys

from selenium import webdriver
from selenium.webdriver.chrome.options import Options
from selenium.webdriver.chrome.service import Service

failures = []


def fail(why):
    print("FAIL:", why, file=sys.stderr)
    failures.append(why)


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def headless_chrome():
    """Chromium through chromedriver, its page 1280x720 whatever the window's frame takes."""
    options = Options()
    for arg in ["--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                "--window-size=1280,720", "--hide-scrollbars"]:
        options.add_argument(arg)
    driver = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)
    driver.execute_cdp_cmd("Emulation.setDeviceMetricsOverride",
                           {"width": 1280, "height": 720, "deviceScaleFactor": 1, "mobile": False})
    return driver
