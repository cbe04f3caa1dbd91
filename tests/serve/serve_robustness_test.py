"""The console's server under abuse: fuzzed commands get HTTP 400 (or 413, 429) with a message
and change nothing — the served run's event log is byte-identical to `argus run`'s — and 100
clients that connect to the live stream and drop leave it serving.

  python3 serve_robustness_test.py ARGUS SCENARIO OUT
"""
import filecmp
import json
import os
import random
import shutil
import socket
import subprocess
import sys
import threading
import time

from serve_session import Serve


def fuzzed_bodies(rng, cameras):
    """Requests that must all be refused: malformed JSON, unknown commands, cameras, links,
    pixels outside the frame, wrong types. `cameras`: /plan.json's."""
    for cam in cameras:  # one pixel past each edge of each camera's frame
        w, h = cam["width_px"], cam["height_px"]
        for x, y in ((w, 0), (0, h), (-1, 0), (0, -0.5), (w + 0.5, h)):
            yield json.dumps({"command": "task", "camera": cam["id"], "pixel": [x, y]}).encode()
    yield b""
    yield b"{"
    yield b"\xff\xfe\x00garbage"
    yield b"null"
    yield b"[]"
    yield b'{"command": null}'
    yield b'{"command": "task", "camera": 1, "pixel": [640, 10]}'
    yield b'{"command": "task", "camera": 1, "pixel": [10, 480]}'
    yield b'{"command": "task", "camera": 1, "pixel": [NaN, 1]}'
    yield b'{"command": "task", "camera": 1, "pixel": [1e999, 1]}'
    yield b'{"command": "crash", "camera": 99}'
    yield b'{"command": "crash", "camera": 1.5}'
    yield b'{"command": "cut", "camera": 1, "peer": 1}'
    yield b'{"command": "cancel", "task": "0"}'
    yield ('{"command": "crash", "camera": %s}' % ("9" * 400)).encode()
    yield ("[" * 5000 + "]" * 5000).encode()
    kinds = ["task", "cancel", "crash", "recover", "cut", "heal", "explode", "", "TASK"]
    values = [None, True, -1, 0, 99, 2**40, -2**63, 1e308, "1", [], {}, [1], [1, 2, 3], "x" * 50]
    for _ in range(400):
        body = {"command": rng.choice(kinds)}
        for key in rng.sample(["camera", "peer", "pixel", "task", "cameras_wanted", "junk"],
                              rng.randint(0, 4)):
            body[key] = rng.choice(values)
        text = json.dumps(body)
        if rng.random() < 0.3:  # truncate or corrupt a byte
            cut = rng.randint(0, len(text))
            text = text[:cut] + rng.choice(["", "\x00", "}", '"', "\\"]) + text[cut + 1:]
        yield text.encode()


def is_valid(serve_url, body):
    """Whether `body` happens to be a command the scenario accepts (then it is not fuzz)."""
    try:
        j = json.loads(body)
    except Exception:
        return False
    if not isinstance(j, dict):
        return False
    if j.get("command") == "cancel":
        return type(j.get("task")) is int and 0 <= j["task"] <= 1_000_000
    if j.get("command") not in ("crash", "recover"):
        return False
    return type(j.get("camera")) is int and j["camera"] in (1, 2, 3, 4, 5, 6, 12)


def raw_request(url, request):
    """(status, body) of one request sent byte for byte, as no HTTP library would send it."""
    host, port = url.split("//")[1].split(":")
    with socket.create_connection((host, int(port)), timeout=10) as s:
        s.sendall(request)
        reply = b""
        while b"\r\n\r\n" not in reply or not reply.rstrip().endswith(b"}"):
            chunk = s.recv(4096)
            if not chunk:
                break
            reply += chunk
    head, _, body = reply.partition(b"\r\n\r\n")
    return int(head.split(b" ")[1]), body


