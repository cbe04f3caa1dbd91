#!/usr/bin/env python3
"""Where her uncovered time goes, by who had her in the frame.

Reads runs made with `argus run ... --mot` (tracks.csv, targets.csv, mot/) and classes each
tick of task 0 in which she is in the station and no group member's box holds her: she is
visible (more than 0.3 of her) in a member's frame and not found; hidden in a member's frame;
in no member's frame but visible in another camera's frame as it points then; nobody performs
the task; or in no camera's frame. It also gives her box height (10th / 50th / 90th
percentile) where she was visible in a member's frame and not found, and her tallest box in the
other cameras' frames where only they had her.

    bench/uncovered_views.py RUN_DIR [RUN_DIR ...]
"""
import collections
import csv
import os
import statistics
import sys

from first_finds import ground_truth_boxes


def classify(run, heights_member, heights_other):
    gt = ground_truth_boxes(run)
    cameras = {c for c, _ in gt}
    members = collections.defaultdict(dict)
    with open(os.path.join(run, "tracks.csv")) as f:
        for r in csv.DictReader(f):
            if r["task"] == "0":
                members[int(r["tick"])][int(r["camera"])] = r["observed"] == "1"
    counts = collections.Counter()
    with open(os.path.join(run, "targets.csv")) as f:
        for r in csv.DictReader(f):
            if r["task"] != "0" or r["present"] != "1":
                continue
            tick, her = int(r["tick"]), int(r["pedestrian"])
            group = members.get(tick, {})
            if any(group.values()):
                counts["covered"] += 1
                continue
            in_members = [gt.get((c, tick), {}).get(her) for c in group]
            visible = [v for v in in_members if v and v[1] > 0.3]
            others = [gt.get((c, tick), {}).get(her) for c in cameras if c not in group]
            others = [v for v in others if v and v[1] > 0.3]
            if visible:
                counts["visible in a member's frame, not found"] += 1
                heights_member.append(max(h for h, _ in visible))
            elif any(in_members):
                counts["hidden in a member's frame"] += 1
            elif not others:
                counts["in no camera's frame" if group else "nobody performs the task"] += 1
            elif group:
                counts["in another camera's frame only"] += 1
                heights_other.append(max(h for h, _ in others))
            else:
                counts["nobody performs the task"] += 1
    total = sum(counts.values())
    return {k: v / total for k, v in counts.items()}


def percentiles(values):
    if len(values) < 10:
        return "too few"
    q = statistics.quantiles(values, n=10)
    return f"{q[0]:.0f} / {q[4]:.0f} / {q[8]:.0f} px ({len(values)} ticks)"


def main():
    runs = sys.argv[1:]
    if not runs:
        sys.exit(__doc__)
    heights_member, heights_other = [], []
    shares = collections.Counter()
    for run in runs:
        for k, v in classify(run, heights_member, heights_other).items():
            shares[k] += v / len(runs)
    for k, v in sorted(shares.items(), key=lambda kv: -kv[1]):
        print(f"{k}: {v:.3f}")
    print("her height, visible in a member's frame and not found:", percentiles(heights_member))
    print("her tallest height, in another camera's frame only:", percentiles(heights_other))


if __name__ == "__main__":
    main()
