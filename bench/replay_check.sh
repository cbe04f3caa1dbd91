#!/usr/bin/env bash
# Replay on whole runs, longer than CI affords (issue 17): each scenario below at --threads 1, 2,
# 3, 4 and 8, free-running (--speed 0) and paced, with --video where the run is short enough;
# events.jsonl, trajectories.csv (and the video) must be byte-identical across the ten runs. Prints, per
# scenario, what the runs went through (faults by kind, recoveries, duplicated messages, the
# camera protocol's joins and hand-overs) and whether the outputs agree; exits 1 if any differ.
#   bench/replay_check.sh [ARGUS]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
argus="${1:-$root/build/apps/argus}"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
status=0
check() {  # scenario duration paced-speed [--video]
  local reference="" started=$SECONDS files=(events.jsonl trajectories.csv) video=()
  if [[ "${4:-}" == --video ]]; then
    files+=(video/feeds.avi)
    video=(--video --video-size 80x60)
  fi
  for speed in 0 "$3"; do
    for threads in 1 2 3 4 8; do
      local dir="$out/$1/t${threads}_s${speed}"
      "$argus" run "$root/scenarios/$1.yaml" --duration "$2" --threads "$threads" --speed "$speed" \
        "${video[@]}" --out "$dir" --no-progress >/dev/null
      if [[ -z "$reference" ]]; then
        reference="$dir"
        continue
      fi
      for f in "${files[@]}"; do
        if ! cmp -s "$reference/$f" "$dir/$f"; then
          echo "$1: $f differs: --threads 1 --speed 0 against --threads $threads --speed $speed"
          status=1
        fi
      done
    done
  done
  python3 - "$1" "$2" "$reference" $((SECONDS - started)) "${files[*]}" <<'PY'
import collections, json, sys
name, duration, ref, wall, files = sys.argv[1:]
summary = json.load(open(f"{ref}/summary.json"))
faults, kinds = collections.Counter(), collections.Counter()
for line in open(f"{ref}/events.jsonl"):
    e = json.loads(line)
    kinds[e["kind"]] += 1
    if e["kind"] == "fault" and e["applied"]:
        faults[e["fault"] + (" (random)" if e["random"] else "")] += 1
totals = summary["network"]["totals"]
print(f"{name} {duration}: {summary['ticks']} ticks, {summary['events_total']} events, "
      f"10 runs in {wall} s, compared: {files}")
print("  faults applied: " + ", ".join(f"{k} {v}" for k, v in sorted(faults.items())) +
      f"; recoveries {kinds['node_recovered']}")
print(f"  messages: {totals['sent']} sent, {totals['duplicated']} duplicated, "
      f"{totals['delivered']} delivered, {totals['lost']} lost, {totals['dropped']} dropped; "
      f"joined {kinds['joined']}, handoff {kinds['handoff']}, "
      f"leader_changed {kinds['leader_changed']}")
PY
}
lscpu | grep -m1 "Model name" || true
check replay_faults "1 min" 20 --video
check penn_station "2 min" 20 --video
check penn_station_emulated "15 min" 200
if [[ $status -eq 0 ]]; then
  echo "identical in every run"
fi
exit $status
