#!/usr/bin/env bash
# Installs the Debian 12 packages wash needs to build, test and render pictures.
# Idempotent: packages already present are skipped, so the test command can call it every time.
set -euo pipefail

LLVM=19
packages=(
  build-essential cmake ninja-build git python3
  # LLVM/Clang 19: find_package(Clang) fails unless every file its export sets name exists.
  clang-$LLVM clang-tools-$LLVM clang-tidy-$LLVM clang-format-$LLVM clangd-$LLVM
  libclang-$LLVM-dev libclang-cpp$LLVM-dev llvm-$LLVM-dev llvm-$LLVM-tools llvm-$LLVM-linker-tools
  libpolly-$LLVM-dev
  libgtest-dev libopenmpi-dev openmpi-bin
  python3-numpy python3-scipy python3-matplotlib
  # VTK's own reader for the VTK output tests (test/e2e/vtk_output.sh) and scripts/render_frame.py.
  python3-vtk9
  # --format hdf5: serial HDF5 (reference, serial, openmp), parallel HDF5 over
  # Open MPI (mpi backend), and h5py for the HDF5 tests and scripts/wash_read.py.
  libhdf5-dev libhdf5-openmpi-dev python3-h5py
  # ip netns / veth for the two-host MPI test (test/e2e/two_hosts.sh).
  iproute2
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO=sudo
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: done"
