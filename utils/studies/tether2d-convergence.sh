#!/usr/bin/env bash
# The 2D convergence studies of thesis Section 3.12.1 with tether2d, on the study deck
# input/tether2d/study/ab1_lambda1_ca0.25.xml (a/b = 1, Ca = 0.25, lambda = 1):
#   mesh        the maximum tether force for N = 64 .. 320 points and the fit
#               F_max = F_inf + C N^alpha (thesis Fig. 3.6: alpha = -1.45, 3.4% spread from 64
#               to 320 elements);
#   quadrature  the maximum tether force for N_GL = 5, 6, 8, 12 (thesis Table 3.2: 3.2525,
#               3.2469, 3.2474, 3.2475), with and without the near-singular subdivision.
# Results: RUNS/mesh.txt and RUNS/quadrature.txt (docs/tether2d-results.md).
set -euo pipefail
STUDY=tether2d-convergence
APP=tether2d
DEFAULT_JOBS=1   # the wall time of each run is part of the result
which=all
mesh_points="64 128 192 256 320"
quadrature_points=256
gap=""
tether_tau=""
extra=()

usage() {
  cat <<EOF
Usage: utils/studies/tether2d-convergence.sh [options] [mesh|quadrature|all]

Runs the mesh and/or quadrature convergence study of the maximum tether force (default: all).

  --points "N..."       the mesh study's numbers of points (default "$mesh_points")
  --quadrature-points N the quadrature study's number of points (default $quadrature_points)
  --gap G               the initial lowest-point height and the anchor height (default: the
                        deck's 0.005); 0.1 resolves the film between the cell and the wall
  --tether-tau T        tether every run at this tau (Minimum = Maximum preparation time), so
                        that the runs differ only in the knob studied (default: each run's own
                        end of preparation, which moves with N and N_GL)
  --set "List/Key=value"  a further setting for every run (repeatable), e.g. the converging
                        family of docs/tether2d-results.md: --set "Cell/Prestress=0.2"
                        --set "Tether/Regrid at tethering=true" --set "Tether/Spacing at the
                        tether=0.1" --set "Tether/Preparation regrid interval=0.05" --tether-tau 4.2
$(common_options_help)
EOF
}

study_option() {
  case "$1" in
    --points) mesh_points="$2"; consumed=2 ;;
    --quadrature-points) quadrature_points="$2"; consumed=2 ;;
    --gap) gap="$2"; consumed=2 ;;
    --tether-tau) tether_tau="$2"; consumed=2 ;;
    --set) extra+=(--set "$2"); consumed=2 ;;
  esac
}

source "$(dirname "${BASH_SOURCE[0]}")/study-lib.sh"
parse_options "$@"
[[ ${#positional[@]} -le 1 ]] || die "give one of mesh, quadrature, all (see --help)"
which=${positional[0]:-all}
[[ $which =~ ^(mesh|quadrature|all)$ ]] || die "unknown study '$which' (mesh, quadrature, all)"
deck=input/tether2d/study/ab1_lambda1_ca0.25.xml

# Runs past the maximum (tau ~ 10) and stops: the study needs F_max only.
common=(--set "Time integration/End time=16" --set "Output/Interval=0.25" --set "Output/Snapshot every=0"
        --set "Output/Checkpoint every=0")
if [[ -n $gap ]]; then
  common+=(--set "Cell/Lowest point height=$gap" --set "Tether/Anchor height=$gap")
fi
common+=("${extra[@]}")
if [[ -n $tether_tau ]]; then
  common+=(--set "Tether/Minimum preparation time=$tether_tau" --set "Tether/Maximum preparation time=$tether_tau")
fi

# F_max of a finished run, or why it failed (the last error line of its log).
max_force() {
  if [[ -f $runs/$1/summary.json ]]; then
    sed -n 's/.*"tether_force": \([-0-9.eE+]*\).*/\1/p' "$runs/$1/summary.json" | tail -1
  else
    echo "failed: $(grep -h 'error' "$runs/$1.log" | tail -1)"
  fi
}

if [[ $which == mesh || $which == all ]]; then
  for n in $mesh_points; do
    queue_run "mesh_N$n" "$deck" "${common[@]}" --set "Cell/Number of points=$n"
  done
fi
if [[ $which == quadrature || $which == all ]]; then
  for near in 0 2; do
    for ngl in 5 6 8 12; do
      queue_run "quad_N${quadrature_points}_near${near}_gl$ngl" "$deck" "${common[@]}" \
        --set "Cell/Number of points=$quadrature_points" --set "Discretisation/Gauss-Legendre points=$ngl" \
        --set "Discretisation/Log-weighted points=$ngl" --set "Discretisation/Near-singular distance=$near"
    done
  done
fi
echo "== $STUDY ($which): runs in $runs, $jobs at a time"
run_queued

if [[ $which == mesh || $which == all ]]; then
  : > "$runs/mesh.txt"
  for n in $mesh_points; do
    echo "$n $(max_force "mesh_N$n") $(seconds_of "mesh_N$n")" | tee -a "$runs/mesh.txt"
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
           bf, bc, ba, sqrt(best/m), 100*(f[1]-f[m])/f[m] }' "$runs/mesh.txt" | tee -a "$runs/mesh.txt"
fi

if [[ $which == quadrature || $which == all ]]; then
  : > "$runs/quadrature.txt"
  for near in 0 2; do
    for ngl in 5 6 8 12; do
      name="quad_N${quadrature_points}_near${near}_gl$ngl"
      echo "N=$quadrature_points near-singular-distance=$near N_GL=$ngl F_max=$(max_force "$name")" \
           "seconds=$(seconds_of "$name")" | tee -a "$runs/quadrature.txt"
    done
  done
fi
