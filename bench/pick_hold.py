#!/usr/bin/env python3
"""How long each task's leader holds the pedestrian it was given, against the pick's size.

For every run folder given (argus run's output: metrics.json, tracks.csv), and every task in
it: the height in pixels of the leader's first box (the operator's pick as the tracker took
it), how long the leader's track stayed on her before it first was not (on nobody, or on
someone else), and the task's coverage. Then the tasks binned by the pick's height.

    bench/pick_hold.py OUT/sweep/runs/seed=*          # a table
    bench/pick_hold.py --json OUT/sweep/runs/seed=*   # the same as JSON

A leader that held her to the end counts the time to the run's end.
"""

import csv
import json
import statistics
import sys
from pathlib import Path

BINS = [(0, 20), (20, 30), (30, 50), (50, 100_000)]
QUICK_LOSS_S = 2.0


def leader_rows(task, tracks):
    """The rows of tracks.csv of the task's first leader (the camera it was given to)."""
    return [
        r
        for r in tracks
        if int(r["task"]) == task["task"]
        and r["role"] == "leader"
        and int(r["camera"]) == task["camera"]
    ]


def first_off_her(rows, her: str):
    """The first row whose box is not on her (on nobody, someone else, or not found), or None."""
    return next((r for r in rows if r["truth"] != her), None)


def tasks_of(run: Path):
    metrics = json.loads((run / "metrics.json").read_text())
    with (run / "tracks.csv").open() as f:
        tracks = list(csv.DictReader(f))
    for task in metrics["tasks"]:
        her = str(task["pedestrian"])
        rows = leader_rows(task, tracks)
        if not rows:
            continue
        start = float(rows[0]["t"])
        first_off = first_off_her(rows, her)
        end = float(first_off["t"]) if first_off else float(rows[-1]["t"])
        yield {
            "seed": metrics["seed"],
            "task": task["task"],
            "pick_height_px": float(rows[0]["h"]),
            "held_s": round(end - start, 3),
            "first_off_on": None if first_off is None else int(first_off["truth"]),
            "coverage": task["coverage"],
        }


def binned(tasks):
    out = []
    for low, high in BINS:
        chosen = [t for t in tasks if low <= t["pick_height_px"] < high]
        if not chosen:
            continue
        out.append(
            {
                "pick_height_px": [low, high],
                "tasks": len(chosen),
                "mean_coverage": round(statistics.mean(t["coverage"] for t in chosen), 3),
                "lost_within_2_s": sum(t["held_s"] < QUICK_LOSS_S for t in chosen),
                "coverage_under_0.05": sum(t["coverage"] < 0.05 for t in chosen),
            }
        )
    return out


def main(argv):
    as_json = "--json" in argv
    runs = [Path(a) for a in argv if a != "--json"]
    if not runs:
        sys.exit(__doc__)
    tasks = []
    for run in runs:
        if not (run / "metrics.json").is_file() or not (run / "tracks.csv").is_file():
            sys.exit(f"pick_hold: {run}: expected an argus run folder (metrics.json, tracks.csv)")
        tasks.extend(tasks_of(run))
    tasks.sort(key=lambda t: (t["seed"], t["task"]))
    bins = binned(tasks)
    if as_json:
        print(json.dumps({"tasks": tasks, "bins": bins}, indent=1))
        return
    for t in tasks:
        print(
            f"seed {t['seed']:>5} task {t['task']}  pick {t['pick_height_px']:5.0f} px"
            f"  held {t['held_s']:7.2f} s  coverage {t['coverage']:.3f}"
        )
    for b in bins:
        low, high = b["pick_height_px"]
        print(
            f"pick {low}-{high} px: {b['tasks']} tasks, mean coverage {b['mean_coverage']:.3f},"
            f" lost within 2 s {b['lost_within_2_s']}, coverage < 0.05 {b['coverage_under_0.05']}"
        )


if __name__ == "__main__":
    main(sys.argv[1:])
