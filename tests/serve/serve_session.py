"""Starts `argus serve` and talks to it over HTTP (the live console's tests)."""
import json
import os
import subprocess
import time
import urllib.error
import urllib.request


class Serve:
    """One `argus serve` process on a free port of 127.0.0.1."""

    def __init__(self, argus, scenario, out, *extra, context=None):
        self.out = out
        self.context = context  # an ssl.SSLContext for a console that serves HTTPS
        self.process = subprocess.Popen(
            [argus, "serve", scenario, "--port", "0", "--out", out, *extra],
            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        line = self.process.stdout.readline()
        if not line.startswith(("argus serve: http://", "argus serve: https://")):
            self.process.kill()
            raise RuntimeError("argus serve did not start: %r %s" %
                               (line, self.process.stderr.read()))
        printed = line.split(": ", 1)[1].strip()
        # Beyond loopback the console prints its secret once, as ?token= on its address.
        base, _, self.token = printed.partition("/?token=")
        self.url = base.rstrip("/").replace("//0.0.0.0:", "//127.0.0.1:")

    def request(self, method, path, body=None, raw=None, timeout=10):
        """(status, parsed JSON or bytes) of one request."""
        data = raw if raw is not None else (None if body is None else json.dumps(body).encode())
        headers = {"Content-Type": "application/json"}
        if self.token:
            headers["Authorization"] = "Bearer " + self.token
        req = urllib.request.Request(self.url + path, data=data, method=method, headers=headers)
        try:
            with urllib.request.urlopen(req, timeout=timeout, context=self.context) as res:
                status, payload, kind = res.status, res.read(), res.headers["Content-Type"]
        except urllib.error.HTTPError as e:
            status, payload, kind = e.code, e.read(), e.headers["Content-Type"]
        if kind and kind.startswith("application/json"):
            return status, json.loads(payload)
        return status, payload

    def state(self):
        status, state = self.request("GET", "/state")
        assert status == 200, (status, state)
        return state

    def wait_tick(self, tick, timeout=120):
        """Waits until the run has reached `tick`."""
        deadline = time.time() + timeout
        while time.time() < deadline:
            if self.state()["tick"] >= tick:
                return
            time.sleep(0.05)
        raise AssertionError("the run did not reach tick %d" % tick)

    def command(self, **body):
        return self.request("POST", "/command", body)

    def pace(self, **body):
        status, reply = self.request("POST", "/pace", body)
        assert status == 200, (status, reply)
        return reply

    def someone_in_view(self):
        """(camera, x, y): an alive, idle camera and the centre of the largest pedestrian in its
        view (ground truth from /feed/N/people.json), or None."""
        best = None
        for cam in self.state()["cameras"]:
            if not cam["alive"] or cam["state"] != "idle":
                continue
            status, seen = self.request("GET", "/feed/%d/people.json" % cam["id"])
            if status != 200:
                continue
            for person in seen["people"]:
                x, y, w, h = person["box"]
                if best is None or w * h > best[0]:
                    best = (w * h, cam["id"], int(x + w / 2), int(y + h / 2))
        return None if best is None else best[1:]

    def pause_on_someone(self, timeout=120):
        """Waits until an idle camera sees someone, pauses the run there and returns
        someone_in_view() of the paused run."""
        deadline = time.time() + timeout
        while time.time() < deadline:
            if self.someone_in_view():
                self.pace(paused=True)
                time.sleep(0.3)  # the tick in progress ends
                target = self.someone_in_view()
                if target:
                    return target
                self.pace(paused=False)
            time.sleep(0.2)
        raise AssertionError("no pedestrian came into an idle camera's view")

    def new_task(self, known, timeout=60):
        """The index of a task that is not in `known`, once the run has issued it."""
        deadline = time.time() + timeout
        while time.time() < deadline:
            fresh = [t["task"] for t in self.state()["tasks"] if t["task"] not in known]
            if fresh:
                return fresh[0]
            time.sleep(0.05)
        raise AssertionError("no new task was issued")

    def running(self):
        """Whether the process still runs (without reaping it: finish() reads its CPU time)."""
        info = os.waitid(os.P_PID, self.process.pid, os.WEXITED | os.WNOHANG | os.WNOWAIT)
        return info is None

    def finish(self, timeout=300):
        """Waits for the run's end; returns the process's stdout. Its CPU seconds (user +
        system) are then in `cpu_seconds`."""
        deadline = time.time() + timeout
        while True:
            pid, status, usage = os.wait4(self.process.pid, os.WNOHANG)
            if pid != 0:
                break
            if time.time() > deadline:
                raise AssertionError("argus serve did not end within %d s" % timeout)
            time.sleep(0.05)
        self.process.returncode = os.waitstatus_to_exitcode(status)
        self.cpu_seconds = usage.ru_utime + usage.ru_stime
        out, err = self.process.stdout.read(), self.process.stderr.read()
        if self.process.returncode != 0:
            raise AssertionError("argus serve exit %d\n%s" % (self.process.returncode, err))
        return out

    def kill(self):
        if self.process.poll() is None:
            self.process.kill()
            self.process.wait()
