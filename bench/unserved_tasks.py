#!/usr/bin/env python3
"""Why a task went unserved: the first thing that took her away from her group, per task.

For every run folder given (argus run's output: metrics.json, tracks.csv, events.jsonl) and
every task in it whose coverage is under the bar (0.05, as Fig. 19's "both tasks served"
counts), the causes among these that happened:

- `moved_by_csp`: the conflict solver moved a camera whose box was on her to another task
  (`left_task` with reason `reassigned` while its last box was on her);
- `leader_lost_her_early:ONTO`: the leader's own track left her within EARLY_S of the pick,
  onto the background (`truth` -1), someone else, or nothing found;
- `no_camera_after:WHY`: nobody performed the task for most of her time
  (`uncovered.no_camera` >= 0.5) after its last camera's last frame; WHY is that camera's
  `left_task` reason then (`operator`: the operator took a lone leader for another task) or
  `crash` (a fault);

the earliest of these that happened, else `later:CLASS`, CLASS the largest share of her
uncovered time (`other_person`, `background`, `lost`, ...).

    bench/unserved_tasks.py OUT/runs/seed=*          # a table, then the counts by cause
    bench/unserved_tasks.py --json OUT/runs/seed=*   # the same as JSON
    bench/unserved_tasks.py --all OUT/runs/seed=*    # every task, served or not
"""

import collections
import csv
import json
import sys
from pathlib import Path

from pick_hold import first_off_her, leader_rows

SERVED = 0.05
EARLY_S = 1.0
NO_CAMERA = 0.5


def fail(message: str):
    print(f"unserved_tasks: {message}", file=sys.stderr)
    sys.exit(2)


def read_run(run: Path):
    for name in ("metrics.json", "tracks.csv", "events.jsonl"):
        if not (run / name).is_file():
            fail(f"{run}: expected an argus run folder (metrics.json, tracks.csv, events.jsonl)")
    metrics = json.loads((run / "metrics.json").read_text())
    with (run / "tracks.csv").open() as f:
        tracks = list(csv.DictReader(f))
    events = []
    with (run / "events.jsonl").open() as f:
        for line in f:
            e = json.loads(line)
            if e.get("kind") in ("left_task", "fault"):
                events.append(e)
    return metrics, tracks, events


def onto(row) -> str:
    if row["found"] != "1":
        return "nothing_found"
    return "background" if row["truth"] == "-1" else "someone_else"


def cause(task, tracks, events) -> dict:
    her = str(task["pedestrian"])
    number = task["task"]
    mine = [r for r in tracks if int(r["task"]) == number]
    leader = leader_rows(task, mine)
    uncovered = task["uncovered"]
    found = []  # (time, cause, details)
    for e in events:
        if e["kind"] != "left_task" or e.get("task") != number or e.get("reason") != "reassigned":
            continue
        before = [
            r
            for r in mine
            if int(r["camera"]) == e["camera"] and float(r["t"]) <= e["t"] and r["found"] == "1"
        ]
        if before and before[-1]["truth"] == her:
            found.append((e["t"], "moved_by_csp", {"camera_moved": e["camera"]}))
            break
    if leader:
        start = float(leader[0]["t"])
        first_off = first_off_her(leader, her)
        if first_off is not None and float(first_off["t"]) - start < EARLY_S:
            at = float(first_off["t"])
            found.append(
                (at, f"leader_lost_her_early:{onto(first_off)}", {"held_s": round(at - start, 3)})
            )
    if uncovered.get("no_camera", 0.0) >= NO_CAMERA and mine:
        last = mine[-1]
        at, camera = float(last["t"]), int(last["camera"])
        why = "unknown"
        for e in events:
            if abs(e["t"] - at) > 0.5 or e.get("camera") != camera:
                continue
            if e["kind"] == "left_task" and e.get("task") == number:
                why = e["reason"]
            elif e["kind"] == "fault" and e.get("fault") == "crash":
                why = "crash"
        found.append((at, f"no_camera_after:{why}", {"last_camera": camera}))
    out = {"pedestrian": task["pedestrian"], "camera": task["camera"]}
    if found:
        at, name, details = min(found, key=lambda f: f[0])
        out.update(cause=name, at_s=at, **details)
        return out
    largest = max(uncovered, key=uncovered.get) if uncovered else "unknown"
    out.update(cause=f"later:{largest}")
    return out


def main(argv):
    as_json = "--json" in argv
    every = "--all" in argv
    runs = [Path(a) for a in argv if not a.startswith("--")]
    if not runs:
        fail("usage: unserved_tasks.py [--json] [--all] RUN_DIR [RUN_DIR ...]")
    rows = []
    for run in runs:
        metrics, tracks, events = read_run(run)
        for task in metrics["tasks"]:
            if not every and task["coverage"] >= SERVED:
                continue
            row = {"seed": metrics["seed"], "task": task["task"], "coverage": task["coverage"]}
            row.update(cause(task, tracks, events))
            rows.append(row)
    rows.sort(key=lambda r: (r["seed"], r["task"]))
    counts = collections.Counter(r["cause"] for r in rows)
    if as_json:
        print(json.dumps({"tasks": rows, "by_cause": dict(counts.most_common())}, indent=1))
        return
    for r in rows:
        at = f"at {r['at_s']:7.2f} s" if "at_s" in r else " " * 12
        print(f"seed {r['seed']:5d} task {r['task']}  coverage {r['coverage']:.3f}  {at}  {r['cause']}")
    print()
    for name, n in counts.most_common():
        print(f"{n:4d}  {name}")


if __name__ == "__main__":
    main(sys.argv[1:])
