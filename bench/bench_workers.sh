# Sourced by the distributed benches: start_workers N starts N `argus worker` processes on
# loopback ports of the system's choosing, with their logs in $out/worker-I.log, adds their pids
# to `pids` (for the caller's trap) and their HOST:PORT to `workers`. Needs $argus and $out.
start_workers() {
  local i
  for i in $(seq "$1"); do
    "$argus" worker --listen 127.0.0.1:0 >"$out/worker-$i.log" 2>&1 &
    pids+=($!)
    for _ in $(seq 100); do grep -q "listening on" "$out/worker-$i.log" && break; sleep 0.1; done
    workers+=("$(sed -n 's/^argus worker: listening on //p' "$out/worker-$i.log")")
  done
}
