#!/usr/bin/env python3
"""How each camera's hold on her ends, and what the leaders' boxes are on.

Reads `argus run` folders (tracks.csv, targets.csv: every run writes them; a sweep's runs are
its runs/ folders) and prints two tables:

- every stretch of frames in which a camera's box was on her (tracks.csv `truth` is her id), by
  role and by how it ended: slid straight onto the background (a box on no one, `truth` -1) or
  onto someone else, lost and then found again (on her, someone else, the background), left
  the task, or the run ended;
- the share of each task's frames by what its leaders' boxes were on (her, someone else,
  background, not found) and whether a member's box was on her then; means over tasks.

    bench/track_ends.py RUN_DIR [RUN_DIR ...] [--json]
"""
import collections
import csv
import json
import os
import sys


def on_what(row, her):
    if row["found"] != "1":
        return "not_found"
    truth = int(row["truth"])
    return "her" if truth == her else "background" if truth == -1 else "someone_else"


def read(run):
    with open(os.path.join(run, "targets.csv")) as f:
        target = {r["task"]: int(r["pedestrian"]) for r in csv.DictReader(f)}
    with open(os.path.join(run, "tracks.csv")) as f:
        rows = list(csv.DictReader(f))
    return target, rows


def stretch_ends(target, rows):
    """(role, how it ended) for every stretch of a camera's frames on her."""
    by_camera = collections.defaultdict(list)
    for r in rows:
        by_camera[(r["task"], r["camera"])].append(
            (int(r["tick"]), on_what(r, target[r["task"]]), r["role"]))
    for frames in by_camera.values():
        i = 0
        while i < len(frames):
            if frames[i][1] != "her":
                i += 1
                continue
            role = frames[i][2]
            j = i + 1
            while j < len(frames) and frames[j][1] == "her" and frames[j][0] == frames[j - 1][0] + 1:
                j += 1
            if j == len(frames):
                yield role, "run ended"
                break
            if frames[j][0] != frames[j - 1][0] + 1:
                yield role, "left the task"
                i = j
                continue
            if frames[j][1] != "not_found":
                yield role, f"slid onto {frames[j][1].replace('_', ' ')}"
                i = j
                continue
            k = j
            while k < len(frames) and frames[k][1] == "not_found" and frames[k][0] == frames[k - 1][0] + 1:
                k += 1
            if k == len(frames) or frames[k][0] != frames[k - 1][0] + 1:
                yield role, "lost, then left the task"
            else:
                yield role, f"lost, found again on {frames[k][1].replace('_', ' ')}"
            i = k


def leader_shares(target, rows):
    """{task: {(leader box on, member on her): share of the task's frames}}."""
    frames = collections.defaultdict(lambda: collections.defaultdict(list))
    for r in rows:
        frames[r["task"]][int(r["tick"])].append(r)
    out = {}
    for task, ticks in frames.items():
        her = target[task]
        counts = collections.Counter()
        for rs in ticks.values():
            leaders = [on_what(r, her) for r in rs if r["role"] == "leader"]
            lead = "her" if "her" in leaders else leaders[0] if leaders else "no leader"
            member = any(on_what(r, her) == "her" for r in rs if r["role"] == "member")
            counts[(lead, member)] += 1
        total = sum(counts.values())
        out[task] = {k: v / total for k, v in counts.items()}
    return out


def main(args):
    as_json = "--json" in args
    runs = [a for a in args if a != "--json"]
    if not runs:
        sys.exit(__doc__)
    ends = collections.Counter()
    shares = collections.defaultdict(float)
    tasks = 0
    for run in runs:
        target, rows = read(run)
        ends.update(stretch_ends(target, rows))
        for per_task in leader_shares(target, rows).values():
            tasks += 1
            for k, v in per_task.items():
                shares[k] += v
    shares = {k: v / tasks for k, v in shares.items()} if tasks else {}
    if as_json:
        print(json.dumps({
            "runs": len(runs), "tasks": tasks,
            "stretch_ends": [{"role": r, "end": e, "count": n} for (r, e), n in sorted(ends.items())],
            "leader_shares": [{"leader_on": l, "member_on_her": m, "share": round(s, 4)}
                              for (l, m), s in sorted(shares.items())]}, indent=1))
        return
    print(f"{len(runs)} runs, {tasks} tasks\n")
    print("| role | how her stretch ended | stretches |\n| --- | --- | ---: |")
    for (role, end), n in sorted(ends.items(), key=lambda x: (x[0][0], -x[1])):
        print(f"| {role} | {end} | {n} |")
    print("\n| leaders' box on | a member on her | share of the task's frames |\n| --- | --- | ---: |")
    for (lead, member), s in sorted(shares.items(), key=lambda x: -x[1]):
        print(f"| {lead.replace('_', ' ')} | {'yes' if member else 'no'} | {s:.3f} |")


if __name__ == "__main__":
    main(sys.argv[1:])
