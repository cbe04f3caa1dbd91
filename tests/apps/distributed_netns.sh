#!/bin/bash
# A distributed run across real network distance on this machine (docs/distributed.md): two
# workers, each in a network namespace of its own behind a veth pair, reached over TLS (they
# listen beyond loopback), with 0, 1 and 5 ms of latency each way: `tc netem` on the veth pairs
# where the kernel has it, else a relay that holds every byte that long (tests/apps/
# delay_relay.py). Each run must write what one process writes; ticks per second against the
# latency go to OUT/netns.csv.
#   distributed_netns.sh ARGUS SOURCE_DIR OUT [DURATION]
# Needs root (ip netns); prints "SKIPPED: ..." and exits 0 where it cannot make namespaces.
set -u
ARGUS=$(realpath "$1")
SOURCE=$2
OUT=$3
DURATION=${4:-20 s}
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$OUT"
mkdir -p "$OUT"
tag=$(printf '%04x' $((RANDOM % 65536)))
spaces=()
links=()
pids=()
cleanup() {
  for p in "${pids[@]}"; do kill -9 "$p" 2>/dev/null; done
  for l in "${links[@]}"; do ip link del "$l" 2>/dev/null; done
  for s in "${spaces[@]}"; do ip netns del "$s" 2>/dev/null; done
}
trap cleanup EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

if [ "$(id -u)" -ne 0 ] || ! ip netns add "ag$tag-probe" 2>/dev/null; then
  echo "SKIPPED: network namespaces need root and ip netns (iproute2)"
  exit 0
fi
ip netns del "ag$tag-probe"

"$here/make_test_pki.sh" "$OUT/pki" || fail "cannot make the test certificates"
pki=$OUT/pki
worker_tls=(--tls-cert "$pki/worker.pem" --tls-key "$pki/worker.key" --tls-ca "$pki/ca-a.pem")
coordinator_tls=(--tls-cert "$pki/coordinator.pem" --tls-key "$pki/coordinator.key" --tls-ca "$pki/ca-a.pem")

# Two namespaces: 10.77.N.1 here, 10.77.N.2 inside, over veth pair agTAG-hN / agTAG-nN.
addresses=()
for n in 1 2; do
  space=ag$tag-w$n
  host_end=ag$tag-h$n
  ip netns add "$space" || fail "ip netns add $space"
  spaces+=("$space")
  ip link add "$host_end" type veth peer name "ag$tag-n$n" || fail "ip link add $host_end"
  links+=("$host_end")
  ip link set "ag$tag-n$n" netns "$space"
  ip addr add "10.77.$n.1/24" dev "$host_end"
  ip link set "$host_end" up
  ip netns exec "$space" ip addr add "10.77.$n.2/24" dev "ag$tag-n$n"
  ip netns exec "$space" ip link set "ag$tag-n$n" up
  ip netns exec "$space" ip link set lo up
  log=$OUT/worker-$n.log
  ip netns exec "$space" "$ARGUS" worker --listen "10.77.$n.2:7001" --threads 1 "${worker_tls[@]}" \
    >"$log" 2>&1 &
  pids+=($!)
  for _ in $(seq 100); do grep -q "listening on" "$log" && break; sleep 0.1; done
  grep -q "listening on" "$log" || fail "worker $n: $(cat "$log")"
  addresses+=("10.77.$n.2:7001")
done

netem=0
if tc qdisc add dev "ag$tag-h1" root netem delay 1ms 2>/dev/null; then
  tc qdisc del dev "ag$tag-h1" root
  netem=1
fi

