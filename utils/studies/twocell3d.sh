#!/usr/bin/env bash
# Two cells near a wall (thesis Chapter 6, docs/twocell3d.md): runs decks of
# input/twocell3d/{side-by-side,in-line}/ with twocell3d and draws Figs. 6.3, 6.4, 6.6, 6.9,
# 6.10 and 6.12 (velocities against the separation, wall shear stress maps) as PNG files.
#   utils/studies/twocell3d.sh --quick /tmp/fig   # ~15 s on 2 cores: 8 runs, mesh level 1, t = 0.3
#   utils/studies/twocell3d.sh docs/figures       # reduced: 10 runs at h/a = 1.25, level 2, t = 1
#   utils/studies/twocell3d.sh --full /tmp/fig    # every deck as written (level 3, t = 15): days
# utils/studies/twocell3d.sh --help lists the options.
set -euo pipefail
STUDY=twocell3d
APP=twocell3d
DEFAULT_RANKS=1
source "$(dirname "${BASH_SOURCE[0]}")/study-lib.sh"

EXPECTED=(
  twocell3d_fig6.3_velocities_side_by_side.png twocell3d_fig6.4_relative_spanwise_velocity.png
  twocell3d_fig6.6_wall_stress_side_by_side.png twocell3d_fig6.9_velocities_in_line.png
  twocell3d_fig6.10_relative_slip_in_line.png twocell3d_fig6.12_wall_stress_in_line.png
)

transient=0.5
study_runs() {
  local settings=() heights d h kind sbs_fixed sbs_free inl_fixed inl_free
  case "$mode" in
    quick)
      settings=(--set "Cells/Cell 0/Mesh level=1" --set "Cells/Cell 1/Mesh level=1"
                --set "Time integration/End time=0.3" --set "Output/Interval=0.05" --set "Output/Snapshot stride=3"
                --set "Output/Wall shear stress/Spacing=1")
      heights="1.25"; sbs_fixed="1 3"; sbs_free="1 3"; inl_fixed="1 3"; inl_free="1 3" ;;
    reduced)
      # Mesh level 2 (thesis: 3), t = 1 (thesis: 15 or steady shape), h/a = 1.25 only.
      settings=(--set "Cells/Cell 0/Mesh level=2" --set "Cells/Cell 1/Mesh level=2"
                --set "Time integration/End time=1" --set "Output/Interval=0.1" --set "Output/Snapshot stride=5")
      heights="1.25"; sbs_fixed="0.5 1 3"; sbs_free="1 3"; inl_fixed="1 3 5"; inl_free="1 3" ;;
    full)
      heights="1.25 2.5"; sbs_fixed="0.5 1 2 3 4 5 7.5 10"; sbs_free="$sbs_fixed"
      inl_fixed="1 2 3 4 5 7.5 10 20"; inl_free="$inl_fixed" ;;
  esac
  for h in $heights; do
    for kind in fixed free; do
      local sbs=$sbs_fixed inl=$inl_fixed
      [[ $kind == fixed ]] || { sbs=$sbs_free; inl=$inl_free; }
      for d in $sbs; do
        queue_run "side-by-side/h$h-dz$d-$kind" "input/twocell3d/side-by-side/h$h-dz$d-$kind.xml" "${settings[@]}"
      done
      for d in $inl; do
        queue_run "in-line/h$h-dx$d-$kind" "input/twocell3d/in-line/h$h-dx$d-$kind.xml" "${settings[@]}"
      done
    done
  done
}

study_figures() {
  [[ "$mode" != quick ]] || transient=0.1
  [[ "$mode" != full ]] || transient=1
  draw twocell3d_figures.py --transient "$transient"
}

figure_study_main "$@"
