#!/usr/bin/env bash
# Sourced by demo.sh and test.sh: installs whatever Debian 12 packages are missing, and
# provides `argus_build DIR [cmake options...]` (configure once, then incremental builds).
set -euo pipefail

ARGUS_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

argus_packages=(
  build-essential cmake ninja-build ccache pkg-config git
  libcaf-dev libeigen3-dev libopencv-dev libmimalloc-dev libpcg-cpp-dev
  libxxhash-dev  # the field cache's checksum (world/field_cache.cpp)
  libjpeg-dev  # libjpeg-turbo: the imaging model's JPEG (vision/jpeg_codec.cpp)
  libssl-dev openssl iproute2  # TLS between processes; the tests' certificates and namespaces
  libegl-dev libgles-dev libegl-mesa0 libgl1-mesa-dri
  libyaml-cpp-dev libcli11-dev libspdlog-dev libfmt-dev nlohmann-json3-dev
  libgtest-dev libgmock-dev libbenchmark-dev clang-format
  clang-14 libclang-rt-14-dev  # the fuzz harnesses (tests/fuzz): libFuzzer and its sanitizers
  chromium  # the report test loads report.html in headless Chromium
  libcpp-httplib-dev  # argus serve's HTTP server (Server-Sent Events for the live stream)
  chromium-driver python3-selenium  # the live console's end-to-end test drives the page
  pybind11-dev python3-pybind11 python3-dev python3-numpy  # the Python module argus
)

argus_install_missing() {
  local missing=()
  for p in "${argus_packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "argus: installing missing packages: ${missing[*]}" >&2
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -q
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
}

# ccache keys on the compile command, whose include paths are absolute: relative to the checkout
# (and without the build folder in debug builds' keys) a clean clone in another folder, as CI's
# is, reuses the objects of a build made here instead of compiling everything again.
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$ARGUS_ROOT}"
export CCACHE_NOHASHDIR="${CCACHE_NOHASHDIR:-1}"

# argus_build DIR [--target T] [cmake options...]: configures DIR, then builds incrementally
# (everything, or target T and what it needs).
argus_build() {
  local dir="$1"
  shift
  local target=()
  if [ "${1:-}" = "--target" ]; then
    target=(--target "$2")
    shift 2
  fi
  # Configured every time (a few seconds), so that a tree made before an option was added to
  # the scripts (-DARGUS_UNITY=ON, say) takes it.
  mkdir -p "$dir"
  cmake -S "$ARGUS_ROOT" -B "$dir" -G Ninja -DCMAKE_CXX_COMPILER_LAUNCHER=ccache "$@" > "$dir/configure.log" 2>&1 ||
    { cat "$dir/configure.log" >&2; return 1; }
  cmake --build "$dir" --parallel "$(nproc)" "${target[@]}" && return 0
  # A compile once failed in CI with no diagnostic at all (a killed compiler or a full disk
  # leaves none); the state of the machine is printed, and the build is tried once more
  # without ccache: an error in the code fails again, with its message.
  echo "argus: the build in $dir failed; free disk and memory now:" >&2
  df -h "$dir" >&2 || true
  free -m >&2 || true
  echo "argus: building $dir once more, without ccache" >&2
  CCACHE_DISABLE=1 cmake --build "$dir" --parallel "$(nproc)" "${target[@]}"
}

argus_install_missing
