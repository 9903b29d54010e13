#!/usr/bin/env bash
# The long validation runs of cell3d (thesis Section 3.12), results recorded in
# docs/validation-cell3d.md:
#   lac2005     Skalak capsule (C = 1) prestressed 2.5% at Ca = 1.8, unbounded shear, mesh
#               levels 1-3: D12 against Lac & Barthes-Biesel (2005) 0.547 (thesis 0.538)
#   small       neo-Hookean capsule at Ca = 0.01, unbounded, levels 1-3: D12 / Ca against the
#               small-deformation limit 25/12 (Barthes-Biesel & Rallison 1981)
#   goldman     nearly rigid capsule held at the heights of Goldman, Cox & Brenner (1967),
#               Ca = 0.01 and 0.005 extrapolated to Ca = 0: slip velocity and rotation rate
#   lac2004     neo-Hookean capsule at Ca = 0.3, 0.6, 0.9, 1.2, unbounded, levels 2-3
# Usage: utils/validate-cell3d.sh [BUILD] [CASE...]   (default: build, all cases)
# Environment: RANKS (default 2), OUT (default out/validation-cell3d), FIGDIR (figures).
# Cost on 2 cores: lac2005 ~10 min, small ~5 min, goldman ~15 min, lac2004 ~20 min.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:-build}
[[ "$build" = /* ]] || build="$here/$build"
shift || true
cases=${*:-lac2005 small goldman lac2004}
ranks=${RANKS:-2}
out=${OUT:-$here/out/validation-cell3d}
cd "$here"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mkdir -p "$out"

# run NAME DECK [--set ...]: runs the deck into $out/NAME (a failed run is reported, not fatal:
# its outputs up to the failure are analysed).
run() {
  local name=$1 deck=$2
  shift 2
  echo "== $name" >&2
  mpiexec -n "$ranks" --oversubscribe "$build/apps/cell3d/cell3d" "input/cell3d/validation/$deck" \
    --output "$out/$name" --set "Output/Snapshots=false" "$@" > "$out/$name.log" 2>&1 ||
    echo "   (stopped early: $(grep -m1 'error' "$out/$name.log" | cut -c1-160))" >&2
}

# column NAME COLUMN TIME: the value of COLUMN at the output time closest to TIME ("max" for
# the maximum over the run, "last" for the last row).
column() {
  python3 - "$out/$1/metrics.csv" "$2" "$3" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
col, when = sys.argv[2], sys.argv[3]
if when == "max":
    print(max(float(r[col]) for r in rows))
elif when == "last":
    print(float(rows[-1][col]))
else:
    t = float(when)
    print(float(min(rows, key=lambda r: abs(float(r["time"]) - t))[col]))
PY
}
maxabs() {
  python3 - "$out/$1/metrics.csv" "$2" <<'PY'
import csv, sys
print(max(abs(float(r[sys.argv[2]])) for r in csv.DictReader(open(sys.argv[1]))))
PY
}

for case in $cases; do
  case $case in
  lac2005)
    echo "## Lac & Barthes-Biesel (2005): Skalak C = 1, prestress 2.5%, Ca = 1.8 (reference D12 = 0.547)"
    echo "| level | N_E | D12(t=4) | D12(t=8) | max D12 (time) | last t | max volume drift |"
    echo "|---|---|---|---|---|---|---|"
    for level in 1 2 3; do
      run lac2005-L$level lac2005-skalak-Ca1.8-prestress2.5.xml --set "Cells/Cell 0/Mesh level=$level" \
        --set "Time integration/End time=12"
      echo "| $level | $((20 * 4 ** level)) | $(column lac2005-L$level D12 4) | $(column lac2005-L$level D12 8) |" \
           "$(column lac2005-L$level D12 max) | $(column lac2005-L$level time last) | $(maxabs lac2005-L$level volume_change) |"
    done
    ;;
  small)
    echo "## Small deformation: neo-Hookean, Ca = 0.01, unbounded (reference D12/Ca = 25/12 = 2.0833)"
    echo "| level | D12(t=0.3) | D12/Ca | max volume drift |"
    echo "|---|---|---|---|"
    for level in 1 2 3; do
      run small-L$level small-deformation-neohookean-Ca0.01.xml --set "Cells/Cell 0/Mesh level=$level"
      d=$(column small-L$level D12 last)
      echo "| $level | $d | $(python3 -c "print($d / 0.01)") | $(maxabs small-L$level volume_change) |"
    done
    ;;
  goldman)
    echo "## Goldman, Cox & Brenner (1967): rigid sphere at height h; capsule Ca -> 0 (level 2, t = 0.3)"
    echo "| h/a | u_slip Ca=0.01 | u_slip Ca=0.005 | u_slip Ca->0 | far field 5/16 (a/h)^2 | Omega Ca->0 | far field -(1 - 5/16 (a/h)^3)/2 |"
    echo "|---|---|---|---|---|---|---|"
    for h in 1.1276 1.5431 2.3524 3.7622 10.0677; do
      run goldman-h$h-Ca0.01 goldman-rigid-h$h.xml
      run goldman-h$h-Ca0.005 goldman-rigid-h$h.xml --set "Flow/Capillary number=0.005"
      s1=$(column goldman-h$h-Ca0.01 u_slip_instant last)
      s2=$(column goldman-h$h-Ca0.005 u_slip_instant last)
      w1=$(column goldman-h$h-Ca0.01 omega_z last)
      w2=$(column goldman-h$h-Ca0.005 omega_z last)
      python3 - "$h" "$s1" "$s2" "$w1" "$w2" <<'PY'
import sys
h, s1, s2, w1, w2 = map(float, sys.argv[1:])
s0, w0 = 2 * s2 - s1, 2 * w2 - w1   # linear in Ca
print("| %g | %.5f | %.5f | %.5f | %.5f | %.5f | %.5f |" % (h, s1, s2, s0, 5 / 16 / h**2, w0, -0.5 * (1 - 5 / 16 / h**3)))
PY
    done
    ;;
  lac2004)
    echo "## Neo-Hookean capsule, unbounded shear (Lac et al. 2004, thesis Fig 3.9)"
    echo "| Ca | level | D12(t=4) | D12(t=8) | max D12 | last t | max volume drift |"
    echo "|---|---|---|---|---|---|---|"
    for ca in 0.3 0.6 0.9 1.2; do
      for level in 2 3; do
        run lac2004-Ca$ca-L$level lac2004-neohookean-Ca$ca.xml --set "Cells/Cell 0/Mesh level=$level" \
          --set "Time integration/End time=10"
        echo "| $ca | $level | $(column lac2004-Ca$ca-L$level D12 4) | $(column lac2004-Ca$ca-L$level D12 8) |" \
             "$(column lac2004-Ca$ca-L$level D12 max) | $(column lac2004-Ca$ca-L$level time last) |" \
             "$(maxabs lac2004-Ca$ca-L$level volume_change) |"
      done
    done
    ;;
  *) echo "unknown case '$case' (lac2005 small goldman lac2004)" >&2; exit 2 ;;
  esac
done

# Figures of the runs in $out (utils/plotting/validation_cell3d.py): into FIGDIR (default
# $out/figures; docs/figures holds the committed ones).
/usr/bin/python3 utils/plotting/validation_cell3d.py "$out" "${FIGDIR:-$out/figures}"
