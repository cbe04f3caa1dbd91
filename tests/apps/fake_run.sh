#!/bin/sh
# Stands in for `argus run` in the sweep tests: takes the same arguments, logs that it started,
# writes them to DIR/arguments, takes FAKE_RUN_SECONDS (default 0.3; 60 for seed FAKE_SLOW_SEED,
# a run the test interrupts) and writes a metrics.json whose summary depends on the seed and on
# the --set values, through a rename, as a run that is not interrupted does.
all="$*"
out="" seed=0 sets=""
while [ $# -gt 0 ]; do
  case "$1" in
    --out) out="$2"; shift ;;
    --seed) seed="$2"; shift ;;
    --set) sets="$sets $2"; shift ;;
  esac
  shift
done
[ -n "$out" ] || { echo "fake_run: no --out" >&2; exit 2; }
mkdir -p "$out"
echo "$all" > "$out/arguments"
echo "start $(basename "$out")" >> "$out/../../invocations.log"
# exec: the sweep's SIGTERM then stops the sleep itself, leaving nothing behind.
[ "$seed" = "${FAKE_SLOW_SEED:-none}" ] && exec sleep 60
sleep "${FAKE_RUN_SECONDS:-0.3}"
loss=0
for s in $sets; do
  case "$s" in network.loss_probability=*) loss="${s#*=}" ;; esac
done
coverage=$(awk -v l="$loss" -v s="$seed" 'BEGIN { printf "%.4f", 0.9 - l + 0.01 * s }')
printf '{"summary": {"tasks": 1, "mean_coverage": %s, "handoffs": %s, "mean_coverage_of_oracle": null}}\n' \
  "$coverage" "$seed" > "$out/metrics.json.partial"
mv "$out/metrics.json.partial" "$out/metrics.json"