def drop_clients(url, count):
    host, port = url.split("//")[1].split(":")
    errors = []

    def client(i):
        try:
            s = socket.create_connection((host, int(port)), timeout=10)
            if i % 3 == 0:
                s.sendall(b"GET /events HTTP/1.1\r\nHost: x\r\n\r\n")
                s.recv(4096)  # the headers and perhaps a first message, then gone
            elif i % 3 == 1:
                s.sendall(b"GET /feed/1.jpg HTTP/1.1\r\nHost: x\r\n\r\n")
            else:
                s.sendall(os.urandom(64))  # not HTTP at all
            s.close()
        except Exception as e:  # noqa: BLE001 - every failure is reported
            errors.append("client %d: %s" % (i, e))

    threads = [threading.Thread(target=client, args=(i,)) for i in range(count)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    return errors


def main(argus, scenario, out):
    shutil.rmtree(out, ignore_errors=True)
    live = os.path.join(out, "live")
    serve = Serve(argus, scenario, live, "--speed", "1", "--duration", "12s", "--threads", "2")
    rng = random.Random(16)
    try:
        serve.wait_tick(5)
        refused = 0
        cameras = serve.request("GET", "/plan.json")[1]["cameras"]
        for body in fuzzed_bodies(rng, cameras):
            if is_valid(serve.url, body):
                continue
            status, reply = serve.request("POST", "/command", raw=body)
            assert status == 400, "fuzzed %r: HTTP %d %r" % (body[:80], status, reply)
            assert isinstance(reply, dict) and reply.get("error"), reply
            refused += 1
        status, _ = serve.request("POST", "/command", raw=b"x" * 100_000)
        assert status == 413, "an oversized command got HTTP %d" % status
        for body in (b"{", b'{"speed": -1}', b'{"speed": "fast"}', b'{"paused": 1}', b"{}"):
            status, reply = serve.request("POST", "/pace", raw=body)
            assert status == 400 and reply.get("error"), (body, status, reply)
        status, reply = serve.request("GET", "/feed/99.jpg")
        assert status == 404 and "camera 99" in reply["error"], (status, reply)
        status, _ = serve.request("GET", "/no/such/page")
        assert status == 404
        # A path that is not UTF-8 is echoed in the error: the server once died writing it.
        for path in (b"/\xff\xfe", b"/feed/\xc3.jpg", b"/x\x80y"):
            status, body = raw_request(serve.url, b"GET " + path + b" HTTP/1.1\r\nHost: x\r\n\r\n")
            assert status == 404 and json.loads(body)["error"], (path, status, body)
        print("fuzz: %d bad commands refused with HTTP 400 and a message" % refused)
        before = serve.state()["tick"]
        errors = drop_clients(serve.url, 100)
        assert not errors, "\n".join(errors)
        time.sleep(1.0)
        after = serve.state()["tick"]
        assert after > before, "the run stalled after 100 clients dropped (%d)" % after
        status, frame = serve.request("GET", "/feed/1.jpg")
        assert status == 200 and frame[:2] == b"\xff\xd8", "no JPEG feed after the clients"
        print("100 clients connected and dropped; the run went on (tick %d -> %d)" % (before, after))
        serve.finish()
    finally:
        serve.kill()
    commands = open(os.path.join(live, "commands.yaml")).read()
    assert "commands: []" in commands, "fuzz reached the run:\n" + commands
    plain = os.path.join(out, "plain")
    subprocess.run([argus, "run", scenario, "--duration", "12s", "--out", plain, "--threads", "2",
                    "--no-progress"], check=True, stdout=subprocess.DEVNULL)
    assert filecmp.cmp(os.path.join(live, "events.jsonl"), os.path.join(plain, "events.jsonl"),
                       shallow=False), "the served run's events differ from argus run's"
    print("the served run's events.jsonl is byte-identical to argus run's")


if __name__ == "__main__":
    main(*sys.argv[1:4])
