#!/usr/bin/env bash
# Where a distributed run's --video tiles are rendered (docs/distributed.md, "Video"): the same
# run with --video in one process, with 2 `argus worker` processes on loopback rendering their
# cameras' tiles (placement.video=workers, the default), and with 2 workers and every tile
# rendered on the coordinator (placement.video=coordinator), in turn, ROUNDS times. Prints each
# variant's median wall seconds of the whole `argus run` and its ratio to one process, paired
# round by round, and checks that every run wrote the one-process video/feeds.avi.
#   bench/distributed_video.sh [ARGUS] [ROUNDS] [SCENARIO] [DURATION] [VIDEO SIZE]
# Defaults: build/apps/argus, 3 rounds, penn_station.yaml (pixels), "30 s", 320x240.
# The field cache is kept warm (one run fills it before the rounds): this compares renders.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
argus="${1:-$root/build/apps/argus}"
rounds="${2:-3}"
scenario="${3:-penn_station.yaml}"
duration="${4:-30 s}"
size="${5:-320x240}"
out="$(mktemp -d)"
export ARGUS_FIELD_CACHE="$out/fields"
pids=()
trap 'for p in "${pids[@]}"; do kill "$p" 2>/dev/null; done; rm -rf "$out"' EXIT

workers=()
# shellcheck source=bench/bench_workers.sh
source "$root/bench/bench_workers.sh"
start_workers 2
two="${workers[0]},${workers[1]}"
run=("$argus" run "$root/scenarios/$scenario" --seed 1 --no-feeds --no-progress --video
     --video-size "$size")

timed() {  # timed FILE COMMAND...: appends the wall seconds of COMMAND to FILE
  local file=$1 start end
  shift
  start=$(date +%s.%N)
  "$@" >/dev/null 2>"$out/last.err" || { cat "$out/last.err" >&2; exit 1; }
  end=$(date +%s.%N)
  python3 -c "print($end - $start)" >>"$file"
}

"${run[@]}" --duration "1 s" --set run.output_dir="$out/fill" >/dev/null 2>&1
run+=(--duration "$duration")
for r in $(seq "$rounds"); do
  timed "$out/one" "${run[@]}" --set run.output_dir="$out/run-one"
  timed "$out/workers" "${run[@]}" --set run.output_dir="$out/run-workers" --workers "$two"
  timed "$out/here" "${run[@]}" --set run.output_dir="$out/run-here" --workers "$two" \
    --set placement.video=coordinator
  for v in workers here; do
    cmp -s "$out/run-one/video/feeds.avi" "$out/run-$v/video/feeds.avi" ||
      { echo "round $r: placement $v wrote another video/feeds.avi" >&2; exit 1; }
  done
done
grep -q "rendering its cameras' video tiles" "$out/worker-1.log" ||
  { echo "worker 1 never rendered a tile" >&2; exit 1; }
python3 - "$scenario" "$duration" "$size" "$out/one" "$out/workers" "$out/here" <<'PY'
import statistics, sys
scenario, duration, size = sys.argv[1:4]
one, workers, here = ([float(x) for x in open(f)] for f in sys.argv[4:7])
med = statistics.median
print(f"{scenario} ({duration}, --video {size}): one process {med(one):.2f} s; "
      f"2 workers, tiles on the workers {med(workers):.2f} s "
      f"({med(b / a for a, b in zip(one, workers)):.2f}x); "
      f"2 workers, tiles on the coordinator {med(here):.2f} s "
      f"({med(b / a for a, b in zip(one, here)):.2f}x); "
      f"{len(one)} rounds, ratios paired by round")
PY
