#!/usr/bin/env bash
# Runs the default demo deck with the apps built in BUILD (default: build).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:-build}
[[ "$build" = /* ]] || build="$here/$build"
cd "$here"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
echo "== Demo: the resting red blood cell's surface mesh and geometry (input/cellshape/red_cell.xml)"
"$build/apps/cellshape/cellshape" input/cellshape/red_cell.xml --output out/demo
