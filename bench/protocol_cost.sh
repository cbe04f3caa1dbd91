#!/usr/bin/env bash
# The camera protocol's cost on whole runs: penn_station with one task, emulated sensing and
# pixel sensing (320x240), each run RUNS times; prints each run's speed ratio (simulated over
# wall seconds, from summary.json) and the median.
#   bench/protocol_cost.sh [RUNS] [ARGUS]
set -euo pipefail
runs="${1:-5}"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
argus="${2:-$root/build/apps/argus}"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
measure() {  # scenario duration
  local ratios=()
  for ((i = 0; i < runs; ++i)); do
    "$argus" run "$root/scenarios/$1.yaml" --duration "$2" --threads 2 --out "$out/$1" \
      --no-progress >/dev/null
    ratios+=("$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["speed_ratio"])' \
      "$out/$1/summary.json")")
  done
  python3 - "$1" "$2" "${ratios[@]}" <<'PY'
import statistics, sys
name, duration, *r = sys.argv[1:]
r = [float(x) for x in r]
print(f"{name:24} {duration:>6}  runs {len(r)}  x real time: median {statistics.median(r):7.1f}"
      f"  min {min(r):7.1f}  max {max(r):7.1f}")
PY
}
lscpu | grep -m1 "Model name" || true
measure penn_station_emulated "15 min"
measure penn_station "2 min"
