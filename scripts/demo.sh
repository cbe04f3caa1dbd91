#!/usr/bin/env bash
# Installs what is missing, builds (Release) and runs the demo scenario.
#   scripts/demo.sh [extra `argus run` options, e.g. --speed 1 or --threads 2]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
cd "$ARGUS_ROOT"
argus_build build -DCMAKE_BUILD_TYPE=Release
build/apps/argus run scenarios/demo.yaml "$@"
echo "argus: the demo's outputs are in $ARGUS_ROOT/out/demo (events.jsonl, summary.json)"
