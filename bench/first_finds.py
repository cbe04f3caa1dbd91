#!/usr/bin/env python3
"""Who a camera's track starts on, and whether she was in its view then.

A camera's tracker starts a track either on the operator's pick or, afterwards, by a find: a
bidder's first look, or a lost track found again. This reads runs made with `argus run --mot`
and classes every track start (a found row after a row without a box, or a camera's first) by
the camera's role, by whether the box is on her (tracks.csv's `truth`), and by whether she was
in that camera's frame at all (the camera's MOT ground truth: in view = visible above 0.3,
hidden = in the frame but covered more, absent = not in the frame). It prints a table, the
acceptance scores (histogram intersection) of right and wrong starts, and, with --json, the
same as JSON.

    bench/first_finds.py RUN_DIR [RUN_DIR ...] [--json]

Each RUN_DIR is an `argus run ... --mot` output folder (tracks.csv, targets.csv, mot/).
"""
import collections
import csv
import glob
import json
import os
import statistics
import sys


def ground_truth_boxes(run):
    """(camera, tick) -> {pedestrian: (box height, visibility)} from the MOT ground truth."""
    seen = collections.defaultdict(dict)
    pattern = os.path.join(run, "mot/gt/mot_challenge/ARGUS-all/cam*/gt/gt.txt")
    files = glob.glob(pattern)
    if not files:
        sys.exit(f"{run}: no MOT ground truth ({pattern}); run argus with --mot")
    for path in files:
        camera = int(path.split("/cam")[-1].split("/")[0])
        with open(path) as f:
            for line in f:
                p = line.strip().split(",")
                seen[(camera, int(p[0]) - 1)][int(p[1])] = (float(p[5]), float(p[8]))
    return seen


def visible_targets(run):
    """(camera, tick) -> {pedestrian: visibility} from the MOT ground truth."""
    return {key: {who: v for who, (_, v) in people.items()}
            for key, people in ground_truth_boxes(run).items()}


def track_starts(run):
    """(role, right|wrong, in_view|hidden|absent, score) for every track start in a run."""
    with open(os.path.join(run, "targets.csv")) as f:
        target = {r["task"]: int(r["pedestrian"]) for r in csv.DictReader(f)}
    seen = visible_targets(run)
    had_box = {}
    with open(os.path.join(run, "tracks.csv")) as f:
        for r in csv.DictReader(f):
            key = (r["camera"], r["task"])
            found = r["found"] == "1"
            if found and not had_box.get(key, False):
                her = target[r["task"]]
                visibility = seen.get((int(r["camera"]), int(r["tick"])), {}).get(her)
                where = ("absent" if visibility is None
                         else "in_view" if visibility > 0.3 else "hidden")
                right = "right" if int(r["truth"]) == her else "wrong"
                yield r["role"], right, where, float(r["score"])
            had_box[key] = found


def quantiles(values):
    if not values:
        return None
    v = sorted(values)
    return [v[int(p * (len(v) - 1))] for p in (0.1, 0.25, 0.5, 0.75, 0.9)]


def main(argv):
    as_json = "--json" in argv
    runs = [a for a in argv if a != "--json"]
    if not runs:
        sys.exit(__doc__)
    counts = collections.Counter()
    scores = {"right": [], "wrong": []}
    for run in runs:
        for role, right, where, score in track_starts(run):
            counts[(role, right, where)] += 1
            scores[right].append(score)
    rows = [{"role": role, "on_her": right == "right", "she_was": where, "starts": n}
            for (role, right, where), n in sorted(counts.items())]
    summary = {
        "runs": len(runs),
        "starts": sum(counts.values()),
        "on_her": sum(n for (_, r, _), n in counts.items() if r == "right"),
        "she_absent": sum(n for (_, _, w), n in counts.items() if w == "absent"),
        "score_quantiles_10_25_50_75_90": {k: quantiles(v) for k, v in scores.items()},
        "rows": rows,
    }
    if as_json:
        print(json.dumps(summary, indent=1))
        return
    print(f"{summary['runs']} runs, {summary['starts']} track starts, "
          f"{summary['on_her']} on her, {summary['she_absent']} while she was not in the frame")
    print(f"{'role':8} {'on her':7} {'she was':8} {'starts':>7}")
    for r in rows:
        print(f"{r['role']:8} {'yes' if r['on_her'] else 'no':7} {r['she_was']:8} {r['starts']:7d}")
    for k, q in summary["score_quantiles_10_25_50_75_90"].items():
        if q:
            print(f"score of {k} starts (10/25/50/75/90 %): " + " ".join(f"{x:.2f}" for x in q)
                  + f"  mean {statistics.mean(scores[k]):.3f}")


if __name__ == "__main__":
    main(sys.argv[1:])
