#!/usr/bin/env bash
# One-command set-up from a clean clone on Debian 12:
#   utils/setup.sh demo   install what is missing, build, run the default demo deck
#   utils/setup.sh test   install what is missing, build, run the whole test suite
# Options (environment): BUILD_DIR (default build), JOBS (default: number of cores).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$here"
mode=${1:-}
build=${BUILD_DIR:-build}
jobs=${JOBS:-$(nproc)}

case "$mode" in
  demo|test) ;;
  -h|--help)
    echo "Usage: bash utils/setup.sh demo|test"
    echo "  demo  install what is missing, build, run the default demo deck"
    echo "  test  install what is missing, build, run the whole test suite"
    echo "Environment: BUILD_DIR (default build), JOBS (default: number of cores)."
    exit 0 ;;
  *) echo "usage: utils/setup.sh demo|test (see --help)" >&2; exit 2 ;;
esac

bash utils/install-deps.sh
# Ninja for a new build folder (it keeps both cores busy; docs/developer-guide.md, "Build
# time"); a folder configured before keeps its generator.
generator=()
[[ -f "$build/CMakeCache.txt" ]] || generator=(-G Ninja)
cmake -S . -B "$build" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release
cmake --build "$build" -j "$jobs"

# Open MPI refuses root without these; harmless otherwise.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
if [[ "$mode" == demo ]]; then
  bash utils/run-demo.sh "$build"
else
  cd "$build"
  ctest --output-on-failure -j "$jobs"
fi
