"""The live console's cost to the simulation (issue 16): the same run, same binary, free-running
(--speed 0) so that any cost shows as wall time, three ways:
  run      `argus run`                       (no server)
  serve    `argus serve`, nobody watching    (the server and the console's publishing)
  browser  `argus serve` with the page open in headless Chromium (live stream, plan, one feed)
and the frames per second the feed reached in the browser. Repeats each `--repeats` times, in
rotating order; reports wall time (the simulation's speed) and the argus process's CPU time
(user + system: its cost, less sensitive than wall time to other load on the machine).

  /usr/bin/python3 bench/serve_bench.py build/apps/argus scenarios/minimal.yaml \
      [--duration '40 s'] [--repeats 3] [--camera 1] [--speed 0]
"""
import argparse
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "tests", "serve"))
from serve_session import Serve  # noqa: E402

WALL = re.compile(r"simulated in ([0-9.]+) s wall")


def run_plain(args, out):
    process = subprocess.Popen([args.argus, "run", args.scenario, "--duration", args.duration,
                                "--speed", args.speed, "--out", out, "--threads", "2",
                                "--no-progress"], stdout=subprocess.PIPE, text=True)
    _, status, usage = os.wait4(process.pid, 0)
    assert os.waitstatus_to_exitcode(status) == 0
    text = process.stdout.read()
    return float(WALL.search(text).group(1)), usage.ru_utime + usage.ru_stime


def run_served(args, out, with_browser):
    serve = Serve(args.argus, args.scenario, out, "--speed", args.speed, "--duration",
                  args.duration, "--threads", "2")
    driver = None
    fps = []
    try:
        if with_browser:
            from selenium import webdriver
            from selenium.webdriver.chrome.service import Service
            from selenium.webdriver.support.ui import Select
            options = webdriver.ChromeOptions()
            options.binary_location = shutil.which("chromium")
            for flag in ("--headless", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                         "--window-size=1600,1200", "--user-data-dir=" + out + "-profile"):
                options.add_argument(flag)
            driver = webdriver.Chrome(service=Service(shutil.which("chromedriver")),
                                      options=options)
            driver.get(serve.url + "/")
            Select(driver.find_element("id", "camera")).select_by_value(args.camera)
            while serve.running():
                frames = driver.execute_script(
                    "return Number(document.getElementById('feed').dataset.frames || 0)")
                time.sleep(2.0)
                if serve.running():
                    now = driver.execute_script(
                        "return Number(document.getElementById('feed').dataset.frames || 0)")
                    fps.append((now - frames) / 2.0)
        text = serve.finish()
    finally:
        if driver:
            driver.quit()
        serve.kill()
    return float(WALL.search(text).group(1)), serve.cpu_seconds, fps


def main():
    p = argparse.ArgumentParser()
    p.add_argument("argus")
    p.add_argument("scenario")
    p.add_argument("--duration", default="40 s")
    p.add_argument("--repeats", type=int, default=3)
    p.add_argument("--camera", default="1")
    p.add_argument("--speed", default="0")
    args = p.parse_args()
    work = tempfile.mkdtemp(prefix="serve_bench_")
    walls = {"run": [], "serve": [], "browser": []}
    cpus = {"run": [], "serve": [], "browser": []}
    fps = []
    for i in range(args.repeats):
        # The order rotates, so that no way always runs after the browser has just quit.
        order = ["run", "serve", "browser"][i % 3:] + ["run", "serve", "browser"][:i % 3]
        for way in order:
            out = os.path.join(work, "%s%d" % (way, i))
            if way == "run":
                wall, cpu = run_plain(args, out)
            else:
                wall, cpu, rates = run_served(args, out, way == "browser")
                fps += rates
            walls[way].append(wall)
            cpus[way].append(cpu)
        print("repeat %d: %s" % (i, ", ".join("%s %.2f s wall %.2f s CPU" % (
            w, walls[w][-1], cpus[w][-1]) for w in walls)), flush=True)
    base_wall = statistics.median(walls["run"])
    base_cpu = statistics.median(cpus["run"])
    print("| way | wall s, median of %d | vs run | argus CPU s, median | vs run |" % args.repeats)
    print("| --- | --- | --- | --- | --- |")
    for way in walls:
        w = statistics.median(walls[way])
        c = statistics.median(cpus[way])
        print("| %s | %.2f | %+.1f%% | %.2f | %+.1f%% |" % (
            way, w, 100.0 * (w / base_wall - 1.0), c, 100.0 * (c / base_cpu - 1.0)))
    if fps:
        print("feed in the browser: median %.1f frames/s, min %.1f, max %.1f (%d samples of 2 s)" % (
            statistics.median(fps), min(fps), max(fps), len(fps)))
    shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
