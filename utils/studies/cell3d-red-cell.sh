#!/usr/bin/env bash
# The red-cell study (docs/cell3d-red-cell-results.md): the Evans-Fung biconcave cell with
# Skalak C = 10 and bending E_b = 0.01 about its initial shape (input/cell3d/red-cell/), in
# unbounded shear (Ca 0.05-0.8, lambda 1 and 5) and released at h/a = 2; classifies each run as
# tank-treading, swinging or tumbling (the criterion of cell3d_viscosity_ratio.py) and draws
# the regime diagram and the inclination and D12 histories (utils/plotting/cell3d_red_cell.py).
#   utils/studies/cell3d-red-cell.sh --quick /tmp/fig   # ~1 min on 2 cores: 2 runs, level 1, t = 2
#   utils/studies/cell3d-red-cell.sh docs/figures       # reduced: the decks at level 2 to t = 10
#   utils/studies/cell3d-red-cell.sh --full /tmp/fig    # the decks as written (level 2, t = 30)
# utils/studies/cell3d-red-cell.sh --help lists the options.
set -euo pipefail
STUDY=cell3d-red-cell
APP=cell3d
DEFAULT_RANKS=1   # level 1-2 meshes: two single-rank runs at a time use 2 cores best
source "$(dirname "${BASH_SOURCE[0]}")/study-lib.sh"

EXPECTED=(cell3d_red_cell_regimes.png cell3d_red_cell_histories.png)

# Regimes are judged on the outputs after this time (the start-up from rest).
transient=5
only=()   # --only GLOB: the runs whose name (e.g. unbounded/Ca0.1-lambda5) matches

study_options_help() {
  echo "  --only GLOB  run only the decks whose name (the path under input/cell3d/red-cell/"
  echo "               without .xml, e.g. 'unbounded/Ca0.1-*') matches GLOB; may be repeated;"
  echo "               the figures are drawn from every run in the runs folder"
}

study_runs() {
  local settings=() deck name
  local decks=("$here"/input/cell3d/red-cell/*/*.xml)
  case "$mode" in
    quick)
      # Mesh level 1 (80 elements) to t = 2, outputs every 0.1, no checkpoints or snapshots:
      # the smallest and the largest Ca of the free-shear decks at lambda = 1.
      settings=(--set "Cells/Cell 0/Mesh level=1" --set "Time integration/End time=2"
                --set "Output/Interval=0.1" --set "Output/Checkpoint=false" --set "Output/Snapshots=false")
      decks=("$here/input/cell3d/red-cell/unbounded/Ca0.05-lambda1.xml"
             "$here/input/cell3d/red-cell/unbounded/Ca0.8-lambda1.xml")
      transient=0.5 ;;
    reduced)
      # The decks (level 2) to t = 10, snapshots every 5 outputs.
      settings=(--set "Time integration/End time=10" --set "Output/Snapshot stride=5") ;;
    full)
      settings=() ;;
  esac
  local pattern selected
  for deck in "${decks[@]}"; do
    name=${deck#"$here"/input/cell3d/red-cell/}
    name=${name%.xml}
    selected=$((${#only[@]} == 0))
    for pattern in "${only[@]}"; do
      # shellcheck disable=SC2053  # GLOB is a pattern
      if [[ "$name" == $pattern ]]; then selected=1; fi
    done
    if [[ $selected -eq 1 ]]; then queue_run "$name" "$deck" "${settings[@]}"; fi
  done
  [[ ${#queued[@]} -gt 0 ]] || die "no deck matches --only ${only[*]}"
}

study_figures() {
  draw cell3d_red_cell.py --transient "$transient"
}

# --only is this study's own option; the rest go to figure_study_main.
args=()
while [[ $# -gt 0 ]]; do
  if [[ "$1" == --only ]]; then
    [[ $# -ge 2 ]] || die "--only needs a GLOB (see --help)"
    only+=("$2")
    shift 2
  else
    args+=("$1")
    shift
  fi
done
figure_study_main "${args[@]}"
