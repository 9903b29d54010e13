#!/usr/bin/env bash
# The viscosity-ratio study (docs/cell3d-viscosity-ratio-results.md): an oblate capsule
# (aspect ratio 0.8) held at h/a = 1.25 and 2 above the wall and in unbounded shear, for
# lambda = 0.2 to 10 and Ca = 0.03 to 0.9, Skalak C = 2.5 and neo-Hookean
# (input/cell3d/viscosity-ratio/); classifies each run as tank-treading, swinging or tumbling
# and draws the phase diagram, the inclination and velocities against lambda and the cost of
# the lambda != 1 solve (utils/plotting/cell3d_viscosity_ratio.py).
#   utils/studies/cell3d-viscosity-ratio.sh --quick /tmp/fig   # ~40 s on 2 cores: 6 runs, level 1, t = 4
#   utils/studies/cell3d-viscosity-ratio.sh docs/figures       # reduced (docs/figures): the 152 decks at level 1: ~80 min
#   utils/studies/cell3d-viscosity-ratio.sh --full /tmp/fig    # the decks as written (level 2): about a day
# utils/studies/cell3d-viscosity-ratio.sh --help lists the options.
set -euo pipefail
STUDY=cell3d-viscosity-ratio
APP=cell3d
DEFAULT_RANKS=1   # level 1-2 meshes: two single-rank runs at a time use 2 cores best
source "$(dirname "${BASH_SOURCE[0]}")/study-lib.sh"

EXPECTED=(cell3d_viscosity_ratio_phase_diagram.png cell3d_viscosity_ratio_inclination.png
          cell3d_viscosity_ratio_velocities.png cell3d_viscosity_ratio_histories.png
          cell3d_viscosity_ratio_cost.png)

# Regimes are judged on the outputs after this time (the start-up from the unstressed shape).
transient=15
only=()   # --only GLOB: the runs whose name (e.g. unbounded/Skalak-Ca0.05-lambda2) matches

study_options_help() {
  echo "  --only GLOB  run only the decks whose name (the path under input/cell3d/viscosity-ratio/"
  echo "               without .xml, e.g. 'unbounded/Skalak-Ca0.05-*') matches GLOB; may be"
  echo "               repeated; the figures are drawn from every run in the runs folder"
}

study_runs() {
  local settings=() deck name
  local decks=("$here"/input/cell3d/viscosity-ratio/*/*.xml)
  case "$mode" in
    quick)
      # Mesh level 1 (80 elements) to t = 4, outputs every 0.2, no checkpoints or snapshots:
      # lambda = 0.2 and 10 at Ca = 0.1 near the wall and in unbounded shear, and the sphere.
      settings=(--set "Cells/Cell 0/Mesh level=1" --set "Time integration/End time=4"
                --set "Output/Interval=0.2" --set "Output/Checkpoint=false" --set "Output/Snapshots=false")
      decks=()
      for name in wall-h1.25/Skalak-Ca0.1-lambda0.2 wall-h1.25/Skalak-Ca0.1-lambda10 \
                  unbounded/Skalak-Ca0.1-lambda0.2 unbounded/Skalak-Ca0.1-lambda10 \
                  wall-h1.25/sphere-Skalak-Ca0.1-lambda10 unbounded/sphere-Skalak-Ca0.1-lambda10; do
        decks+=("$here/input/cell3d/viscosity-ratio/$name.xml")
      done
      transient=1 ;;
    reduced)
      # Every deck on mesh level 1 (80 elements; the decks: level 2), snapshots every 5 (at t = 0, 0.5, ...).
      settings=(--set "Cells/Cell 0/Mesh level=1" --set "Output/Snapshot stride=5") ;;
    full)
      settings=() ;;
  esac
  local pattern selected
  for deck in "${decks[@]}"; do
    name=${deck#"$here"/input/cell3d/viscosity-ratio/}
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
  local check=()
  # The quick runs are too short for regimes, not for the trends every run set must show.
  [[ "$mode" != quick ]] || check=(--check-trends)
  draw cell3d_viscosity_ratio.py --transient "$transient" "${check[@]}"
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
