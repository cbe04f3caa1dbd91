#!/bin/bash
# One run across processes on loopback (docs/distributed.md): `argus worker` processes host the
# cameras and links of `argus run --workers`, over CAF's middleman.
#   distributed_loopback.sh ARGUS SOURCE_DIR OUT
# - replay_faults.yaml (pixels, every fault kind) with 1, 2 and 3 workers writes the same
#   events.jsonl, trajectories.csv, poses.csv, tracks.csv and metrics.json (less its wall time)
#   as one process, and with 2 workers the same --video (each worker renders its cameras'
#   tiles); the crowd's partitions step on the workers (five partitions on three workers too),
#   or on the coordinator when asked;
# - a worker killed mid-run: the coordinator ends within 5 s with exit 1, naming the worker and
#   the last whole tick, and every line of events.jsonl is whole;
# - the same under --on-worker-loss crash-nodes: exit 0, the run goes on to its end, the crowd
#   stays one process's (its lost partitions step on on the coordinator), the lost
#   worker's cameras are down (`worker_lost`) and the survivors notice;
# - a worker that never answers, or no worker at all, is reported by name;
# - a coordinator of another Argus version, in a process of its own, is refused naming the worker
#   and both versions, and the worker says whom it refused and why;
# - a worker asked to listen beyond loopback without TLS refuses.
set -u
ARGUS=$1
SOURCE=$2
OUT=$3
OTHER_VERSION=${4:-}  # tests/apps/other_version_coordinator, for the version refusal
rm -rf "$OUT"
mkdir -p "$OUT"
pids=()
cleanup() { for p in "${pids[@]}"; do kill -9 "$p" 2>/dev/null; done; }
trap cleanup EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

# Starts a worker on a port of the system's choosing; sets $port and $pid.
start_worker() {
  local log=$OUT/worker-$1.log
  "$ARGUS" worker --listen 127.0.0.1:0 --threads 1 >"$log" 2>&1 &
  pid=$!
  pids+=("$pid")
  for _ in $(seq 100); do
    port=$(sed -n 's/^argus worker: listening on 127.0.0.1:\([0-9]*\)$/\1/p' "$log")
    [ -n "$port" ] && return 0
    kill -0 "$pid" 2>/dev/null || fail "worker $1 exited: $(cat "$log")"
    sleep 0.1
  done
  fail "worker $1 did not listen within 10 s"
}

# The outputs a distributed run must share with one process.
same_outputs() {
  local a=$1 b=$2
  for f in events.jsonl trajectories.csv pedestrians.csv poses.csv tracks.csv targets.csv; do
    cmp -s "$a/$f" "$b/$f" || fail "$b/$f differs from $a/$f"
  done
  local strip='/"wall_seconds"\|"speed_ratio"/d'
  diff <(sed "$strip" "$a/metrics.json") <(sed "$strip" "$b/metrics.json") >/dev/null ||
    fail "$b/metrics.json differs from $a/metrics.json beyond the wall time"
}

run() { "$ARGUS" run "$SOURCE/scenarios/replay_faults.yaml" --seed 5 --duration "30 s" --no-feeds \
  --no-progress --set run.threads=2 "$@"; }

run --set run.output_dir="$OUT/alone" >"$OUT/alone.txt" 2>&1 || fail "the one-process run: $(tail -3 "$OUT/alone.txt")"
grep -q '"kind":"node_recovered"' "$OUT/alone/events.jsonl" || fail "no recovery in the reference run"
grep -q '"kind":"handoff"' "$OUT/alone/events.jsonl" || fail "no hand-over in the reference run"

ports=()
for i in 1 2 3; do start_worker "$i"; ports+=("127.0.0.1:$port"); done
list=""
for n in 1 2 3; do
  list=${list:+$list,}${ports[$((n - 1))]}
  run --set run.output_dir="$OUT/w$n" --workers "$list" >"$OUT/w$n.txt" 2>&1 ||
    fail "$n workers: $(tail -3 "$OUT/w$n.txt")"
  same_outputs "$OUT/alone" "$OUT/w$n"
  echo "$n workers: the same outputs as one process"
