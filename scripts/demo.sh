#!/usr/bin/env bash
# Installs what is missing, builds (Release) and runs the main demo: the paper's Penn Station
# with 16 PTZ cameras and 100 pedestrians for 15 minutes of virtual time, then draws its plan
# view and the cameras' feeds.
#   scripts/demo.sh [extra `argus run` options, e.g. --speed 1, --threads 2 or --video]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
cd "$ARGUS_ROOT"
argus_build build -DCMAKE_BUILD_TYPE=Release
out=out/penn_station
build/apps/argus run scenarios/penn_station.yaml --out "$out" "$@"
build/apps/argus plan scenarios/penn_station.yaml --time "5 min" --trails "20 s" --out "$out/plan.png"
build/apps/argus feeds scenarios/penn_station.yaml --time "5 min" --out "$out/feeds.png"
echo "argus: the demo's outputs are in $ARGUS_ROOT/$out:"
echo "  events.jsonl, summary.json, trajectories.csv, plan.png (plan view), feeds.png (camera feeds)"
