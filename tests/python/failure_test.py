"""A strategy that raises ends the run with exit 1 (argus.RunFailed in Python), naming the
strategy, the camera and the tick, and leaves every output complete up to that tick. A
strategy that cannot be found is bad input (exit 2, ValueError) naming the field."""

import json
import os
import subprocess
import unittest

import argus
from common import ARGUS, EMULATED, events, scratch

FAILING_TICK = 30


class Raiser(argus.Strategy):
    def step(self, inp):
        if self.me.id == 7 and inp.tick == FAILING_TICK:
            return 1 / 0
        return argus.Output()


class RaisesWhenMade(argus.Strategy):
    def __init__(self, context):
        super().__init__(context)
        raise RuntimeError("no camera for me")


class NoStrategy:
    pass


class FailureTest(unittest.TestCase):
    def check_complete_up_to_the_failure(self, out):
        log = events(os.path.join(out, "events.jsonl"))  # every line parses
        self.assertEqual(max(e["tick"] for e in log), FAILING_TICK)
        failed = [e for e in log if e["kind"] == "strategy_failed"]
        self.assertEqual(len(failed), 1)
        self.assertEqual(failed[0]["camera"], 7)
        self.assertIn("ZeroDivisionError", failed[0]["error"])
        with open(os.path.join(out, "summary.json"), encoding="utf-8") as f:
            summary = json.load(f)
        self.assertEqual(summary["ticks"], FAILING_TICK + 1)
        self.assertIn("camera 7, tick 30", summary["failure"])
        self.assertTrue(os.path.isfile(os.path.join(out, "metrics.json")))

    def test_run_raises_naming_strategy_camera_and_tick(self):
        out = scratch("raiser")
        with self.assertRaises(argus.RunFailed) as caught:
            argus.run(EMULATED, duration=5, out=out, strategy=Raiser)
        message = str(caught.exception)
        self.assertIn("strategy 'python:failure_test:Raiser' raised at camera 7, tick 30", message)
        self.assertIn("ZeroDivisionError: division by zero", message)
        self.assertIn("failure_test.py", message)  # where, from the traceback
        self.assertEqual(caught.exception.result["output_dir"], out)
        self.check_complete_up_to_the_failure(out)

    def test_executable_exits_1(self):
        out = scratch("raiser_exe")
        p = subprocess.run([ARGUS, "run", EMULATED, "--out", out, "--no-feeds", "--duration", "5 s",
                            "--set", "controller.strategy=python:failure_test:Raiser"],
                           capture_output=True, text=True)
        self.assertEqual(p.returncode, 1, p.stderr)
        self.assertIn("strategy 'python:failure_test:Raiser' raised at camera 7, tick 30", p.stderr)
        self.check_complete_up_to_the_failure(out)

    def test_constructor_that_raises(self):
        with self.assertRaisesRegex(argus.RunFailed,
                                    "its constructor raised RuntimeError: no camera for me"):
            argus.run(EMULATED, duration=2, out=scratch("made"), strategy=RaisesWhenMade)

    def test_missing_module_exits_2_naming_the_field(self):
        p = subprocess.run([ARGUS, "validate", EMULATED,
                            "--set", "controller.strategy=python:no_such_module:Anything"],
                           capture_output=True, text=True)
        self.assertEqual(p.returncode, 2, p.stderr)
        self.assertRegex(p.stderr, r"penn_station_emulated\.yaml: controller\.strategy: "
                                   r"'python:no_such_module:Anything': Python could not load it: "
                                   r"ModuleNotFoundError: No module named 'no_such_module'")

    def test_missing_module_is_a_value_error(self):
        with self.assertRaisesRegex(ValueError, "No module named 'no_such_module'"):
            argus.run(EMULATED, duration=1, out=scratch("missing"),
                      set={"controller.strategy": "python:no_such_module:Anything"})

    def test_not_a_strategy_exits_2(self):
        p = subprocess.run([ARGUS, "validate", EMULATED,
                            "--set", "controller.strategy=python:failure_test:NoStrategy"],
                           capture_output=True, text=True)
        self.assertEqual(p.returncode, 2, p.stderr)
        self.assertIn("failure_test.NoStrategy is not a subclass of argus.Strategy", p.stderr)


if __name__ == "__main__":
    unittest.main()
