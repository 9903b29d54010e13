#!/usr/bin/env bash
# Runs the default demo deck with the apps built in BUILD (default: build): a Skalak capsule
# released near the wall in shear flow (input/cell3d/demo.xml), on 2 MPI ranks, about a
# minute on 2 cores. Outputs in out/cell3d-demo: metrics.csv, summary.json, snapshots.xdmf
# (open it in ParaView; the data are in snapshots.h5), checkpoint.h5.
set -euo pipefail
if [[ ${1:-} == -h || ${1:-} == --help ]]; then
  echo "Usage: bash utils/run-demo.sh [BUILD]"
  echo "Runs input/cell3d/demo.xml on 2 MPI ranks with the cell3d of BUILD (default build);"
  echo "outputs in out/cell3d-demo."
  exit 0
fi
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:-build}
[[ "$build" = /* ]] || build="$here/$build"
cd "$here"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
echo "== Demo: a capsule near the wall in shear flow (input/cell3d/demo.xml), 2 ranks"
mpiexec -n 2 --oversubscribe "$build/apps/cell3d/cell3d" input/cell3d/demo.xml --output out/cell3d-demo