done
# The crowd stepped on the workers: replay_faults.yaml's two partitions on the first two.
for i in 1 2; do
  grep -q "stepping crowd partition $((i - 1)) " "$OUT/worker-$i.log" ||
    fail "worker $i did not step crowd partition $((i - 1)): $(cat "$OUT/worker-$i.log")"
done
# Five partitions on three workers (two, two and one): hand-overs between partitions of one
# worker and of two; then the crowd on the coordinator.
run --set run.output_dir="$OUT/five" --workers "$list" --set world.partitions=5 >"$OUT/five.txt" 2>&1 ||
  fail "five partitions: $(tail -3 "$OUT/five.txt")"
run --set run.output_dir="$OUT/five-alone" --set world.partitions=5 >"$OUT/five-alone.txt" 2>&1 ||
  fail "five partitions in one process: $(tail -3 "$OUT/five-alone.txt")"
same_outputs "$OUT/alone" "$OUT/five-alone"
same_outputs "$OUT/alone" "$OUT/five"
[ "$(grep -c "stepping crowd partition" "$OUT/worker-3.log")" = 1 ] ||
  fail "worker 3 did not step one of five partitions: $(cat "$OUT/worker-3.log")"
echo "3 workers stepping five crowd partitions: the same outputs as one process"
run --set run.output_dir="$OUT/crowd-here" --workers "$list" --set placement.crowd=coordinator \
  >"$OUT/crowd-here.txt" 2>&1 || fail "the crowd on the coordinator: $(tail -3 "$OUT/crowd-here.txt")"
same_outputs "$OUT/alone" "$OUT/crowd-here"
echo "3 workers, the crowd on the coordinator: the same outputs as one process"
# The same workers serve the next run: by id this time.
run --set run.output_dir="$OUT/by-id" --workers "$list" --set placement.policy=id >"$OUT/by-id.txt" 2>&1 ||
  fail "placement id: $(tail -3 "$OUT/by-id.txt")"
same_outputs "$OUT/alone" "$OUT/by-id"
echo "3 workers placed by id: the same outputs as one process"

# --video: each worker renders its cameras' tiles, the coordinator tiles them into the feeds.
video() { "$ARGUS" run "$SOURCE/scenarios/replay_faults.yaml" --seed 5 --duration "12 s" \
  --no-feeds --no-progress --set run.threads=2 --video --video-size 80x60 "$@"; }
video --set run.output_dir="$OUT/video-alone" >"$OUT/video-alone.txt" 2>&1 ||
  fail "the one-process video run: $(tail -3 "$OUT/video-alone.txt")"
video --set run.output_dir="$OUT/video-w2" --workers "${ports[0]},${ports[1]}" >"$OUT/video-w2.txt" 2>&1 ||
  fail "the video run with 2 workers: $(tail -3 "$OUT/video-w2.txt")"
cmp -s "$OUT/video-alone/video/feeds.avi" "$OUT/video-w2/video/feeds.avi" ||
  fail "2 workers recorded another video/feeds.avi"
for i in 1 2; do
  grep -q "rendering its cameras' video tiles (80x60 pixels" "$OUT/worker-$i.log" ||
    fail "worker $i did not render its cameras' video tiles: $(tail -3 "$OUT/worker-$i.log")"
done
echo "2 workers, --video: the same feeds.avi as one process"

# A worker killed mid-run.
"$ARGUS" run "$SOURCE/scenarios/penn_station_emulated.yaml" --seed 5 --no-feeds --no-progress \
  --set run.output_dir="$OUT/killed" --workers "${ports[0]},${ports[1]}" >"$OUT/killed.txt" 2>&1 &
coordinator=$!
pids+=("$coordinator")
for _ in $(seq 300); do
  [ -s "$OUT/killed/events.jsonl.partial" ] || [ -s "$OUT/killed/events.jsonl" ] && break
  sleep 0.1
