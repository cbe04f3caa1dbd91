#!/usr/bin/env bash
# Installs what is missing, then builds and runs the whole test suite three ways:
#   Release; ASan+UBSan (everything); TSan (the actor layer, label "actors").
#   scripts/test.sh            all three
#   scripts/test.sh --quick    Release only
# Any failing test or sanitizer report fails the script.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
cd "$ARGUS_ROOT"
quick=0
[ "${1:-}" = "--quick" ] && quick=1
jobs="$(nproc)"
stage_time() { echo "$((SECONDS / 60)) min $((SECONDS % 60)) s in"; }

echo "== free on this disk: $(df -h --output=avail . | tail -1 | tr -d ' '); memory: $(free -g | awk '/^Mem/ {print $7}') GiB available"
echo "== Release build and tests ($(stage_time))"
argus_build build -DCMAKE_BUILD_TYPE=Release
ctest --test-dir build --output-on-failure -j "$jobs"
[ "$quick" -eq 1 ] && exit 0

export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:halt_on_error=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
echo "== ASan+UBSan build and tests ($(stage_time))"
# -O1 -g1 (ASan's own advice, and line tables suffice for its stack traces): at -O2 -g the
# sanitizer build took half of CI's 90 minutes; a CAF-heavy file now compiles 2.6x faster.
argus_build build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DARGUS_SANITIZE=address,undefined \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DARGUS_BUILD_BENCH=OFF
# A test that fails is run once more under ASan: LeakSanitizer's exit-time tracer can crash
# itself ("Tracer caught signal 11 ... LeakSanitizer has encountered a fatal error"); a real
# failure fails twice. (Its frequent cause here, a stale entry of the OpenGL driver's dynamic
# TLS in a main thread that had rendered, is gone: report/feed_frames.cpp.)
ctest --test-dir build-asan --output-on-failure -j "$jobs" --repeat until-pass:2

export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:suppressions=$ARGUS_ROOT/tests/tsan.supp"
echo "== TSan build and actor-layer tests, against a TSan build of CAF ($(stage_time))"
scripts/tsan_caf.sh "$ARGUS_ROOT/build-tsan/caf"
# Only what the actor-layer tests need is built, with line tables rather than full debug info.
argus_build build-tsan --target actor_tests -DCMAKE_BUILD_TYPE=RelWithDebInfo -DARGUS_SANITIZE=thread \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" -DARGUS_BUILD_BENCH=OFF \
  -DCMAKE_PREFIX_PATH="$ARGUS_ROOT/build-tsan/caf"
ctest --test-dir build-tsan --output-on-failure -j "$jobs" -L actors
echo "== all tests passed ($(stage_time))"
