"""The live console end to end in a real browser (headless Chromium through Selenium): the page
loads, the plan view and a feed update, a click on a pedestrian in a feed starts a task that
appears on the page and in the events, and a camera crashed from the page dies in the events.

  python3 serve_browser_test.py ARGUS SCENARIO OUT

Prints "SKIPPED: ..." and exits 0 only where Chromium, chromedriver or Selenium is missing.
"""
import json
import os
import shutil
import sys
import time

from serve_session import Serve


def skip(why):
    print("SKIPPED: %s (Debian packages chromium, chromium-driver, python3-selenium; "
          "scripts/setup.sh installs them)" % why)
    sys.exit(0)


try:
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    from selenium.webdriver.common.action_chains import ActionChains
    from selenium.webdriver.common.by import By
    from selenium.common.exceptions import TimeoutException
    from selenium.webdriver.support.ui import Select, WebDriverWait
except ImportError:
    skip("Python's selenium is not installed")

CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
DRIVER = shutil.which("chromedriver") or (
    "/usr/bin/chromedriver" if os.path.exists("/usr/bin/chromedriver") else None)
if not CHROMIUM:
    skip("chromium is not installed")
if not DRIVER:
    skip("chromedriver is not installed")


def browser(profile):
    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    for flag in ("--headless", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                 "--window-size=1600,1200", "--user-data-dir=" + profile):
        options.add_argument(flag)
    return webdriver.Chrome(service=Service(DRIVER), options=options)


def main(argus, scenario, out):
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    live = os.path.join(out, "live")
    serve = Serve(argus, scenario, live, "--speed", "1", "--duration", "60s", "--threads", "2")
    driver = None
    try:
        driver = browser(os.path.join(out, "profile"))
        wait = WebDriverWait(driver, 60, poll_frequency=0.2)
        driver.get(serve.url + "/")
        # The plan view and a feed update.
        wait.until(lambda d: int(d.execute_script("return document.body.dataset.tick || 0")) > 15)
        tick = int(driver.execute_script("return document.body.dataset.tick"))
        wait.until(lambda d: int(d.execute_script("return document.body.dataset.tick")) > tick)
        assert driver.execute_script("return document.getElementById('plan-canvas').width") > 0
        frames = lambda d: int(d.execute_script(  # noqa: E731
            "return Number(document.getElementById('feed').dataset.frames || 0)"))
        wait.until(lambda d: frames(d) >= 3)
        print("page: plan view at tick %s, %d feed frames" % (
            driver.execute_script("return document.body.dataset.tick"), frames(driver)))

        # A click on a pedestrian in a feed: pause, pick a camera that sees someone, click her.
        camera, x, y = serve.pause_on_someone()
        known = {t["task"] for t in serve.state()["tasks"]}
        wait.until(lambda d: d.find_element(By.ID, "run-state").text == "paused")
        Select(driver.find_element(By.ID, "camera")).select_by_value(str(camera))
        seen = frames(driver)
        wait.until(lambda d: frames(d) >= seen + 2)  # the feed now shows that camera
        feed = driver.find_element(By.ID, "feed")
        shown = driver.execute_script(  # the size of the frame the page shows
            "const i = arguments[0]; return [Number(i.dataset.width), Number(i.dataset.height)]",
            feed)
        size = feed.size
        dx = x * size["width"] / shown[0] - size["width"] / 2
        dy = y * size["height"] / shown[1] - size["height"] / 2
        ActionChains(driver).move_to_element_with_offset(feed, dx, dy).click().perform()
        try:
            wait.until(lambda d: "queued" in d.find_element(By.ID, "reply").text)
        except TimeoutException:
            raise AssertionError("the click at (%d, %d) on camera %d's feed queued no task; the "
                                 "page says %r, its feed %r" % (
                                     x, y, camera, driver.find_element(By.ID, "reply").text,
                                     driver.find_element(By.ID, "feed-source").text))
        driver.find_element(By.ID, "pause").click()
        wait.until(lambda d: d.find_element(By.ID, "run-state").text == "running")

        # The tables are redrawn with every message: read them in one script, not element by
        # element (an element may be gone by the next call).
        def task_row(d):
            rows = d.execute_script(
                "return [...document.querySelectorAll('#tasks tr')]"
                ".map(r => [...r.cells].map(c => c.textContent))")
            for cells in rows:
                if cells and cells[1] == str(camera) and int(cells[0]) not in known:
                    return cells
            return None
        wait.until(lambda d: task_row(d) and task_row(d)[3] != "issued")
        row = task_row(driver)
        print("page: task %s through camera %d: %s" % (row[0], camera, row[3]))
        assert row[3] == "observed", "the task did not start: " + row[3]

        # Crash a camera from the page.
        victim = next(c["id"] for c in serve.state()["cameras"]
                      if c["alive"] and c["id"] != camera)
        Select(driver.find_element(By.ID, "camera")).select_by_value(str(victim))
        driver.find_element(By.ID, "crash").click()
        wait.until(lambda d: d.execute_script(
            "const r = document.querySelector(\"#cameras tr[data-camera='%d']\");"
            "return r !== null && r.className === 'dead'" % victim))
        fps = driver.find_element(By.ID, "feed-fps").text
        print("page: camera %d crashed; feed at %s frames/s" % (victim, fps))

        # Let the run finish at full speed, then read the log.
        Select(driver.find_element(By.ID, "speed")).select_by_value("0")
        serve.finish()
    finally:
        if driver:
            driver.quit()
        serve.kill()
    events = [json.loads(line) for line in open(os.path.join(live, "events.jsonl"))]
    task = int(row[0])
    issued = [e for e in events if e["kind"] == "task_issued" and e["task"] == task]
    assert issued and issued[0]["by"] == "pixel" and issued[0]["camera"] == camera, issued
    started = [e for e in events if e["kind"] == "task_target" and e["task"] == task]
    assert started, "no task_target for the clicked task"
    crashed = [e for e in events if e["kind"] == "fault" and e["fault"] == "crash" and
               e["camera"] == victim and e["applied"]]
    assert crashed, "the crash from the page is not in the events"
    print("events: task %d issued at t=%s s, target pedestrian %d; camera %d crashed at t=%s s" % (
        task, issued[0]["t"], started[0]["pedestrian"], victim, crashed[0]["t"]))


if __name__ == "__main__":
    main(*sys.argv[1:4])