done
sleep 1
victim=${pids[1]}
kill -9 "$victim"
killed_at=$(date +%s.%N)
wait "$coordinator"
rc=$?
ended_at=$(date +%s.%N)
[ $rc -eq 1 ] || fail "a lost worker: exit $rc, expected 1: $(tail -3 "$OUT/killed.txt")"
took=$(python3 -c "print(round($ended_at - $killed_at, 2))")
python3 -c "import sys; sys.exit(0 if $took < 5 else 1)" || fail "the coordinator took $took s to end after the kill"
grep -q "worker ${ports[1]} was lost during tick [0-9]*.*complete up to tick [0-9]*" "$OUT/killed.txt" ||
  fail "no message naming the lost worker: $(tail -3 "$OUT/killed.txt")"
last=$(sed -n 's/.*complete up to tick \([0-9]*\).*/\1/p' "$OUT/killed.txt" | tail -1)
events=$OUT/killed/events.jsonl
[ -f "$events" ] || fail "no events.jsonl after the loss"
python3 - "$events" "$last" <<'PY' || fail "events.jsonl after the loss is not whole"
import json, sys
ticks = [json.loads(line)["tick"] for line in open(sys.argv[1])]
assert ticks and max(ticks) <= int(sys.argv[2]), (max(ticks), sys.argv[2])
PY
for f in trajectories.csv pedestrians.csv; do
  [ -f "$OUT/killed/$f" ] || fail "no $f after the loss"
  [ -z "$(tail -c 1 "$OUT/killed/$f")" ] || fail "$f ends in half a line"
done
echo "a worker killed: exit 1 after $took s, outputs whole up to tick $last"

# A worker killed mid-run under --on-worker-loss crash-nodes: its cameras become crashed nodes
# and the run goes on to its end with the other worker.
start_worker 4
survivor_port=${ports[0]}
victim_port=127.0.0.1:$port
victim=$pid
"$ARGUS" run "$SOURCE/scenarios/penn_station_emulated.yaml" --seed 5 --duration "10 min" --no-feeds \
  --no-progress --set run.output_dir="$OUT/crashed" --workers "$survivor_port,$victim_port" \
  --on-worker-loss crash-nodes >"$OUT/crashed.txt" 2>&1 &
coordinator=$!
pids+=("$coordinator")
for _ in $(seq 300); do
  [ -s "$OUT/crashed/events.jsonl.partial" ] || [ -s "$OUT/crashed/events.jsonl" ] && break
  sleep 0.1
done
sleep 1
kill -9 "$victim"
wait "$coordinator"
rc=$?
[ $rc -eq 0 ] || fail "crash-nodes: exit $rc, expected 0: $(tail -3 "$OUT/crashed.txt")"
grep -q "worker $victim_port was lost during tick [0-9]*.*crash-nodes" "$OUT/crashed.txt" ||
  fail "crash-nodes: no message naming the lost worker: $(tail -3 "$OUT/crashed.txt")"
python3 - "$OUT/crashed" "$victim_port" <<'PY' || fail "crash-nodes: the run did not go on as it should"
import json, sys
out, victim = sys.argv[1], sys.argv[2]
events = [json.loads(line) for line in open(f"{out}/events.jsonl")]
summary = json.load(open(f"{out}/summary.json"))
json.load(open(f"{out}/metrics.json"))
assert summary["ticks"] == 9000, summary["ticks"]
lost = summary["lost_workers"]
assert len(lost) == 1 and lost[0].startswith(victim + " at tick "), lost
at = int(lost[0].rsplit(" ", 1)[1])
downs = [e for e in events if e["kind"] == "fault" and e["fault"] == "worker_lost"]
cameras = {e["camera"] for e in downs}
assert cameras and all(e["tick"] in (at, at + 1) for e in downs), downs
# The run went on after the loss, and the survivors noticed it through silence alone.
assert max(e["tick"] for e in events) > at + 15 * 60, "nothing happened after the loss"
noticed = [e for e in events if e["kind"] == "neighbour_lost" and e["tick"] > at
           and e["neighbour"] in cameras and e["camera"] not in cameras]
