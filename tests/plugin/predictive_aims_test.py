"""The example strategy beyond the paper's (examples/strategies/predictive.cpp), loaded by argus:
its variants are registered, and a camera it sends after her is sent where she really is.

Each camera that joins the search for her is pointed at where the group's shared floor
estimates and their motion model put her one second ahead (event `predictive_aimed`). On two
seeds whose groups hold her at first, the first such aim must land within 3 m of where the
ground truth (trajectories.csv) has her one second later: an aim built on a wrong calibration, a
wrong unit or a motion model that runs away would miss by far more (the station's cameras are
10-40 m from her).

Usage: predictive_aims_test.py ARGUS PLUGIN SCENARIO SCRATCH
"""

import csv
import json
import math
import subprocess
import sys
from pathlib import Path

ARGUS, PLUGIN, SCENARIO, SCRATCH = sys.argv[1:5]
AHEAD_TICKS = 15  # lead_s = 1 s at 15 ticks a second
TOLERANCE_M = 3.0


def fail(message):
    print(f"FAIL: {message}")
    sys.exit(1)


def listed_variants():
    out = subprocess.run([ARGUS, "strategies", "--plugin", PLUGIN], capture_output=True,
                         text=True, check=True).stdout
    for name in ("predictive", "predictive_gated", "predictive_ahead"):
        if not any(line.split()[:1] == [name] for line in out.splitlines()):
            fail(f"`argus strategies --plugin` does not list {name}:\n{out}")


def first_aim_error(seed):
    out = Path(SCRATCH) / f"predictive_seed{seed}"
    run = subprocess.run([ARGUS, "run", SCENARIO, "--seed", str(seed), "--duration", "20 s",
                          "--no-feeds", "--out", str(out), "--set",
                          f"controller.strategy=plugin:{PLUGIN}#predictive"],
                         capture_output=True, text=True)
    if run.returncode != 0:
        fail(f"seed {seed}: argus exited {run.returncode}:\n{run.stderr}")
    events = [json.loads(line) for line in open(out / "events.jsonl")]
    targets = {e["task"]: e["pedestrian"] for e in events if e["kind"] == "task_target"}
    aims = [e for e in events if e["kind"] == "predictive_aimed"]
    if not targets or not aims:
        fail(f"seed {seed}: no task target ({len(targets)}) or no aim ({len(aims)}) in 20 s")
    aim = aims[0]
    who, tick = targets[aim["task"]], aim["tick"] + AHEAD_TICKS
    with open(out / "trajectories.csv") as f:
        for row in csv.DictReader(f):
            if int(row["tick"]) == tick and int(row["id"]) == who:
                return aim, math.dist((float(row["x"]), float(row["y"])), (aim["x"], aim["y"]))
    fail(f"seed {seed}: pedestrian {who} has no position at tick {tick}")


listed_variants()
for seed in (1, 3):
    aim, error = first_aim_error(seed)
    print(f"seed {seed}: {aim['source']} aimed at ({aim['x']}, {aim['y']}) at tick "
          f"{aim['tick']}, {error:.2f} m from her one second later")
    if error > TOLERANCE_M:
        fail(f"seed {seed}: the first aim is {error:.2f} m from her (at most {TOLERANCE_M} m)")
print("ok")
