#!/usr/bin/env bash
# Builds CAF's core library from Debian's own source package with ThreadSanitizer, into
# PREFIX (default build-tsan/caf), once; later calls find it there and return at once.
#
# Why: Debian's libcaf_core is not instrumented, so TSan cannot see the synchronisation in
# CAF's mailboxes and reports every message handed between threads as a race. A TSan build
# of the same CAF version (0.17.6, the one libcaf-dev installs) makes the reports real.
#   scripts/tsan_caf.sh [PREFIX]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
prefix="${1:-$root/build-tsan/caf}"
[ -f "$prefix/lib/libcaf_core.so" ] && exit 0

version="$(dpkg-query -W -f='${Version}' libcaf-dev)"   # e.g. 0.17.6-2.1+b1
upstream="${version%%-*}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
echo "argus: building CAF $upstream core with TSan into $prefix (once)" >&2

# Debian's source index, taken from the machine's own apt sources (deb -> deb-src), in a
# private apt state so the system's configuration is left as it is.
mkdir -p "$work/sources" "$work/lists/partial" "$work/cache/archives/partial"
for f in /etc/apt/sources.list.d/*.sources; do
  [ -f "$f" ] && sed 's/^Types: *deb$/Types: deb-src/' "$f" > "$work/sources/$(basename "$f")"
done
if [ -f /etc/apt/sources.list ]; then
  sed -n 's/^deb \(.*\)/deb-src \1/p' /etc/apt/sources.list > "$work/sources/list.list"
fi
apt_opts=(-o "Dir::Etc::SourceList=/dev/null" -o "Dir::Etc::SourceParts=$work/sources"
          -o "Dir::State::Lists=$work/lists" -o "Dir::Cache=$work/cache"
          -o "APT::Sandbox::User=root" -o "Debug::NoLocking=1")
tarball="$work/actor-framework_${upstream}.orig.tar.gz"
# Only the upstream tarball is needed; apt verifies it against the signed source index, and a
# missing Debian diff (the mirror has answered 404 for it) is no loss. A mirror or proxy that
# fails once is tried again: a CI run was lost to one fetch.
for attempt in 1 2 3 4; do
  if timeout 300 apt-get "${apt_opts[@]}" -q update >&2; then
    (cd "$work" && timeout 300 apt-get "${apt_opts[@]}" -q source --download-only \
      "actor-framework=${version%+b*}" >&2) || true
  fi
  [ -f "$tarball" ] && break
  echo "argus: fetching Debian's actor-framework $upstream source failed (attempt $attempt of 4)" >&2
  [ "$attempt" -lt 4 ] && sleep $((attempt * 20))
done
if [ ! -f "$tarball" ]; then
  echo "argus: could not fetch Debian's actor-framework $upstream source (needed for the TSan build)" >&2
  exit 1
fi
tar -xzf "$tarball" -C "$work"
# The source lies in a new temporary folder each time: ccache's keys relative to it let a
# second machine-local build (CI's clone after a developer's) reuse the first one's objects.
export CCACHE_BASEDIR="$work" CCACHE_NOHASHDIR=1
cmake -S "$work/actor-framework-$upstream" -B "$work/build" -G Ninja \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" \
  -DCMAKE_INSTALL_PREFIX="$prefix" \
  -DCMAKE_CXX_FLAGS="-fsanitize=thread" -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=thread" \
  $(command -v ccache >/dev/null && echo -DCMAKE_CXX_COMPILER_LAUNCHER=ccache) \
  -DCAF_NO_EXAMPLES=yes -DCAF_NO_UNIT_TESTS=yes -DCAF_NO_TOOLS=yes -DCAF_NO_IO=yes \
  -DCMAKE_UNITY_BUILD=ON -DCAF_NO_OPENSSL=yes -DCAF_NO_PYTHON=yes -DCAF_NO_OPENCL=yes -DCAF_NO_SUMMARY=yes >&2
cmake --build "$work/build" --parallel "$(nproc)" >&2
cmake --install "$work/build" >&2
