#!/usr/bin/env bash
# The thesis's Chapter 4 viscosity ratios as they come out of its printed equations.
# With the normal of eqs A.26-A.27 (left of increasing s) on the anticlockwise contour of
# Fig. 4.22 the double layer of eq A.35 changes sign, and lambda times the solution of that
# equation solves the correct one at 1/lambda (unit test
# InterfaceVelocity2D.ThesisInwardNormalTurnsLambdaIntoItsInverse). The thesis's lambda = L
# cell at its time tau = k t / L is then this code's lambda = 1/L cell at k t. This script
# runs that cell: the a/b = 1 study deck at lambda = 1/L with every time of the deck (tau,
# which this code also divides by lambda) multiplied by L, so that the preparation
# criterion, the end time and the outputs are the thesis's in k t, and prints the maxima
# next to lambda = 1 (docs/tether2d-results.md, "The thesis's lambda read as 1/lambda").
set -euo pipefail
STUDY=tether2d-thesis-lambda
APP=tether2d
ca=0.25
points=256
tau_end=100
thesis_lambdas="5 10"
compare=()

usage() {
  cat <<EOF
Usage: utils/studies/tether2d-thesis-lambda.sh [options]

Runs the a/b = 1 study deck at lambda = 1 and at the thesis's lambdas read as 1/lambda, writes
RUNS/thesis-lambda.txt (the maxima, times in k t) and draws RUNS/tether2d_thesis_lambda_ca<CA>.png.

  --ca CA          capillary number: the study deck ab1_lambda1_ca<CA>.xml (default $ca)
  --points N       points of the contour (default $points: the study's)
  --end KT         the tethered runs end at this k t (default $tau_end)
  --lambdas "L..." the thesis's lambdas (default "$thesis_lambdas")
  --compare DIR    a run of this code's own lambda > 1 (e.g. the study's ab1_lambda5_ca0.25)
                   to draw next to them (repeatable)
$(common_options_help)

Cost (256 points, Ca = 0.25, --end 100): 4-5 minutes a run on one core.
EOF
}

study_option() {
  case "$1" in
    --ca) ca="$2"; consumed=2 ;;
    --points) points="$2"; consumed=2 ;;
    --end) tau_end="$2"; consumed=2 ;;
    --lambdas) thesis_lambdas="$2"; consumed=2 ;;
    --compare) compare+=("$2"); consumed=2 ;;
  esac
}

source "$(dirname "${BASH_SOURCE[0]}")/study-lib.sh"
parse_options "$@"
[[ ${#positional[@]} -eq 0 ]] || die "unexpected argument '${positional[0]}' (see --help)"
deck="input/tether2d/study/ab1_lambda1_ca${ca}.xml"
[[ -f $here/$deck ]] || die "no study deck for Ca = $ca: $deck"

# queue_scaled NAME SCALE LAMBDA: the deck at viscosity ratio LAMBDA with its times multiplied
# by SCALE (the deck's defaults: preparation window 0.05, tolerance 1e-3 per tau, 0.5 to 50 tau
# of preparation, force transient 0.1, output every 0.5).
queue_scaled() {
  local name=$1 scale=$2 lambda=$3 window tolerance tmin tmax transient interval tend
  read -r window tolerance tmin tmax transient interval tend <<< "$(awk -v s="$scale" -v e="$tau_end" 'BEGIN {
    printf "%.12g %.12g %.12g %.12g %.12g %.12g %.12g", 0.05 * s, 1e-3 / s, 0.5 * s, 50 * s, 0.1 * s, 0.5 * s, e * s }')"
  queue_run "$name" "$deck" \
    --set "Flow/Viscosity ratio=$lambda" --set "Cell/Number of points=$points" \
    --set "Tether/Preparation window=$window" --set "Tether/Preparation tolerance=$tolerance" \
    --set "Tether/Minimum preparation time=$tmin" --set "Tether/Maximum preparation time=$tmax" \
    --set "Tether/Force transient=$transient" --set "Output/Interval=$interval" \
    --set "Time integration/End time=$tend"
}

run_dirs=("$runs/lambda1")
queue_scaled lambda1 1 1
for thesis in $thesis_lambdas; do
  queue_scaled "thesis_lambda$thesis" "$thesis" "$(awk -v l="$thesis" 'BEGIN { printf "%.12g", 1 / l }')"
  run_dirs+=("$runs/thesis_lambda$thesis")
done
echo "== $STUDY (Ca = $ca, $points points): runs in $runs, $jobs at a time"
run_queued
[[ $failed_runs -eq 0 ]] || die "$failed_runs run(s) failed (see $runs/<name>.log)"

"$python" "$plotting/tether2d_thesis_lambda.py" --out "$runs" --table "$runs/thesis-lambda.txt" \
  "${run_dirs[@]}" "${compare[@]}"
cat "$runs/thesis-lambda.txt"
