#!/usr/bin/env bash
# Installs the Debian 12 packages Capsula needs, only those that are missing.
# Idempotent and quiet when everything is present; exits non-zero with a clear
# message if an install fails. Uses sudo when not run as root.
set -euo pipefail
if [[ ${1:-} == -h || ${1:-} == --help ]]; then
  echo "Usage: bash utils/install-deps.sh"
  echo "Installs the Debian 12 packages Capsula needs that are missing (with sudo unless root)."
  exit 0
fi

packages=(
  # build tools
  build-essential cmake ninja-build git pkg-config clang-format
  # Trilinos 13.2 is split in Debian; its CMake config needs all of these
  libtrilinos-teuchos-dev libtrilinos-kokkos-dev libtrilinos-kokkos-kernels-dev
  libtrilinos-epetra-dev libtrilinos-epetraext-dev libtrilinos-tpetra-dev
  libtrilinos-belos-dev libtrilinos-aztecoo-dev libtrilinos-rtop-dev
  libtrilinos-thyra-dev libtrilinos-triutils-dev libtrilinos-xpetra-dev
  # MPI, parallel HDF5, geometry, tests, benchmarks
  libopenmpi-dev openmpi-bin libhdf5-openmpi-dev
  libcgal-dev libeigen3-dev libboost-dev
  libgtest-dev libbenchmark-dev
  # FFTs of the spectral Ewald sums (packages/ewald)
  libfftw3-dev
  # plotting and output checks (Debian's python3, not a pyenv one)
  python3 python3-numpy python3-matplotlib python3-h5py
  # ParaView, the viewer of the snapshots: the test figures_demo_snapshots_open_in_both_paraview_readers
  # reads them with its two XDMF readers (pvpython)
  paraview python3-paraview
)

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done
[[ ${#missing[@]} -eq 0 ]] && exit 0

echo "capsula: installing ${#missing[@]} missing Debian package(s): ${missing[*]}"
if [[ $(id -u) -eq 0 ]]; then
  sudo_cmd=()
elif command -v sudo >/dev/null 2>&1; then
  sudo_cmd=(sudo)
else
  echo "capsula: error: packages are missing and this user is not root and has no sudo." >&2
  echo "capsula: ask an administrator to run: apt-get install ${missing[*]}" >&2
  exit 1
fi

export DEBIAN_FRONTEND=noninteractive
if ! "${sudo_cmd[@]}" apt-get update -qq >/tmp/capsula-apt.log 2>&1; then
  echo "capsula: error: 'apt-get update' failed; see /tmp/capsula-apt.log" >&2
  exit 1
fi
if ! "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >>/tmp/capsula-apt.log 2>&1; then
  echo "capsula: error: installing ${missing[*]} failed; see /tmp/capsula-apt.log" >&2
  exit 1
fi
echo "capsula: packages installed."
