"""Strategies written in Python: passed to argus.run, or named python:MODULE:CLASS in the argus
executable. The Python port of the example plug-in must log what the C++ one logs, byte for
byte: the bindings lose nothing on the way in or out."""

import os
import subprocess
import unittest

import argus
from common import ARGUS, EMULATED, events, scratch
from lone_tracker import LoneTracker

PLUGIN = os.environ.get("LONE_TRACKER_PLUGIN")


def read(path):
    with open(path, "rb") as f:
        return f.read()


class Chatter(argus.Strategy):
    """Every camera says hello to its neighbourhood once; what each hears is logged."""

    def step(self, inp):
        out = argus.Output()
        if inp.tick == 60:  # once the neighbours have found each other
            out.send(argus.BROADCAST, "hello", bytes([self.me.id]), task=9)
        for m in inp.messages:
            out.event("heard", origin=m.origin, message=m.kind, topic=m.topic, body=list(m.body),
                      task=m.task)
        return out


class PythonStrategyTest(unittest.TestCase):
    @unittest.skipUnless(PLUGIN, "needs the example plug-in (LONE_TRACKER_PLUGIN)")
    def test_python_port_logs_what_the_cpp_plugin_logs(self):
        cpp = argus.run(EMULATED, duration="3 min", out=scratch("lone_cpp"),
                        set={"controller.strategy": f"plugin:{PLUGIN}"})
        py = argus.run(EMULATED, duration="3 min", out=scratch("lone_py"), strategy=LoneTracker)
        self.assertEqual(py["metrics"]["strategy"], "python:lone_tracker:LoneTracker")
        log = read(py["paths"]["events"])
        self.assertIn(b"lone_tracker_started", log)
        self.assertEqual(read(cpp["paths"]["events"]), log)

    @unittest.skipUnless(PLUGIN, "needs the example plug-in (LONE_TRACKER_PLUGIN)")
    def test_named_in_a_scenario_run_by_the_executable(self):
        out = scratch("lone_exe")
        subprocess.run([ARGUS, "run", EMULATED, "--out", out, "--no-feeds", "--duration", "3 min",
                        "--set", "controller.strategy=python:lone_tracker:LoneTracker"],
                       check=True, capture_output=True)
        cpp = argus.run(EMULATED, duration="3 min", out=scratch("lone_cpp2"),
                        set={"controller.strategy": f"plugin:{PLUGIN}"})
        self.assertEqual(read(cpp["paths"]["events"]), read(os.path.join(out, "events.jsonl")))

    def test_notes_reach_the_neighbourhood(self):
        r = argus.run(EMULATED, duration=6, out=scratch("chatter"), strategy=Chatter,
                      set={"network.node_failure_probability": 0})
        heard = [e for e in events(r["paths"]["events"]) if e["kind"] == "heard"]
        self.assertGreater(len(heard), 16)  # every camera hears at least one neighbour
        for e in heard:
            self.assertEqual(e["message"], "note")
            self.assertEqual(e["topic"], "hello")
            self.assertEqual(e["body"], [e["origin"]])
            self.assertEqual(e["task"], 9)
            self.assertNotEqual(e["source"], f"camera/{e['origin']}")
        self.assertEqual(argus.strategies()["python:strategy_test:Chatter"],
                         "Every camera says hello to its neighbourhood once; what each hears is "
                         "logged.")


if __name__ == "__main__":
    unittest.main()
