#!/usr/bin/env python3
"""Where a task's group first goes wrong: the operator's pick, the leader's first seconds, or
the first bids.

Reads `argus run` output folders (events.jsonl, tracks.csv, targets.csv, metrics.json) of
runs with one task and finds, for each, the first `--min-seconds` in which nobody observes her
while a camera of the group holds someone else (metrics.json's `other_person`). It blames one
camera (the leader if it is on someone else, else the first member that is) and classes its
track:

- `pick`: the original leader's box never held her (the operator's pick went wrong);
- `leader_drifted` / `member_drifted`: the camera had held her and moved to someone else;
- `handover_to_wrong`: the camera took the group (by hand-over or its leader's failure) while
  on someone who never was her;
- `first_bid`: a member whose track never held her (its bid's first look);
- `never`: the group never did.

It also prints, per run, the pick (pedestrian, the leader's first box: on whom, its height and
score), when the leader's box was last on her, and her coverage. With --json the same as JSON.

    bench/first_look.py RUN_DIR [RUN_DIR ...] [--min-seconds 1] [--json]
"""
import collections
import csv
import json
import os
import sys


def read_events(run):
    with open(os.path.join(run, "events.jsonl")) as f:
        return [json.loads(line) for line in f if line.strip()]


def read_tracks(run):
    """tick -> camera -> row, for task 0's rows."""
    by_tick = collections.defaultdict(dict)
    with open(os.path.join(run, "tracks.csv")) as f:
        for r in csv.DictReader(f):
            if r["task"] != "0":
                continue
            by_tick[int(r["tick"])][int(r["camera"])] = r
    return by_tick


def target_of(run):
    with open(os.path.join(run, "targets.csv")) as f:
        for r in csv.DictReader(f):
            if r["task"] == "0":
                return int(r["pedestrian"])
    return None


def on_whom(row):
    """The pedestrian a found box holds (0: nobody), or None without a box."""
    if row["found"] != "1":
        return None
    truth = int(row["truth"])
    return truth if truth > 0 else 0


def observed_ticks(run):
    """Ticks in which some camera observes task 0's target (targets.csv's observed_by)."""
    with open(os.path.join(run, "targets.csv")) as f:
        return {int(r["tick"]) for r in csv.DictReader(f)
                if r["task"] == "0" and int(r["observed_by"]) >= 0}


def last_on(tracks, camera, her, before):
    """The last time (s) before tick `before` at which `camera`'s box was on her, or None."""
    last = None
    for tick in sorted(tracks):
        if tick >= before:
            break
        row = tracks[tick].get(camera)
        if row is not None and on_whom(row) == her:
            last = float(row["t"])
    return last


def classify(run, min_seconds):
    events = read_events(run)
    her = target_of(run)
    if her is None:
        return {"run": run, "task": False}
    tracks = read_tracks(run)
    pick = next((e for e in events if e["kind"] == "task_target" and e.get("task") == 0), None)
    created = next((e for e in events if e["kind"] == "task_created" and e.get("task") == 0), None)
    leader0 = created["camera"] if created else (pick["camera"] if pick else None)
    first_box = {}  # camera -> (tick, whom)
    held_her = set()
    ticks = sorted(tracks)
    observed = observed_ticks(run)
    need = max(1, int(round(min_seconds * 15)))  # the scenarios' tick is 1/15 s
    wrong_since = None
    verdict = None
    culprit = None
    for tick in ticks:
        rows = tracks[tick]
        # The group is on someone else: nobody observes her and some box holds another person.
        wrong_cams = [cam for cam, row in sorted(rows.items()) if on_whom(row) not in (None, 0, her)]
        for cam, row in rows.items():
            whom = on_whom(row)
            if whom is None:
                continue
            if cam not in first_box:
                first_box[cam] = (tick, whom, row["role"], float(row["score"] or 0), float(row["h"]))
            if whom == her:
                held_her.add(cam)
        if tick in observed or not wrong_cams:
            wrong_since = None
            continue
        if wrong_since is None:
            wrong_since = (tick, set(held_her), dict(first_box))
        if tick - wrong_since[0] + 1 < need:
            continue
        start_tick, held_then, first_then = wrong_since
        rows0 = tracks[start_tick]
        cams0 = [c for c in sorted(rows0) if on_whom(rows0[c]) not in (None, 0, her)]
        # The camera most to blame: the leader if it is on someone else, else the first member.
        cam = next((c for c in cams0 if rows0[c]["role"] == "leader"), cams0[0] if cams0 else wrong_cams[0])
        row = tracks[start_tick].get(cam) or rows[cam]
        fb = first_then.get(cam)
        if cam in held_then:
            verdict = "leader_drifted" if row["role"] == "leader" else "member_drifted"
        elif row["role"] == "leader" and cam == leader0:
            verdict = "pick"
        elif row["role"] == "leader":
            verdict = "handover_to_wrong"
        else:
            verdict = "first_bid"
        culprit = {"camera": cam, "tick": start_tick, "t": float(row["t"]), "role": row["role"],
                   "on": on_whom(row), "first_box_on": fb[1] if fb else None,
                   "leader_last_on_her": last_on(tracks, leader0, her, start_tick)}
        break
    if verdict is None:
        verdict = "never"
    coverage = None
    metrics_path = os.path.join(run, "metrics.json")
    if os.path.exists(metrics_path):
        with open(metrics_path) as f:
            m = json.load(f)
        tasks = m.get("tasks", [])
        if tasks:
            coverage = tasks[0].get("coverage")
    lead_box = first_box.get(leader0)
    return {
        "run": run,
        "task": True,
        "pedestrian": her,
        "pick_t": pick["t"] if pick else None,
        "leader": leader0,
        "leader_first_box": {"tick": lead_box[0], "on": lead_box[1], "score": lead_box[3],
                             "height_px": lead_box[4]} if lead_box else None,
        "first_wrong": verdict,
        "culprit": culprit,
        "coverage": coverage,
    }


def main(argv):
    as_json = "--json" in argv
    min_seconds = 1.0
    runs = []
    it = iter(a for a in argv if a != "--json")
    for a in it:
        if a == "--min-seconds":
            min_seconds = float(next(it))
        else:
            runs.append(a)
    if not runs:
        sys.exit(__doc__)
    out = [classify(r, min_seconds) for r in runs]
    if as_json:
        print(json.dumps(out, indent=1))
        return
    counts = collections.Counter(o["first_wrong"] for o in out if o["task"])
    for o in out:
        if not o["task"]:
            print(f"{o['run']}: no task")
            continue
        lb = o["leader_first_box"] or {}
        c = o["culprit"] or {}
        print(f"{o['run']}: her {o['pedestrian']} picked at {o['pick_t']} s by camera "
              f"{o['leader']} (first box on {lb.get('on')}, {lb.get('height_px')} px, "
              f"score {lb.get('score')}); first wrong: {o['first_wrong']}"
              + (f" (camera {c['camera']} as {c['role']} at {c['t']:.1f} s on {c['on']}; "
                 f"the leader last on her at {c['leader_last_on_her']} s)" if c else "")
              + f"; coverage {o['coverage']}")
    print("first wrong:", dict(counts))


if __name__ == "__main__":
    main(sys.argv[1:])