assert noticed, "no surviving camera noticed a lost one"
print(f"lost at tick {at}: cameras {sorted(cameras)} down, noticed by", sorted({e['camera'] for e in noticed}))
# Its crowd partitions (2 and 3 of 4) stepped on, on the coordinator, from their checkpoints.
adopted = [e for e in events if e["kind"] == "world_partition_adopted"]
assert sorted(e["partition"] for e in adopted) == [2, 3], adopted
assert all(e["worker"] == victim and 0 <= e["replayed_ticks"] < 15 for e in adopted), adopted
assert not [e for e in events if e["kind"] == "world_partitions_missing"]
PY
# The crowd does not look at the cameras: after the loss it is still one process's crowd.
"$ARGUS" run "$SOURCE/scenarios/penn_station_emulated.yaml" --seed 5 --duration "10 min" --no-feeds \
  --no-progress --set run.output_dir="$OUT/crashed-alone" >"$OUT/crashed-alone.txt" 2>&1 ||
  fail "the one-process run of the crash-nodes scenario: $(tail -3 "$OUT/crashed-alone.txt")"
for f in trajectories.csv pedestrians.csv; do
  cmp -s "$OUT/crashed-alone/$f" "$OUT/crashed/$f" || fail "crash-nodes: $f differs from one process's"
done
echo "a worker killed under crash-nodes: exit 0, the run went on to its end, the crowd one process's"

# A worker that accepts the connection and never answers, and a port with no worker.
python3 -c '
import socket, sys, time
s = socket.socket(); s.bind(("127.0.0.1", 0)); s.listen(4)
print(s.getsockname()[1], flush=True); time.sleep(60)' >"$OUT/mute.port" &
pids+=($!)
for _ in $(seq 50); do [ -s "$OUT/mute.port" ] && break; sleep 0.1; done
mute=127.0.0.1:$(cat "$OUT/mute.port")
start=$(date +%s)
run --set run.output_dir="$OUT/mute" --workers "$mute" >"$OUT/mute.txt" 2>&1
rc=$?
[ $rc -ne 0 ] || fail "a mute worker was accepted"
grep -q "worker $mute" "$OUT/mute.txt" || fail "the mute worker is not named: $(cat "$OUT/mute.txt")"
[ $(( $(date +%s) - start )) -le 30 ] || fail "the mute worker took over 30 s to report"
echo "a mute worker: $(grep -o "worker $mute.*" "$OUT/mute.txt" | head -1)"

"$ARGUS" worker --listen 0.0.0.0:0 >"$OUT/open.txt" 2>&1 && fail "a worker listened beyond loopback without TLS"
grep -q "TLS" "$OUT/open.txt" || fail "no reason given: $(cat "$OUT/open.txt")"
echo "beyond loopback without TLS: refused"

if [ -n "$OTHER_VERSION" ]; then
  "$OTHER_VERSION" "$survivor_port" 0.0.0-other >"$OUT/other.txt" 2>&1 ||
    fail "a coordinator of another version: exit $?: $(cat "$OUT/other.txt")"
  version=$("$ARGUS" --version | grep -o '[0-9][0-9.]*[^ ]*' | head -1)
  grep -q "worker $survivor_port runs Argus $version and the coordinator Argus 0.0.0-other" "$OUT/other.txt" ||
    fail "the refusal does not name the worker and both versions: $(cat "$OUT/other.txt")"
  grep -q "refused the coordinator on node .*runs Argus $version and the coordinator Argus 0.0.0-other" \
    "$OUT/worker-1.log" || fail "the worker did not say whom it refused: $(tail -3 "$OUT/worker-1.log")"
  echo "another version, across processes: $(cat "$OUT/other.txt")"
fi
