#!/usr/bin/env python3
"""Whom the group follows when it is not on her, and how much she looks like them.

Colour indexing compares colours only: a pedestrian dressed as she is scores as high as she does
however well the tracker works, and the station's palettes hold near-twins on purpose
(world/behaviour.cpp). This reads `argus run` folders (tracks.csv, targets.csv, pedestrians.csv)
and, per task, counts her look-alikes among everyone who entered the station before the task
ended, then splits the time she was not covered while a member's box was on someone else by how
much that someone looks like her:

- twin: shirt and trousers each within --alike of hers (RGB distance, 0-255 per channel; the
  default 30 takes the palettes' designed near-twins, 11-26 apart, and nothing else: the next
  nearest pair is 32 apart);
- shirt: the shirt alike, the trousers not;
- trousers: the trousers alike, the shirt not;
- unlike: neither.

Where members are on several others at once, the tick goes to the most alike. It prints a table
per task and the totals; --json gives the same as JSON.

    bench/lookalikes.py RUN_DIR [RUN_DIR ...] [--alike 30] [--json]
"""
import argparse
import collections
import csv
import json
import math
import os
import sys

RELATIONS = ("twin", "shirt", "trousers", "unlike")


def colour(text):
    return tuple(int(text[i:i + 2], 16) for i in (1, 3, 5))


def relation(her, other, alike):
    shirt = math.dist(her["shirt"], other["shirt"]) <= alike
    trousers = math.dist(her["trousers"], other["trousers"]) <= alike
    if shirt and trousers:
        return "twin"
    if shirt:
        return "shirt"
    if trousers:
        return "trousers"
    return "unlike"


def read_csv(run, name):
    path = os.path.join(run, name)
    if not os.path.exists(path):
        sys.exit(f"{path}: missing (pedestrians.csv is written by argus run since it was added; "
                 "rerun with the current binary)")
    with open(path) as f:
        return list(csv.DictReader(f))


def tasks_of(run, alike):
    """One record per task of a run: her look-alikes and where her uncovered time went."""
    people = {}
    for r in read_csv(run, "pedestrians.csv"):
        people[int(r["id"])] = {"shirt": colour(r["shirt"]), "trousers": colour(r["trousers"]),
                                "first_tick": int(r["first_tick"])}
    targets = collections.defaultdict(dict)  # task -> tick -> row
    for r in read_csv(run, "targets.csv"):
        targets[int(r["task"])][int(r["tick"])] = r
    on = collections.defaultdict(lambda: collections.defaultdict(set))  # task -> tick -> truths
    for r in read_csv(run, "tracks.csv"):
        if r["found"] == "1" and int(r["truth"]) > 0:
            on[int(r["task"])][int(r["tick"])].add(int(r["truth"]))
    out = []
    for task, ticks in sorted(targets.items()):
        first = next(iter(ticks.values()))
        her_id = int(first["pedestrian"])
        her = people[her_id]
        last_tick = max(ticks)
        census = collections.Counter(
            relation(her, p, alike) for pid, p in people.items()
            if pid != her_id and p["first_tick"] <= last_tick)
        present = covered = 0
        elsewhere = collections.Counter()
        for tick, row in ticks.items():
            if row["present"] != "1":
                continue
            present += 1
            if int(row["observed_by"]) >= 0:
                covered += 1
                continue
            others = [p for p in on[task].get(tick, ()) if p != her_id and p in people]
            if others:
                rank = min(RELATIONS.index(relation(her, people[p], alike)) for p in others)
                elsewhere[RELATIONS[rank]] += 1
        share = (lambda n: n / present) if present else (lambda n: 0.0)
        out.append({
            "run": run, "task": task, "pedestrian": her_id,
            "lookalikes": {k: census[k] for k in RELATIONS[:3]},
            "people": sum(census.values()),
            "coverage": share(covered),
            "on_someone_else": {k: share(elsewhere[k]) for k in RELATIONS},
        })
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("runs", nargs="+")
    parser.add_argument("--alike", type=float, default=30.0)
    parser.add_argument("--json", action="store_true")
    args = parser.parse_args()
    records = [t for run in args.runs for t in tasks_of(run, args.alike)]
    if args.json:
        json.dump(records, sys.stdout, indent=1)
        print()
        return
    print(f"{'run':24} {'task':>4} {'her':>4} {'people':>6} {'twins':>5} {'shirt':>5}"
          f" {'cover':>6} | on someone else: " + " ".join(f"{k:>8}" for k in RELATIONS))
    for t in records:
        print(f"{t['run'][-24:]:24} {t['task']:4d} {t['pedestrian']:4d} {t['people']:6d}"
              f" {t['lookalikes']['twin']:5d} {t['lookalikes']['shirt']:5d} {t['coverage']:6.3f} |"
              "                  " + " ".join(f"{t['on_someone_else'][k]:8.3f}" for k in RELATIONS))
    if len(records) > 1:
        n = len(records)
        mean = {k: sum(t["on_someone_else"][k] for t in records) / n for k in RELATIONS}
        print(f"{'mean over ' + str(n) + ' tasks':24} {'':4} {'':4} {'':6} {'':5} {'':5}"
              f" {sum(t['coverage'] for t in records) / n:6.3f} |                  "
              + " ".join(f"{mean[k]:8.3f}" for k in RELATIONS))


if __name__ == "__main__":
    main()
