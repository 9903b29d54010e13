#!/usr/bin/env bash
# The 2D convergence studies of thesis Section 3.12.1 with apps/tether2d:
#   mesh:        maximum tether force for N = 64 .. 320 points (a/b = 1, Ca = 0.25, lambda = 1)
#                and the fit F_max = F_inf + C N^alpha (thesis Fig. 3.6: alpha = -1.45, 3.4%
#                spread from 64 to 320 elements);
#   quadrature:  maximum tether force for N_GL = 5, 6, 8, 12 (thesis Table 3.2: 3.2525, 3.2469,
#                3.2474, 3.2475), with and without the near-singular subdivision.
# Usage: utils/tether2d-convergence.sh BUILD_DIR OUT_DIR [mesh|quadrature|all] [QUADRATURE_N] [GAP] [TETHER_TAU]
#   GAP (default or empty: the deck's 0.005): the initial lowest-point height and the anchor
#   height; 0.1 resolves the film between the cell and the wall at N >= 128, but without
#   Cell/Prestress (TETHER2D_SET) the free cell wrinkles from N = 512 on (docs/tether2d.md).
#   TETHER_TAU (default: the preparation's own end): tether every run at this tau instead
#   (Minimum = Maximum preparation time), so that the runs differ only in the knob studied:
#   the preparation's end moves by up to 0.03 tau with N_GL at 256 points, and F_max with it.
# Environment (optional):
#   MESH_POINTS   the mesh study's N (default "64 128 192 256 320");
#   TETHER2D_SET  further deck settings for every run, separated by ';', e.g. the converging
#                 family of docs/tether2d.md: "Cell/Prestress=0.2;Tether/Regrid at
#                 tethering=true;Tether/Spacing at the tether=0.1;Tether/Preparation regrid
#                 interval=0.05" (with TETHER_TAU = 4.2).
# Results: OUT_DIR/mesh.txt, OUT_DIR/quadrature.txt (docs/tether2d.md records them).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:?build directory}
out=${2:?output directory}
which=${3:-all}
quadN=${4:-256}
gap=${5:-}
tetherTau=${6:-}
app="$build/apps/tether2d/tether2d"
deck="$here/input/tether2d/study/ab1_lambda1_ca0.25.xml"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mkdir -p "$out"

# Runs past the maximum (tau ~ 10) and stops: the study needs F_max only.
common=(--set "Time integration/End time=16" --set "Output/Interval=0.25" --set "Output/Snapshot every=0"
        --set "Output/Checkpoint every=0")
if [[ -n $gap ]]; then
  common+=(--set "Cell/Lowest point height=$gap" --set "Tether/Anchor height=$gap")
fi
if [[ -n ${TETHER2D_SET:-} ]]; then
  IFS=';' read -r -a extra <<< "$TETHER2D_SET"
  for assignment in "${extra[@]}"; do
    common+=(--set "$assignment")
  done
fi
if [[ -n $tetherTau ]]; then
  common+=(--set "Tether/Minimum preparation time=$tetherTau" --set "Tether/Maximum preparation time=$tetherTau")
fi

# F_max of a finished run, or why it failed (the last error line of its log).
maxForce() {
  if [[ -f $1/summary.json ]]; then
    sed -n 's/.*"tether_force": \([-0-9.eE+]*\).*/\1/p' "$1/summary.json" | tail -1
  else
    echo "failed: $(grep -h 'error' "$1.log" | tail -1)"
  fi
}

if [[ $which == mesh || $which == all ]]; then
  : > "$out/mesh.txt"
  for n in ${MESH_POINTS:-64 128 192 256 320}; do
    dir="$out/mesh_N$n"
    start=$(date +%s)
    "$app" "$deck" "${common[@]}" --set "Cell/Number of points=$n" --output "$dir" > "$dir.log" 2>&1 || true
    echo "$n $(maxForce "$dir") $(( $(date +%s) - start ))" | tee -a "$out/mesh.txt"
  done
  # Least-squares fit of F = F_inf + C N^alpha: linear in (F_inf, C) for each alpha on a grid.
  # Failed runs ("failed: ...") are left out of the fit.
  awk '$2 ~ /^[-0-9.eE+]+$/ { ++m; n[m] = $1; f[m] = $2 } END {
    best = 1e300
    for (a = -4.0; a <= -0.2; a += 0.001) {
      sx = sy = sxx = sxy = 0
      for (i = 1; i <= m; ++i) { x = n[i]^a; sx += x; sy += f[i]; sxx += x*x; sxy += x*f[i] }
      c = (m*sxy - sx*sy) / (m*sxx - sx*sx); finf = (sy - c*sx) / m
      r = 0; for (i = 1; i <= m; ++i) { e = f[i] - finf - c*n[i]^a; r += e*e }
      if (r < best) { best = r; ba = a; bc = c; bf = finf }
    }
    printf "fit: F_max = %.5f + %.4f N^%.3f (rms residual %.2e); spread N_min..N_max: %.2f%%\n",
           bf, bc, ba, sqrt(best/m), 100*(f[1]-f[m])/f[m] }' "$out/mesh.txt" | tee -a "$out/mesh.txt"
fi

if [[ $which == quadrature || $which == all ]]; then
  : > "$out/quadrature.txt"
  for near in 0 2; do
    for ngl in 5 6 8 12; do
      dir="$out/quad_N${quadN}_near${near}_gl$ngl"
      start=$(date +%s)
      "$app" "$deck" "${common[@]}" --set "Cell/Number of points=$quadN" \
        --set "Discretisation/Gauss-Legendre points=$ngl" --set "Discretisation/Log-weighted points=$ngl" \
        --set "Discretisation/Near-singular distance=$near" --output "$dir" > "$dir.log" 2>&1 || true
      echo "N=$quadN near-singular-distance=$near N_GL=$ngl F_max=$(maxForce "$dir") seconds=$(( $(date +%s) - start ))" \
        | tee -a "$out/quadrature.txt"
    done
  done
fi
