#!/usr/bin/env bash
# Times what a newcomer meets on a bare Debian 12 machine: a fresh root made by debootstrap
# (minbase: no compiler, no git, no libraries), entered with chroot, with a clean clone of this
# checkout's HEAD inside. In it:
#   1. scripts/demo.sh: packages installed, then `argus` built and the demo run, from an empty
#      compiler cache;
#   2. scripts/test.sh on a second clean clone, with the packages installed and the compiler
#      cache emptied again: Release, ASan+UBSan and TSan from nothing, as CI meets them.
# Each step's log and a summary (summary.json, summary.txt: times, stage lines, the machine)
# go into OUT. Needs root (debootstrap, chroot, mounts) and Debian's network mirror.
#   scripts/bare_machine_check.sh [--root DIR] [--out DIR] [--demo-only | --tests-only]
#                                 [--new-root]
#     --root DIR    the Debian root (default /var/tmp/argus-bare/root); made if missing
#     --new-root    remove DIR first, so that no package of an earlier check is left in it
#     --out DIR     logs and summary (default out/bare_machine_check)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
root=/var/tmp/argus-bare/root
out="$here/out/bare_machine_check"
do_demo=1 do_tests=1 new_root=0
while [ $# -gt 0 ]; do
  case "$1" in
    --root) root="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --demo-only) do_tests=0; shift ;;
    --tests-only) do_demo=0; shift ;;
    --new-root) new_root=1; shift ;;
    *) echo "bare_machine_check: unknown option '$1' (see the comment at the top of $0)" >&2; exit 2 ;;
  esac
done
[ "$(id -u)" -eq 0 ] || { echo "bare_machine_check: needs root (debootstrap, chroot, mount)" >&2; exit 2; }
for tool in debootstrap chroot mount git; do
  command -v "$tool" >/dev/null || { echo "bare_machine_check: '$tool' is missing (apt-get install debootstrap git)" >&2; exit 2; }
done
mkdir -p "$out"
out="$(cd "$out" && pwd)"
summary="$out/summary.txt"
: > "$summary"
note() { echo "$*" | tee -a "$summary"; }

mounted=()
unmount_all() {
  local i
  for ((i = ${#mounted[@]} - 1; i >= 0; i--)); do umount -l "${mounted[$i]}" 2>/dev/null || true; done
  mounted=()
}
trap unmount_all EXIT

if [ "$new_root" -eq 1 ] && [ -d "$root" ]; then
  # A root left mounted by a killed check would take the host's /dev with it.
  if grep -q " $root/" /proc/mounts; then
    echo "bare_machine_check: $root still has mounts; unmount them first" >&2; exit 1
  fi
  rm -rf "$root"
fi
if [ ! -x "$root/bin/bash" ]; then
  mkdir -p "$(dirname "$root")"
  s=$SECONDS
  debootstrap --variant=minbase bookworm "$root" http://deb.debian.org/debian > "$out/debootstrap.log" 2>&1 ||
    { echo "bare_machine_check: debootstrap failed; see $out/debootstrap.log" >&2; exit 1; }
  note "debootstrap (minbase bookworm): $((SECONDS - s)) s"
fi
# The host's apt sources (bookworm, -updates and -security: Chromium comes from -security) and
# name resolution; nothing else of the host's goes in.
rm -f "$root"/etc/apt/sources.list "$root"/etc/apt/sources.list.d/*
for f in /etc/apt/sources.list.d/*.sources; do
  [ -f "$f" ] && grep -q 'debian' "$f" && cp "$f" "$root/etc/apt/sources.list.d/"
done
[ -f /etc/apt/sources.list ] && cp /etc/apt/sources.list "$root/etc/apt/"
cp -L /etc/resolv.conf "$root/etc/resolv.conf"
# debootstrap writes no /etc/hosts, which every installed Debian has: without it "localhost"
# does not resolve, and Selenium cannot reach chromedriver (the live console's browser test).
if [ ! -f "$root/etc/hosts" ]; then
  printf '127.0.0.1\tlocalhost\n::1\t\tlocalhost ip6-localhost ip6-loopback\n' > "$root/etc/hosts"
fi
for m in proc sys dev dev/pts dev/shm; do
  mkdir -p "$root/$m"
  case "$m" in
    proc) mount -t proc proc "$root/proc" ;;
    sys) mount -t sysfs sys "$root/sys" ;;
    *) mount --bind "/$m" "$root/$m" ;;
  esac
  mounted+=("$root/$m")
done

# The clone is of HEAD: what is committed, not the working tree.
commit="$(git -C "$here" rev-parse HEAD)"
fresh_clone() {  # fresh_clone NAME: a clean clone at /src/NAME inside the root
  rm -rf "$root/src/$1"
  mkdir -p "$root/src"
  git clone -q --no-local "$here" "$root/src/$1"
  git -C "$root/src/$1" checkout -q "$commit"
}
in_root() {  # in_root LOG COMMAND: runs COMMAND as root in a login-like clean environment
  local log="$1"
  shift
  chroot "$root" /usr/bin/env -i HOME=/root TERM=dumb LANG=C.UTF-8 \
    PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
    /bin/bash -c "$*" > "$log" 2>&1
}
empty_ccache() { rm -rf "$root/root/.cache/ccache" "$root/root/.ccache"; }

cpu="$(lscpu | sed -n 's/^Model name: *//p' | head -1)"
note "machine: $cpu, $(nproc) cores, $(free -g | awk '/^Mem/ {print $2}') GiB memory; commit $commit"
run_s=0 run_rc=0
timed() {  # timed LOG COMMAND: runs COMMAND in the root; sets run_s and run_rc
  local s=$SECONDS
  set +e
  in_root "$@"
  run_rc=$?
  set -e
  run_s=$((SECONDS - s))
}
demo_s=null demo_rc=null tests_s=null tests_rc=null packages_s=null
if [ "$do_demo" -eq 1 ]; then
  fresh_clone demo
  empty_ccache
  timed "$out/demo.log" "cd /src/demo && scripts/demo.sh"
  demo_s=$run_s demo_rc=$run_rc
  note "demo.sh: exit $demo_rc after $demo_s s, packages included; its stages:"
  grep -E '^== ' "$out/demo.log" | tee -a "$summary" || true
  grep -E 'report.html|plan.png|contact_sheet.png' "$out/demo.log" | tail -3 | tee -a "$summary" || true
fi
if [ "$do_tests" -eq 1 ]; then
  fresh_clone tests
  empty_ccache
  # Packages first (a no-op after the demo), so that test.sh's own time starts installed.
  timed "$out/packages.log" "cd /src/tests && source scripts/setup.sh"
  packages_s=$run_s
  note "packages: exit $run_rc after $packages_s s"
  timed "$out/test.log" "cd /src/tests && scripts/test.sh"
  tests_s=$run_s tests_rc=$run_rc
  note "test.sh: exit $tests_rc after $tests_s s; its stages:"
  grep -E '^== ' "$out/test.log" | tee -a "$summary" || true
fi
cat > "$out/summary.json" <<EOF
{"commit": "$commit", "cpu": "$cpu", "cores": $(nproc),
 "memory_gib": $(free -g | awk '/^Mem/ {print $2}'),
 "demo_seconds": $demo_s, "demo_exit": $demo_rc, "packages_seconds": $packages_s,
 "test_seconds": $tests_s, "test_exit": $tests_rc}
EOF
note "logs and summary in $out"
[ "$demo_rc" != "null" ] && [ "$demo_rc" -ne 0 ] && exit 1
[ "$tests_rc" != "null" ] && [ "$tests_rc" -ne 0 ] && exit 1
exit 0
