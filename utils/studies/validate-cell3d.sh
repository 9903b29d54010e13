#!/usr/bin/env bash
# The long validation runs of cell3d (thesis Section 3.12), recorded in docs/validation-cell3d.md:
#   lac2005     Skalak capsule (C = 1) prestressed 2.5% at Ca = 1.8, unbounded shear, mesh
#               levels 1-3: D12 against Lac & Barthes-Biesel (2005) 0.547 (thesis 0.538)
#   small       neo-Hookean capsule at Ca = 0.01, unbounded, levels 1-3: D12 / Ca against the
#               small-deformation limit 25/12 (Barthes-Biesel & Rallison 1981)
#   goldman     nearly rigid capsule held at the heights of Goldman, Cox & Brenner (1967),
#               Ca = 0.01 and 0.005 extrapolated to Ca = 0: slip velocity and rotation rate
#   lac2004     neo-Hookean capsule at Ca = 0.3, 0.6, 0.9, 1.2, unbounded, levels 2-3
set -euo pipefail
STUDY=validate-cell3d
APP=cell3d
DEFAULT_RANKS=2
DEFAULT_JOBS=1
figure_dir=""

usage() {
  cat <<EOF
Usage: utils/studies/validate-cell3d.sh [options] [CASE...]

Runs the validation cases (default: all of lac2005 small goldman lac2004), prints their
tables (Markdown) and draws their figures.

  --figures DIR  where the figures go (default: RUNS/figures; docs/figures holds the
                 committed ones)
$(common_options_help)

A run that stops early is reported, and its outputs up to then are analysed.
Cost on 2 cores: lac2005 ~10 min, small ~5 min, goldman ~15 min, lac2004 ~20 min.
EOF
}

study_option() {
  case "$1" in
    --figures) figure_dir="$2"; consumed=2 ;;
  esac
}

source "$(dirname "${BASH_SOURCE[0]}")/study-lib.sh"
parse_options "$@"
cases=("${positional[@]}")
[[ ${#cases[@]} -gt 0 ]] || cases=(lac2005 small goldman lac2004)
out=$runs
goldman_heights="1.1276 1.5431 2.3524 3.7622 10.0677"

# validation_run NAME DECK [--set ...]: a run of a validation deck, without snapshots.
validation_run() {
  local name=$1 deck=$2
  shift 2
  queue_run "$name" "input/cell3d/validation/$deck" --set "Output/Snapshots=false" "$@"
}

for case in "${cases[@]}"; do
  case $case in
  lac2005)
    for level in 1 2 3; do
      validation_run "lac2005-L$level" lac2005-skalak-Ca1.8-prestress2.5.xml \
        --set "Cells/Cell 0/Mesh level=$level" --set "Time integration/End time=12"
    done ;;
  small)
    for level in 1 2 3; do
      validation_run "small-L$level" small-deformation-neohookean-Ca0.01.xml --set "Cells/Cell 0/Mesh level=$level"
    done ;;
  goldman)
    for h in $goldman_heights; do
      validation_run "goldman-h$h-Ca0.01" "goldman-rigid-h$h.xml"
      validation_run "goldman-h$h-Ca0.005" "goldman-rigid-h$h.xml" --set "Flow/Capillary number=0.005"
    done ;;
  lac2004)
    for ca in 0.3 0.6 0.9 1.2; do
      for level in 2 3; do
        validation_run "lac2004-Ca$ca-L$level" "lac2004-neohookean-Ca$ca.xml" \
          --set "Cells/Cell 0/Mesh level=$level" --set "Time integration/End time=10"
      done
    done ;;
  *) die "unknown case '$case' (lac2005 small goldman lac2004)" ;;
  esac
done
echo "== $STUDY (${cases[*]}): runs in $runs, $jobs at a time, $ranks rank(s) each" >&2
run_queued >&2
[[ $failed_runs -eq 0 ]] || echo "== $failed_runs run(s) stopped early; their outputs up to then are analysed" >&2

# column NAME COLUMN TIME: the value of COLUMN at the output time closest to TIME ("max" for
# the maximum over the run, "last" for the last row).
column() {
  "$python" - "$out/$1/metrics.csv" "$2" "$3" <<'PY'
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
  "$python" - "$out/$1/metrics.csv" "$2" <<'PY'
import csv, sys
print(max(abs(float(r[sys.argv[2]])) for r in csv.DictReader(open(sys.argv[1]))))
PY
}

for case in "${cases[@]}"; do
  case $case in
  lac2005)
    echo "## Lac & Barthes-Biesel (2005): Skalak C = 1, prestress 2.5%, Ca = 1.8 (reference D12 = 0.547)"
    echo "| level | N_E | D12(t=4) | D12(t=8) | max D12 (time) | last t | max volume drift |"
    echo "|---|---|---|---|---|---|---|"
    for level in 1 2 3; do
      echo "| $level | $((20 * 4 ** level)) | $(column lac2005-L$level D12 4) | $(column lac2005-L$level D12 8) |" \
           "$(column lac2005-L$level D12 max) | $(column lac2005-L$level time last) | $(maxabs lac2005-L$level volume_change) |"
    done
    ;;
  small)
    echo "## Small deformation: neo-Hookean, Ca = 0.01, unbounded (reference D12/Ca = 25/12 = 2.0833)"
    echo "| level | D12(t=0.3) | D12/Ca | max volume drift |"
    echo "|---|---|---|---|"
    for level in 1 2 3; do
      d=$(column small-L$level D12 last)
      echo "| $level | $d | $("$python" -c "print($d / 0.01)") | $(maxabs small-L$level volume_change) |"
    done
    ;;
  goldman)
    echo "## Goldman, Cox & Brenner (1967): rigid sphere at height h; capsule Ca -> 0 (level 2, t = 0.3)"
    echo "| h/a | u_slip Ca=0.01 | u_slip Ca=0.005 | u_slip Ca->0 | far field 5/16 (a/h)^2 | Omega Ca->0 | far field -(1 - 5/16 (a/h)^3)/2 |"
    echo "|---|---|---|---|---|---|---|"
    for h in $goldman_heights; do
      s1=$(column goldman-h$h-Ca0.01 u_slip last)
      s2=$(column goldman-h$h-Ca0.005 u_slip last)
      w1=$(column goldman-h$h-Ca0.01 omega_z last)
      w2=$(column goldman-h$h-Ca0.005 omega_z last)
      "$python" - "$h" "$s1" "$s2" "$w1" "$w2" <<'PY'
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
        echo "| $ca | $level | $(column lac2004-Ca$ca-L$level D12 4) | $(column lac2004-Ca$ca-L$level D12 8) |" \
             "$(column lac2004-Ca$ca-L$level D12 max) | $(column lac2004-Ca$ca-L$level time last) |" \
             "$(maxabs lac2004-Ca$ca-L$level volume_change) |"
      done
    done
    ;;
  esac
done

# The figures of the runs (utils/plotting/validation_cell3d.py).
"$python" "$plotting/validation_cell3d.py" "$out" "${figure_dir:-$out/figures}"
