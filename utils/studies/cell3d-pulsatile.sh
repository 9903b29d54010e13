#!/usr/bin/env bash
# The pulsatile study (docs/cell3d-pulsatile-results.md): the demo's capsule (Skalak C = 2.5,
# Ca = 0.3, released at h/a = 1.6) under k(t) = 1 + 0.5 sin(2 pi t / T) at a short and a long
# period, and in the steady shear of the same mean (input/cell3d/pulsatile/); draws the phase
# lags and amplitudes of D12 and u_slip and the centroid heights (utils/plotting/cell3d_pulsatile.py).
#   utils/studies/cell3d-pulsatile.sh --quick /tmp/fig   # ~10 s on 2 cores: level 1, T = 0.5 and 1.5, t = 3
#   utils/studies/cell3d-pulsatile.sh docs/figures       # reduced (docs/figures): level 2, T = 0.5 and 5, t = 15: ~8 min
#   utils/studies/cell3d-pulsatile.sh --full /tmp/fig    # the decks as written (the reduced runs)
# utils/studies/cell3d-pulsatile.sh --help lists the options.
set -euo pipefail
STUDY=cell3d-pulsatile
APP=cell3d
DEFAULT_RANKS=1   # level 1-2 meshes: two single-rank runs at a time use 2 cores best
source "$(dirname "${BASH_SOURCE[0]}")/study-lib.sh"

EXPECTED=(cell3d_pulsatile_response.png cell3d_pulsatile_lags.png)

transient=5
study_runs() {
  local settings=() long=5 long_interval=0.25
  case "$mode" in
    quick)
      # Mesh level 1 (80 elements) to t = 3: two periods of T = 1.5 (in place of 5) and six
      # of T = 0.5 after a transient of 1; no checkpoints or snapshots.
      settings=(--set "Cells/Cell 0/Mesh level=1" --set "Time integration/End time=3"
                --set "Output/Checkpoint=false" --set "Output/Snapshots=false")
      long=1.5; long_interval=0.075; transient=1 ;;
    reduced|full)
      # The decks as written: level 2, to t = 15, fitted after t = 5.
      settings=() ;;
  esac
  queue_run steady input/cell3d/pulsatile/steady.xml "${settings[@]}"
  queue_run T0.5-A0.5 input/cell3d/pulsatile/T0.5-A0.5.xml "${settings[@]}"
  queue_run "T${long}-A0.5" input/cell3d/pulsatile/T5-A0.5.xml "${settings[@]}" \
    --set "Flow/Shear rate/Period=$long" --set "Output/Interval=$long_interval"
}

study_figures() {
  [[ "$mode" != quick ]] || transient=1
  draw cell3d_pulsatile.py --transient "$transient"
}

figure_study_main "$@"
