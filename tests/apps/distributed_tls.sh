#!/bin/bash
# A distributed run over TLS with mutual authentication (docs/distributed.md, "Security"), with
# certificates this test makes with openssl:
#   distributed_tls.sh ARGUS SOURCE_DIR OUT
# - a coordinator and a worker with certificates of the same CA run, and write what one process
#   writes;
# - refused, each with a message naming the worker and the reason: a coordinator certificate of
#   another CA, an expired one, a coordinator without TLS, and a TLS coordinator meeting a worker
#   without it; the worker logs each connection it refused, naming the peer and the reason;
# - beyond loopback only with TLS, for a worker's --listen and a coordinator's --workers;
# - no private key in any output.
set -u
ARGUS=$1
SOURCE=$2
OUT=$3
rm -rf "$OUT"
pids=()
cleanup() { for p in "${pids[@]}"; do kill -9 "$p" 2>/dev/null; done; }
trap cleanup EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

pki=$OUT/pki
"$(dirname "$0")/make_test_pki.sh" "$pki" || fail "cannot make the test certificates"
tls() { echo --tls-cert "$pki/$1.pem" --tls-key "$pki/$1.key" --tls-ca "$pki/ca-a.pem"; }

# --- workers --------------------------------------------------------------------------------
start_worker() {  # start_worker NAME LISTEN [TLS options]: sets $port
  local name=$1 listen=$2
  shift 2
  "$ARGUS" worker --listen "$listen" --threads 1 "$@" >"$OUT/worker-$name.log" 2>&1 &
  pids+=($!)
  for _ in $(seq 100); do
    port=$(sed -n 's/^argus worker: listening on .*:\([0-9]*\)$/\1/p' "$OUT/worker-$name.log")
    [ -n "$port" ] && return 0
    kill -0 "${pids[-1]}" 2>/dev/null || fail "worker $name exited: $(cat "$OUT/worker-$name.log")"
    sleep 0.1
  done
  fail "worker $name did not listen within 10 s"
}
# Beyond loopback with TLS: listens on every interface; reached here through loopback.
start_worker tls 0.0.0.0:0 $(tls worker)
secure=127.0.0.1:$port
start_worker plain 127.0.0.1:0
plain=127.0.0.1:$port

run() {  # run NAME [options]: replay_faults' first 20 s
  local name=$1
  shift
  "$ARGUS" run "$SOURCE/scenarios/replay_faults.yaml" --seed 5 --duration "20 s" --no-feeds \
    --no-progress --set run.threads=2 --set sensing.mode=emulated \
    --set run.output_dir="$OUT/$name" "$@" >"$OUT/$name.txt" 2>&1
}

run alone || fail "the one-process run: $(tail -3 "$OUT/alone.txt")"
run secure --workers "$secure" $(tls coordinator) || fail "over TLS: $(tail -3 "$OUT/secure.txt")"
for f in events.jsonl trajectories.csv poses.csv tracks.csv; do
  cmp -s "$OUT/alone/$f" "$OUT/secure/$f" || fail "over TLS: $f differs from one process's"
done
echo "over TLS with mutual authentication: the same outputs as one process"

refused() {  # refused NAME WORKER REASON [options]: the run fails naming WORKER and REASON
  local name=$1 worker=$2 reason=$3
  shift 3
  run "$name" --workers "$worker" "$@"
  local rc=$?
  [ $rc -ne 0 ] || fail "$name: accepted"
  grep -q "worker $worker" "$OUT/$name.txt" || fail "$name: the worker is not named: $(cat "$OUT/$name.txt")"
  grep -qi "$reason" "$OUT/$name.txt" || fail "$name: no '$reason' in: $(cat "$OUT/$name.txt")"
  echo "$name: $(grep -o "worker $worker.*" "$OUT/$name.txt" | head -1)"
}
refused other-ca "$secure" "refused this side's certificate.*unknown ca" $(tls stranger)
refused expired "$secure" "refused this side's certificate.*expired" $(tls expired)
refused plain-coordinator "$secure" "it speaks TLS"
refused plain-worker "$plain" "does not speak TLS" $(tls coordinator)
refused wrong-ca "$secure" "its certificate is refused: it is not signed by the CA" $(tls stranger | sed "s|ca-a.pem|ca-b.pem|")
grep -q "expired" "$OUT/expired.txt" || fail "no warning of the expired certificate"
# The worker says so too, naming the coordinator's address and the reason.
wlog=$OUT/worker-tls.log
grep -q "refused a TLS connection from 127.0.0.1:[0-9]*: its certificate is refused: unable to get local issuer certificate" "$wlog" ||
  fail "the worker did not log the other CA's certificate: $(grep refused "$wlog")"
grep -q "refused a TLS connection from 127.0.0.1:[0-9]*: its certificate is refused: certificate has expired" "$wlog" ||
  fail "the worker did not log the expired certificate: $(grep refused "$wlog")"
grep -q "refused a TLS connection from 127.0.0.1:[0-9]*: it does not speak TLS" "$wlog" ||
  fail "the worker did not log the coordinator without TLS: $(grep refused "$wlog")"
grep -q "refused a TLS connection from 127.0.0.1:[0-9]*: it refused the handshake (OpenSSL: .*unknown ca)" "$wlog" ||
  fail "the worker did not log the coordinator that refused its certificate: $(grep refused "$wlog")"
echo "the worker logged each refused connection: $(grep -o "refused a TLS connection.*" "$wlog" | sort -u | sed 's/from 127.0.0.1:[0-9]*/from 127.0.0.1:PORT/' | sort -u | tr '\n' ';')"
grep -q "not signed by --tls-ca" "$OUT/other-ca.txt" || fail "no warning of the stranger's certificate"

"$ARGUS" worker --listen 0.0.0.0:0 >"$OUT/open.txt" 2>&1 && fail "a worker listened beyond loopback without TLS"
grep -q "TLS" "$OUT/open.txt" || fail "no reason: $(cat "$OUT/open.txt")"
run far --workers 192.0.2.1:7001
[ $? -eq 2 ] || fail "a worker beyond loopback without TLS: not refused as bad input"
grep -q "beyond loopback.*TLS" "$OUT/far.txt" || fail "no reason: $(cat "$OUT/far.txt")"
echo "beyond loopback without TLS: refused for --listen and --workers"

if grep -l "PRIVATE KEY\|$(sed -n 2p "$pki/coordinator.key")\|$(sed -n 2p "$pki/worker.key")" \
     "$OUT"/*.txt "$OUT"/*.log; then
  fail "a private key was printed"
fi
echo "no private key in any output"