run() {  # run NAME [options]
  local name=$1
  shift
  "$ARGUS" run "$SOURCE/scenarios/replay_faults.yaml" --seed 5 --duration "$DURATION" \
    --no-feeds --no-progress --json --set run.threads=2 --set sensing.mode=emulated \
    --set run.output_dir="$OUT/$name" "$@" >"$OUT/$name.json" 2>"$OUT/$name.err"
}
run alone || fail "the one-process run: $(tail -3 "$OUT/alone.err")"
echo "latency_ms_each_way,how,ticks,wall_seconds,ticks_per_second" >"$OUT/netns.csv"
for delay in 0 1 5; do
  relays=()
  workers=""
  how=direct
  if [ "$delay" -gt 0 ] && [ $netem -eq 1 ]; then
    how=netem
    for n in 1 2; do
      tc qdisc replace dev "ag$tag-h$n" root netem delay "${delay}ms"
      ip netns exec "ag$tag-w$n" tc qdisc replace dev "ag$tag-n$n" root netem delay "${delay}ms"
    done
    workers=$(IFS=,; echo "${addresses[*]}")
  elif [ "$delay" -gt 0 ]; then
    how=relay
    for n in 1 2; do
      python3 "$here/delay_relay.py" "10.77.$n.1" "10.77.$n.2" 7001 "$delay" >"$OUT/relay-$n.port" &
      relays+=($!)
      pids+=($!)
      for _ in $(seq 50); do [ -s "$OUT/relay-$n.port" ] && break; sleep 0.1; done
      workers=${workers:+$workers,}10.77.$n.1:$(cat "$OUT/relay-$n.port")
    done
  else
    workers=$(IFS=,; echo "${addresses[*]}")
  fi
  run "d$delay" --workers "$workers" "${coordinator_tls[@]}" ||
    fail "$delay ms: $(tail -3 "$OUT/d$delay.err")"
  for f in events.jsonl trajectories.csv poses.csv tracks.csv; do
    cmp -s "$OUT/alone/$f" "$OUT/d$delay/$f" || fail "$delay ms: $f differs from one process's"
  done
  python3 - "$OUT/d$delay.json" "$delay" "$how" >>"$OUT/netns.csv" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
print("%s,%s,%d,%.3f,%.1f" % (sys.argv[2], sys.argv[3], r["ticks"], r["wall_seconds"],
                             r["ticks"] / r["wall_seconds"]))
PY
  for r in "${relays[@]}"; do kill "$r" 2>/dev/null; done
  [ "$how" = netem ] && for n in 1 2; do tc qdisc del dev "ag$tag-h$n" root 2>/dev/null; done
  echo "$delay ms each way ($how): the same outputs as one process; $(tail -1 "$OUT/netns.csv")"
done
cat "$OUT/netns.csv"

# A worker whose network goes silent (its veth pair down: no connection closes, nothing comes
# back): the coordinator's heartbeat finds it, and the run ends within 5 s, naming it.
"$ARGUS" run "$SOURCE/scenarios/penn_station_emulated.yaml" --seed 5 --no-feeds --no-progress \
  --set run.output_dir="$OUT/silent" --workers "$(IFS=,; echo "${addresses[*]}")" \
  "${coordinator_tls[@]}" >"$OUT/silent.txt" 2>&1 &
coordinator=$!
pids+=("$coordinator")
for _ in $(seq 300); do [ -s "$OUT/silent/events.jsonl.partial" ] && break; sleep 0.1; done
sleep 1
ip link set "ag$tag-h2" down
silent_at=$(date +%s.%N)
wait "$coordinator"
rc=$?
took=$(python3 -c "print(round($(date +%s.%N) - $silent_at, 2))")
[ $rc -eq 1 ] || fail "a silent worker: exit $rc, expected 1: $(tail -3 "$OUT/silent.txt")"
grep -q "worker ${addresses[1]} was lost during tick" "$OUT/silent.txt" ||
  fail "a silent worker: not named: $(tail -3 "$OUT/silent.txt")"
python3 -c "import sys; sys.exit(0 if $took < 5 else 1)" ||
  fail "a silent worker was found after $took s"
echo "a silent worker (its network down): found and named after $took s, exit 1"
