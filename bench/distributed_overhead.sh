#!/usr/bin/env bash
# What a distributed run costs against one process on the same machine (issue 51): each
# scenario below run in one process and with 2 and 4 `argus worker` processes on loopback, in
# turn (one process, 2 workers, 4 workers, again ...), ROUNDS times; prints each variant's median
# wall seconds of the whole `argus run` and its ratio to one process, paired round by round, and
# checks that every run wrote the one-process events.jsonl.
#   bench/distributed_overhead.sh [ARGUS] [ROUNDS] [RUN OPTIONS...]
# RUN OPTIONS go to the distributed runs, e.g. `--set placement.crowd=coordinator`.
# Then the per-tick cost of the cross-process barrier: minimal.yaml (emulated, three cameras,
# nearly nothing to compute) in one process and with one worker, 1,800 ticks.
# Each scenario runs for its own duration (the large station 2 min, Penn Station 15 min), as a
# user's run does: a short run is mostly the fixed set-up of three processes on two cores.
# LARGE_DURATION and PENN_DURATION set another, e.g. LARGE_DURATION="20 s" PENN_DURATION="60 s"
# for a quicker look (about 3 min a round instead of about 12).
# Every process shares one field cache (docs/world.md, "The field cache"). FIELD_CACHE=cold (the
# default) empties it before each run, so each run computes its station's fields once (in its
# coordinator; its workers read them); FIELD_CACHE=warm keeps it, as on a machine that has run
# the station before.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
argus="${1:-$root/build/apps/argus}"
rounds="${2:-3}"
shift $(($# < 2 ? $# : 2))
distributed_options=("$@")
out="$(mktemp -d)"
cache_state="${FIELD_CACHE:-cold}"
case "$cache_state" in cold | warm) ;; *) echo "FIELD_CACHE: expected cold or warm, got '$cache_state'" >&2; exit 2 ;; esac
export ARGUS_FIELD_CACHE="$out/fields"
pids=()
trap 'for p in "${pids[@]}"; do kill "$p" 2>/dev/null; done; rm -rf "$out"' EXIT

workers=()
# shellcheck source=bench/bench_workers.sh
source "$root/bench/bench_workers.sh"
start_workers 4
two="${workers[0]},${workers[1]}"
four="${workers[0]},${workers[1]},${workers[2]},${workers[3]}"

timed() {  # timed FILE COMMAND...: appends the wall seconds of COMMAND to FILE
  local file=$1 start end
  shift
  [ "$cache_state" = cold ] && rm -rf "$ARGUS_FIELD_CACHE"
  start=$(date +%s.%N)
  "$@" >/dev/null 2>"$out/last.err" || { cat "$out/last.err" >&2; exit 1; }
  end=$(date +%s.%N)
  python3 -c "print($end - $start)" >>"$file"
}

compare() {  # compare NAME LABEL SCENARIO DURATION [run options]; DURATION "" is the scenario's
  local name=$1 label=$2 scenario=$3 duration=$4
  shift 4
  local run=("$argus" run "$root/scenarios/$scenario" --seed 1 --no-feeds --no-progress "$@")
  if [ -n "$duration" ]; then
    run+=(--duration "$duration")
  else
    duration="its own duration"
  fi
  for r in $(seq "$rounds"); do
    timed "$out/$name-1" "${run[@]}" --set run.output_dir="$out/$name-run-1"
    timed "$out/$name-2" "${run[@]}" --set run.output_dir="$out/$name-run-2" --workers "$two" \
      ${distributed_options[@]+"${distributed_options[@]}"}
    timed "$out/$name-4" "${run[@]}" --set run.output_dir="$out/$name-run-4" --workers "$four" \
      ${distributed_options[@]+"${distributed_options[@]}"}
    for n in 2 4; do
      cmp -s "$out/$name-run-1/events.jsonl" "$out/$name-run-$n/events.jsonl" ||
        { echo "$name: $n workers wrote another events.jsonl" >&2; exit 1; }
    done
  done
  python3 - "$label" "$duration" "$out/$name-1" "$out/$name-2" "$out/$name-4" "$cache_state" <<'PY'
import statistics, sys
name, duration = sys.argv[1], sys.argv[2]
one, two, four = ([float(x) for x in open(f)] for f in sys.argv[3:6])
med = statistics.median
print(f"{name} ({duration}, field cache {sys.argv[6]}): one process {med(one):.2f} s; "
      f"2 workers {med(two):.2f} s ({med(b / a for a, b in zip(one, two)):.2f}x); "
      f"4 workers {med(four):.2f} s ({med(b / a for a, b in zip(one, four)):.2f}x); "
      f"{len(one)} rounds, ratios paired by round")
PY
}

compare large "large station, emulated" large_station.yaml "${LARGE_DURATION:-}"
compare penn "Penn Station, pixels" penn_station.yaml "${PENN_DURATION:-}"

# The barrier: the same near-empty run in one process and with one worker.
for r in $(seq "$rounds"); do
  timed "$out/bare-1" "$argus" run "$root/scenarios/minimal.yaml" --duration "120 s" --no-feeds \
    --no-progress --set sensing.mode=emulated --set run.output_dir="$out/bare-run-1"
  timed "$out/bare-w" "$argus" run "$root/scenarios/minimal.yaml" --duration "120 s" --no-feeds \
    --no-progress --set sensing.mode=emulated --set run.output_dir="$out/bare-run-w" \
    --workers "${workers[0]}"
done
python3 - "$out/bare-1" "$out/bare-w" <<'PY'
import statistics, sys
one, one_worker = ([float(x) for x in open(f)] for f in sys.argv[1:3])
ticks = 1800
per_tick = statistics.median((b - a) / ticks for a, b in zip(one, one_worker))
print(f"barrier: minimal.yaml, {ticks} ticks: one process {statistics.median(one):.2f} s, "
      f"one worker {statistics.median(one_worker):.2f} s: {per_tick * 1e6:.0f} us more a tick")
PY
