#!/usr/bin/env bash
# Installs what is missing, builds the one program the demo needs (Release, `argus`; no tests,
# no benchmarks) and runs the main demo: the paper's Penn Station with 16 PTZ cameras and 100
# pedestrians for 15 minutes of virtual time. The run draws its own report: report.html, the
# plan view (plan.png) and the cameras' feeds at the key events (feeds/contact_sheet.png).
#   scripts/demo.sh [extra `argus run` options, e.g. --speed 1, --threads 2 or --video]
set -euo pipefail
start=$SECONDS
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
cd "$ARGUS_ROOT"
stage() { echo "== $1 ($(((SECONDS - start) / 60)) min $(((SECONDS - start) % 60)) s in)"; }
stage "packages ready; building argus (Release)"
argus_build build --target argus -DCMAKE_BUILD_TYPE=Release -DARGUS_UNITY=ON
stage "built; running scenarios/penn_station.yaml"
out=out/penn_station
build/apps/argus run scenarios/penn_station.yaml --out "$out" "$@"
stage "done"
echo "argus: the demo's outputs, to look at first:"
for f in report.html plan.png feeds/contact_sheet.png; do
  if [ -f "$out/$f" ]; then echo "  $ARGUS_ROOT/$out/$f"; else echo "  (missing) $out/$f" >&2; fi
done
echo "  and beside them: events.jsonl, summary.json, metrics.json, trajectories.csv, timeline.png"
