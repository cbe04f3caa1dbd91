#!/usr/bin/env python3
"""Solve time against conflict size for every CSP solver, through `argus csp solve`.

    bench/csp_scaling.py [--argus build/apps/argus] [--max-seconds 10] [--max-work N]
                         [--csv OUT.csv]

Instances: G groups over C cameras, each group min 1 and max 12 cameras, every relevance
uniform in [0, 1) (seeded), the shape the issue tried (40 cameras, 6 groups) and its
neighbours. Each solve runs under the command's default memory budget and the given wall-clock
budget; a run that hits it prints its best answer with proven_optimal false. Prints a Markdown
table (one row per instance and solver) and writes the same as CSV.
"""
import argparse
import csv
import json
import os
import random
import subprocess
import sys
import tempfile
import time

SIZES = [(10, 2), (15, 3), (20, 3), (25, 4), (30, 4), (40, 6), (80, 8), (160, 12)]
SOLVERS = ["allsolv", "bestsolv", "optimisticsolv", "boundsolv"]


def instance(cameras, groups, seed):
    rng = random.Random(seed)
    return {
        "threshold": 0.1,
        "groups": [{
            "id": f"g{g:02d}",
            "min_cameras": 1,
            "max_cameras": 12,
            "relevance": {f"c{c:03d}": round(rng.random(), 6) for c in range(cameras)},
        } for g in range(groups)],
    }



def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--argus", default="build/apps/argus")
    parser.add_argument("--max-seconds", type=float, default=10.0)
    parser.add_argument("--max-work", type=int, default=0,
                        help="values tried (a run's conflicts get 200000); 0: no limit")
    parser.add_argument("--csv", default="bench/csp_scaling.csv")
    args = parser.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as scratch:
        for cameras, groups in SIZES:
            path = os.path.join(scratch, f"c{cameras}_g{groups}.json")
            with open(path, "w") as f:
                json.dump(instance(cameras, groups, 1000 * cameras + groups), f)
            for solver in SOLVERS:
                start = time.monotonic()
                # /usr/bin/time -f %M reports the peak resident set in KiB.
                done = subprocess.run(
                    ["/usr/bin/time", "-f", "%M", args.argus, "csp", "solve", path, "--solver",
                     solver, "--max-seconds", str(args.max_seconds), "--max-work",
                     str(args.max_work)],
                    capture_output=True, text=True)
                wall = time.monotonic() - start
                if done.returncode != 0:
                    sys.exit(f"{solver} on {path}: exit {done.returncode}: {done.stderr}")
                answer = json.loads(done.stdout)
                peak_mb = int(done.stderr.strip().splitlines()[-1]) / 1024
                rows.append({
                    "cameras": cameras, "groups": groups, "solver": solver,
                    "time_ms": round(answer["time_ms"], 1), "wall_s": round(wall, 2),
                    "peak_rss_mb": round(peak_mb, 1), "weight": round(answer["weight"], 4),
                    "complete": answer["complete"], "proven_optimal": answer["proven_optimal"],
                    "stopped_by": answer["stopped_by"] or "",
                    "nodes_explored": answer["nodes_explored"],
                })
                r = rows[-1]
                print(f"| {cameras} | {groups} | {solver} | {r['time_ms']} | {r['peak_rss_mb']} | "
                      f"{r['weight']} | {r['proven_optimal']} | {r['stopped_by'] or '-'} |",
                      flush=True)
    with open(args.csv, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)


if __name__ == "__main__":
    main()
