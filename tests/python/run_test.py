"""argus.run: what a notebook calls."""

import json
import os
import unittest

import argus
from common import EMULATED, MINIMAL, events, scratch


class RunTest(unittest.TestCase):
    def test_returns_metrics_summary_and_paths(self):
        out = scratch("run_minimal")
        r = argus.run(MINIMAL, seed=4, duration=10, out=out)
        self.assertEqual(r["output_dir"], out)
        self.assertIsNone(r["failure"])
        self.assertEqual(r["summary"]["ticks"], 150)  # 10 s at 15 frames a second
        self.assertEqual(r["summary"]["seed"], 4)
        self.assertEqual(r["metrics"]["seed"], 4)
        with open(os.path.join(out, "metrics.json"), encoding="utf-8") as f:
            self.assertEqual(r["metrics"], json.load(f))
        for key in ("events", "summary", "metrics", "trajectories"):
            self.assertTrue(os.path.isfile(r["paths"][key]), key)

    def test_set_overrides_fields(self):
        out = scratch("run_set")
        r = argus.run(EMULATED, duration="20 s", out=out,
                      set={"controller.strategy": "no_collaboration", "world.population": 10})
        self.assertEqual(r["metrics"]["strategy"], "no_collaboration")
        kinds = {e["kind"] for e in events(r["paths"]["events"])}
        self.assertIn("task_issued", kinds)

    def test_same_seed_same_log(self):
        a = argus.run(MINIMAL, seed=2, duration=8, out=scratch("run_seed_a"))
        b = argus.run(MINIMAL, seed=2, duration=8, out=scratch("run_seed_b"))
        with open(a["paths"]["events"], "rb") as fa, open(b["paths"]["events"], "rb") as fb:
            self.assertEqual(fa.read(), fb.read())

    def test_bad_field_is_a_value_error_naming_it(self):
        with self.assertRaisesRegex(ValueError, r"network\.loss_probability"):
            argus.run(MINIMAL, duration=1, out=scratch("run_bad"),
                      set={"network.loss_probability": 7})

    def test_missing_file_is_named(self):
        with self.assertRaisesRegex(ValueError, "no_such_scenario.yaml"):
            argus.run("no_such_scenario.yaml")


if __name__ == "__main__":
    unittest.main()
