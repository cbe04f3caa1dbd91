"""The live console beyond loopback (argus serve --bind 0.0.0.0): it prints its secret once, as
?token= on its address; without it every request gets HTTP 401, commands included; in a real
browser (headless Chromium) the address without the secret shows the refusal, and with it the
page runs: the plan view and the feeds update (their requests carry the cookie the first page
set) and a command from the page takes effect.

  python3 serve_token_test.py ARGUS SCENARIO OUT

Prints "SKIPPED: ..." and exits 0 only where Chromium, chromedriver or Selenium is missing.
"""
import json
import os
import shutil
import sys
import urllib.error
import urllib.request

from serve_session import Serve
from serve_browser_test import browser, skip  # noqa: F401 (skips where no browser exists)

from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import Select, WebDriverWait


def status_of(url, data=None, headers=None):
    req = urllib.request.Request(url, data=data, method="POST" if data else "GET",
                                 headers=headers or {})
    try:
        with urllib.request.urlopen(req, timeout=10) as res:
            return res.status
    except urllib.error.HTTPError as e:
        return e.code


def main(argus, scenario, out):
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    live = os.path.join(out, "live")
    serve = Serve(argus, scenario, live, "--bind", "0.0.0.0", "--speed", "1", "--duration", "40s",
                  "--threads", "2")
    driver = None
    try:
        assert len(serve.token) == 32, "no secret printed beyond loopback: %r" % serve.token
        # Without the secret (or with a wrong one) nothing answers but 401, commands included.
        crash = json.dumps({"op": "crash", "camera": 1}).encode()
        for path in ("/", "/state", "/plan.png", "/feed/1.jpg", "/events"):
            assert status_of(serve.url + path) == 401, path
        assert status_of(serve.url + "/?token=" + "0" * 32) == 401
        assert status_of(serve.url + "/command", crash,
                         {"Content-Type": "application/json"}) == 401
        assert status_of(serve.url + "/state",
                         headers={"Authorization": "Bearer " + "f" * 32}) == 401
        assert serve.state()["tick"] >= 0  # with the secret (Authorization: Bearer)
        print("without the secret: 401 for the page, the state, the feeds, the stream, commands")

        driver = browser(os.path.join(out, "profile"))
        driver.get(serve.url + "/")
        body = driver.find_element(By.TAG_NAME, "body").text
        assert "needs its secret" in body, body
        print("browser without the secret: %r" % body.splitlines()[0])

        driver.get(serve.url + "/?token=" + serve.token)
        wait = WebDriverWait(driver, 60, poll_frequency=0.2)
        wait.until(lambda d: int(d.execute_script("return document.body.dataset.tick || 0")) > 15)
        frames = lambda d: int(d.execute_script(  # noqa: E731
            "return Number(document.getElementById('feed').dataset.frames || 0)"))
        wait.until(lambda d: frames(d) >= 3)
        # A command from the page: full speed, as the operator would set it.
        Select(driver.find_element(By.ID, "speed")).select_by_value("0")
        print("browser with the secret: tick %s, %d feed frames, speed set from the page" % (
            driver.execute_script("return document.body.dataset.tick"), frames(driver)))
        wait.until(lambda d: serve.state()["speed"] == 0)
        serve.finish()
    finally:
        if driver:
            driver.quit()
        serve.kill()
    for name in os.listdir(live):
        path = os.path.join(live, name)
        if os.path.isfile(path) and serve.token in open(path, errors="replace").read():
            raise AssertionError("the secret was written to %s" % path)
    print("the secret is in no file of the run")


if __name__ == "__main__":
    main(*sys.argv[1:4])
