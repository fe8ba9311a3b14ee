#!/usr/bin/env bash
# Installs every Debian (bookworm) package mrpt_fog needs to build, test and run.
# Idempotent and fast when everything is already installed (no apt-get call at all then).
set -euo pipefail

PACKAGES=(
  build-essential cmake ninja-build pkg-config git
  ccache               # compiler cache: CI and test builds reuse unchanged objects
  libmrpt-dev          # MRPT 2.5: obs, io, serialization, poses, containers (yaml), TCLAP
  mrpt-apps            # rawlog-edit, pf-localization: MRPT's own tools, used by the tests
  libeigen3-dev        # Eigen 3.4
  libopencv-dev        # OpenCV 4.6: PNG plots
  libgtest-dev         # GoogleTest
  libbenchmark-dev     # Google Benchmark (bench/)
  python3 python3-numpy  # NumPy peer for the fit benchmark
  xxd                  # test helpers that patch binary files
  clang libclang-rt-14-dev  # libFuzzer targets (scripts/run-fuzz.sh, CI hardening step)
)

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#PACKAGES[@]} packages already installed"
  exit 0
fi

echo "setup: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
echo "setup: done"
