#!/usr/bin/env bash
# Regenerates docs/accuracy-cost.md and its figures (docs/figures/accuracy-cost/): the
# performance targets (bench_targets.py), the kernel microbenchmarks (apps/bench_kernels,
# Google Benchmark, if built), then the accuracy sweeps and the report (accuracy_cost.py all).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
bench="$here/utils/bench"
build=$here/build
runs=$here/out/accuracy-cost
report=
quick=()
check=()
args="$*"

usage() {
  cat <<EOF
Usage: utils/bench/accuracy-cost.sh [--quick] [--check] [--build DIR] [--runs DIR] [--report FILE]

Runs the performance targets, the kernel microbenchmarks and the accuracy sweeps, and writes
the report (default docs/accuracy-cost.md, its figures in docs/figures/accuracy-cost/).

  --quick        tiny meshes and short end times (about a minute on 2 cores): a pipeline
                 check; the report then goes to RUNS/accuracy-cost.md unless --report is given
  --check        exit non-zero unless every study has runs with finite errors and its plots
  --build DIR    the build directory with the apps (default: build)
  --runs DIR     where the runs and bench results go (default: out/accuracy-cost); finished
                 runs found there are reused: delete it for fresh numbers (from scratch
                 about 25 minutes on 2 cores)
  --report FILE  where the report goes
  --help         this text
EOF
}

while [[ $# -gt 0 ]]; do
  case $1 in
    --quick) quick=(--quick) ;;
    --check) check=(--check) ;;
    --build) build=$2; shift ;;
    --runs) runs=$2; shift ;;
    --report) report=$2; shift ;;
    -h|--help) usage; exit 0 ;;
    *) echo "accuracy-cost.sh: unknown option $1 (see --help)" >&2
       exit 2 ;;
  esac
  shift
done
if [[ -z $report ]]; then
  if [[ ${#quick[@]} -gt 0 ]]; then report=$runs/accuracy-cost.md; else report=$here/docs/accuracy-cost.md; fi
fi
mkdir -p "$runs"
start=$(date +%s)
# Like the sweeps' runs, the benches' results in RUNS are reused (delete RUNS for fresh numbers).
if [[ -f $runs/targets.json ]]; then
  echo "accuracy-cost.sh: reusing $runs/targets.json"
else
  /usr/bin/python3 "$bench/bench_targets.py" --build "$build" --out "$runs/bench" --json "$runs/targets.json" \
    "${quick[@]}"
fi
# Google Benchmark microbenchmarks of the kernels and operators (apps/bench_kernels), where built.
kernels=()
if [[ -x $build/apps/bench_kernels/bench_kernels ]]; then
  filter=.
  if [[ ${#quick[@]} -gt 0 ]]; then filter='Sums<FreeSpace|/1$'; fi
  if [[ ! -f $runs/bench_kernels.json ]]; then
    "$build/apps/bench_kernels/bench_kernels" --benchmark_min_time=0.2 --benchmark_filter="$filter" \
      --benchmark_out="$runs/bench_kernels.json.tmp" --benchmark_out_format=json
    mv "$runs/bench_kernels.json.tmp" "$runs/bench_kernels.json"
  fi
  kernels=(--kernels "$runs/bench_kernels.json")
fi
ACCURACY_COST_COMMAND="bash utils/bench/accuracy-cost.sh $args" /usr/bin/python3 "$bench/accuracy_cost.py" all \
  --build "$build" --runs "$runs" --report "$report" --targets "$runs/targets.json" "${kernels[@]}" \
  "${quick[@]}" "${check[@]}"
echo "== accuracy-cost.sh done in $(( $(date +%s) - start )) s"
