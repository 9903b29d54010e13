#!/usr/bin/env bash
# The single-cell study near a wall (thesis Chapter 5, docs/cell3d.md): runs decks of
# input/cell3d/{heights,fixed-height,unbounded}/ with cell3d and draws Figs. 5.3-5.22
# (profiles, deformation and velocities against h/a and against C and Ca, wall shear
# stress maps and line cuts) as PNG files.
#   utils/studies/cell3d.sh --quick /tmp/fig      # ~1 min on 2 cores: 18 runs, mesh level 1, t = 0.4
#   utils/studies/cell3d.sh docs/figures          # reduced (docs/figures): 25 runs, level 2, t = 2
#   utils/studies/cell3d.sh --full /tmp/fig       # every deck as written (level 3, t = 15): days
# utils/studies/cell3d.sh --help lists the options.
set -euo pipefail
STUDY=cell3d
APP=cell3d
DEFAULT_RANKS=1   # level 1-2 meshes: two single-rank runs at a time use 2 cores best
source "$(dirname "${BASH_SOURCE[0]}")/study-lib.sh"

EXPECTED=(
  cell3d_fig5.5_xy_profiles_over_C.png cell3d_fig5.6_xy_profiles_over_Ca.png cell3d_fig5.9_xz_profiles_over_Ca.png
  cell3d_fig5.3_reduced_volume_vs_height.png cell3d_fig5.4_reduced_volume_vs_C_and_Ca.png
  cell3d_fig5.7_footprint_vs_height.png cell3d_fig5.8_footprint_vs_C_and_Ca.png
  cell3d_fig5.10_slip_velocity_vs_height.png cell3d_fig5.11_slip_velocity_vs_C_and_Ca.png
  cell3d_fig5.13_migration_velocity_vs_height.png cell3d_fig5.14_migration_velocity_vs_C_and_Ca.png
  cell3d_fig5.15_membrane_stress_increase_vs_height.png cell3d_fig5.16_membrane_stress_increase_vs_C_and_Ca.png
  cell3d_fig5.19_wall_area_downstream_vs_height.png cell3d_fig5.20_wall_area_downstream_vs_C_and_Ca.png
  cell3d_fig5.21_wall_area_upstream_vs_height.png cell3d_fig5.22_wall_area_upstream_vs_C_and_Ca.png
  cell3d_fig5.17_wall_stress_maps.png cell3d_fig5.18_wall_stress_line.png
)

transient=1
study_runs() {
  local settings=() ca c h heights cas_a cs_b cas_fixed cs_fixed cas_free
  local wall=(--set "Output/Wall shear stress/Spacing=0.5")
  case "$mode" in
    quick)
      # Mesh level 1 (80 elements), t = 0.4: the cell has only begun to deform.
      settings=(--set "Cells/Cell 0/Mesh level=1" --set "Time integration/End time=0.4"
                --set "Output/Interval=0.05" --set "Output/Snapshot stride=4"
                --set "Output/Wall shear stress/Upstream extent=3" --set "Output/Wall shear stress/Downstream extent=3"
                --set "Output/Wall shear stress/Half width=2")
      heights="1.2 2"; cas_a="0.1 0.6"; cs_b="0.5 2.5"; cas_fixed="0.1 0.6"; cs_fixed="0.5 2.5"; cas_free="0.1 0.6"
      transient=0.2 ;;
    reduced)
      # Mesh level 2 (320 elements; the thesis: level 3), t = 2 (the thesis: 15, or steady
      # state); outputs after t = 1 count as past the transient.
      settings=(--set "Cells/Cell 0/Mesh level=2" --set "Time integration/End time=2"
                --set "Output/Interval=0.1" --set "Output/Snapshot stride=5")
      heights="1.2 2 3"; cas_a="0.1 0.6"; cs_b="0.5 2.5"; cas_fixed="0.1 0.3 0.9"
      cs_fixed="0.5 2.5"; cas_free="0.1 0.3 0.9" ;;
    full)
      settings=()
      wall=()
      heights="1.2 1.6 2 3 5 7.5 10"; cas_a="0.01 0.1 0.3 0.6"; cs_b="0.5 1 1.5 2 2.5"
      cas_fixed="0.01 0.1 0.3 0.6 0.9"; cs_fixed="0.5 1 1.5 2 2.5"; cas_free="0.01 0.1 0.3 0.6 0.9" ;;
  esac
  # Released from several heights (Figs. 5.3, 5.7, 5.10, 5.13, 5.15, 5.19, 5.21).
  for h in $heights; do
    for ca in $cas_a; do
      queue_run "heights/Ca${ca}-C2.5-prestress5-h${h}" "input/cell3d/heights/Ca${ca}-C2.5-prestress5-h${h}.xml" \
        "${settings[@]}" "${wall[@]}"
    done
    for c in $cs_b; do
      queue_run "heights/Ca0.9-C${c}-prestress0-h${h}" "input/cell3d/heights/Ca0.9-C${c}-prestress0-h${h}.xml" \
        "${settings[@]}" "${wall[@]}"
    done
  done
  # Held at h/a = 1.25 (Figs. 5.4-5.9, 5.11, 5.16-5.18, 5.20, 5.22).
  for ca in $cas_fixed; do
    for c in $cs_fixed; do
      queue_run "fixed-height/Ca${ca}-C${c}-prestress5" "input/cell3d/fixed-height/Ca${ca}-C${c}-prestress5.xml" \
        "${settings[@]}" "${wall[@]}"
    done
  done
  for c in $cs_fixed; do
    queue_run "fixed-height/Ca0.9-C${c}-prestress0" "input/cell3d/fixed-height/Ca0.9-C${c}-prestress0.xml" \
      "${settings[@]}" "${wall[@]}"
  done
  # Unbounded shear (top rows of Figs. 5.5, 5.6, 5.9).
  for ca in $cas_free; do
    queue_run "unbounded/Ca${ca}-C0.5-prestress5" "input/cell3d/unbounded/Ca${ca}-C0.5-prestress5.xml" "${settings[@]}"
  done
  for c in $cs_fixed; do
    queue_run "unbounded/Ca0.9-C${c}-prestress0" "input/cell3d/unbounded/Ca0.9-C${c}-prestress0.xml" "${settings[@]}"
  done
}

study_figures() {
  [[ "$mode" != quick ]] || transient=0.2
  draw cell3d_profiles.py
  draw cell3d_trends.py --transient "$transient"
  draw cell3d_wall_stress.py
}

figure_study_main "$@"
