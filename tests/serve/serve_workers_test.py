"""A live run across processes (`argus serve --workers`, docs/distributed.md "Live runs"): two
`argus worker` processes host the cameras, the operator's clicks, crashes, cuts, cancellations
and recoveries reach them, and the run's events.jsonl is the same to the byte as its replay in
one process (serve_replay_test's script). The console shows the workers' cameras: their poses
(the people under them) and the frames their nodes sensed, with the tracker's boxes.

  python3 serve_workers_test.py ARGUS SCENARIO OUT
"""
import os
import re
import shutil
import subprocess
import sys
import time
import urllib.request

import serve_replay_test


def start_worker(argus, log_path):
    log = open(log_path, "w")
    process = subprocess.Popen([argus, "worker", "--listen", "127.0.0.1:0", "--threads", "1"],
                               stdout=log, stderr=subprocess.STDOUT, text=True)
    deadline = time.time() + 20
    while time.time() < deadline:
        found = re.search(r"^argus worker: listening on (127\.0\.0\.1:\d+)$",
                          open(log_path).read(), re.M)
        if found:
            return process, found.group(1)
        if process.poll() is not None:
            raise AssertionError("a worker exited: " + open(log_path).read())
        time.sleep(0.1)
    process.kill()
    raise AssertionError("a worker did not listen within 20 s")


def node_frame_shown(serve, camera, timeout=30):
    """Waits until the console serves camera `camera`'s feed as its node sensed it (on a
    worker), not as the console renders it for display; returns the JPEG's size."""
    deadline = time.time() + timeout
    while time.time() < deadline:
        with urllib.request.urlopen(serve.url + "/feed/%d.jpg" % camera, timeout=10) as res:
            body = res.read()
            if res.headers["X-Frame-Source"] == "node":
                assert body[:2] == b"\xff\xd8", "the feed is not a JPEG"
                return len(body)
        time.sleep(0.1)
    raise AssertionError("camera %d's feed never showed its node's own frame" % camera)


def main(argus, scenario, out):
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    workers = []
    try:
        for i in (1, 2):
            workers.append(start_worker(argus, os.path.join(out, "worker-%d.log" % i)))
        addresses = ",".join(address for _, address in workers)
        shown = {}

        def while_tasked(serve, camera):
            # The clicked camera's node tracks its target on a worker: its frames reach the page.
            shown["bytes"] = node_frame_shown(serve, camera)
            # Traffic is counted on the workers' links: only what they report reaches the page.
            messages = serve.state()["messages"]
            assert messages["sent"] > 0 and messages["received"] > 0, messages
            assert [c for c in serve.state()["cameras"] if c["id"] == camera][0]["has_frame"]

        serve_replay_test.main(argus, scenario, os.path.join(out, "run"), "--workers", addresses,
                               while_tasked=while_tasked)
        print("the clicked camera's own frame reached the page: %d bytes" % shown["bytes"])
    finally:
        for process, _ in workers:
            process.kill()
            process.wait()
    for i in (1, 2):
        log = open(os.path.join(out, "worker-%d.log" % i)).read()
        assert "hosting 'two_tasks'" in log, "worker %d hosted nothing:\n%s" % (i, log)


if __name__ == "__main__":
    main(*sys.argv[1:4])
