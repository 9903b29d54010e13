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
# next to lambda = 1 (docs/tether2d.md, "Dependence on the viscosity ratio").
# Usage: utils/tether2d-thesis-lambda.sh BUILD_DIR OUT_DIR [CA] [POINTS] [THESIS_TAU_END]
#   CA (default 0.25), POINTS (default 256: the study's), THESIS_TAU_END (default 100): the
#   tethered runs end at this k t. Environment: THESIS_LAMBDAS (default "5 10");
#   CORRECT_RUNS: this code's own lambda > 1 run directories (e.g. the study's
#   ab1_lambda5_ca0.25) to draw next to them.
# Results: OUT_DIR/thesis-lambda.txt and OUT_DIR/tether2d_thesis_lambda_ca<CA>.png. Cost (256 points, Ca = 0.25, THESIS_TAU_END = 100):
# 4-5 minutes a run on one core.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:?build directory}
out=${2:?output directory}
ca=${3:-0.25}
points=${4:-256}
tauEnd=${5:-100}
app="$build/apps/tether2d/tether2d"
deck="$here/input/tether2d/study/ab1_lambda1_ca${ca}.xml"
[[ -f $deck ]] || { echo "no study deck for Ca = $ca: $deck" >&2; exit 2; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mkdir -p "$out"

# run NAME SCALE LAMBDA: the deck at viscosity ratio LAMBDA with its times multiplied by SCALE
# (the deck's defaults: preparation window 0.05, tolerance 1e-3 per tau, 0.5 to 50 tau of
# preparation, force transient 0.1, output every 0.5).
run() {
  local name=$1 scale=$2 lambda=$3
  local times
  times=$(awk -v s="$scale" -v e="$tauEnd" 'BEGIN { printf "%.12g %.12g %.12g %.12g %.12g %.12g %.12g",
    0.05 * s, 1e-3 / s, 0.5 * s, 50 * s, 0.1 * s, 0.5 * s, e * s }')
  read -r window tolerance tmin tmax transient interval tend <<< "$times"
  echo "running $name (lambda = $lambda, times x $scale)" >&2
  "$app" "$deck" --output "$out/$name" \
    --set "Flow/Viscosity ratio=$lambda" --set "Cell/Number of points=$points" \
    --set "Tether/Preparation window=$window" --set "Tether/Preparation tolerance=$tolerance" \
    --set "Tether/Minimum preparation time=$tmin" --set "Tether/Maximum preparation time=$tmax" \
    --set "Tether/Force transient=$transient" --set "Output/Interval=$interval" \
    --set "Time integration/End time=$tend" > "$out/$name.log" 2>&1
}

names=()
run lambda1 1 1
names+=("lambda1:1:1")
for thesis in ${THESIS_LAMBDAS:-5 10}; do
  inverse=$(awk -v l="$thesis" 'BEGIN { printf "%.12g", 1 / l }')
  run "thesis_lambda$thesis" "$thesis" "$inverse"
  names+=("thesis_lambda$thesis:$thesis:$inverse")
done

/usr/bin/python3 - "$out" "$ca" "$points" "${names[@]}" > "$out/thesis-lambda.txt" <<'EOF'
import json, sys
out, ca, points = sys.argv[1:4]
print(f"a/b = 1, Ca = {ca}, {points} points; times in k t (the thesis's tau for its lambda)")
print("| thesis lambda | lambda run here | tethered at k t | F_max | k t of F_max after tethering "
      "| A_max/A0 | L_cell max | max area drift |")
print("|---|---|---|---|---|---|---|---|")
for entry in sys.argv[4:]:
    name, thesis, inverse = entry.split(":")
    s = json.load(open(f"{out}/{name}/summary.json"))
    lam = float(inverse)
    tether = s["preparation time"] * lam          # tau = k t / lambda in this code
    peak = s["max"]["time_of_max_tether_force"] * lam
    print(f"| {thesis} | {inverse} | {tether:.3f} | {s['max']['tether_force']:.4f} | {peak - tether:.2f} "
          f"| {s['max']['contour_length_ratio']:.4f} | {s['max']['cell_length']:.4f} "
          f"| {100 * s['max']['abs_area_drift']:.3f}% |")
EOF
cat "$out/thesis-lambda.txt"
# shellcheck disable=SC2086 # CORRECT_RUNS is a list of directories
/usr/bin/python3 "$here/utils/plotting/tether2d_thesis_lambda.py" --out "$out" \
  "$out/lambda1" "$out"/thesis_lambda* ${CORRECT_RUNS:-}
