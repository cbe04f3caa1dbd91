#!/usr/bin/env bash
# Coverage of one scenario's tasks over seeds, for one or two argus binaries (old against new,
# same machine, same run): each seed's `argus run` (two at a time), then per binary the mean
# coverage, each seed's coverage, the mean correct identity, the leader changes summed and the
# mean share of her time lost to each cause (metrics.json's `uncovered`).
#   bench/coverage_by_seed.sh SCENARIO DURATION SEEDS ARGUS [ARGUS2] [-- RUN ARGS...]
# e.g. bench/coverage_by_seed.sh scenarios/penn_station.yaml "2 min" 16 old/argus build/apps/argus
set -euo pipefail
scenario="$1" duration="$2" seeds="$3"
shift 3
binaries=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do binaries+=("$1"); shift; done
[ "${1:-}" = "--" ] && shift
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
lscpu | grep -m1 "Model name" || true
for b in "${!binaries[@]}"; do
  feeds=()  # binaries from before feeds/ know no --no-feeds
  "${binaries[$b]}" run --help | grep -q -- --no-feeds && feeds=(--no-feeds)
  seq 1 "$seeds" | xargs -P 2 -I{} "${binaries[$b]}" run "$scenario" --seed {} \
    --duration "$duration" --out "$out/$b/s{}" "${feeds[@]}" "$@" >/dev/null 2>&1
  python3 - "${binaries[$b]}" "$out/$b" "$seeds" <<'PY'
import json, statistics, sys
name, folder, seeds = sys.argv[1], sys.argv[2], int(sys.argv[3])
cov, ident, changes, why = [], [], 0, {}
for s in range(1, seeds + 1):
    for t in json.load(open(f"{folder}/s{s}/metrics.json"))["tasks"]:
        cov.append(t["coverage"])
        ident.append(t["correct_identity"] or 0.0)
        changes += t["leader_changes"]
        for cause, share in t.get("uncovered", {}).items():  # older binaries have none
            why.setdefault(cause, []).append(share)
print(f"{name}: tasks {len(cov)}, coverage mean {statistics.mean(cov):.3f}"
      f" (sd {statistics.stdev(cov):.3f}), identity {statistics.mean(ident):.2f},"
      f" leader changes {changes}")
print("  per seed: " + " ".join(f"{c:.2f}" for c in cov))
if why:
    print("  not covered: " + ", ".join(f"{k} {statistics.mean(v):.3f}" for k, v in sorted(why.items())))
PY
done
