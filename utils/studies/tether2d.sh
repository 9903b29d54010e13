#!/usr/bin/env bash
# The 2D tethered-cell study (thesis Chapter 4, docs/tether2d.md): runs the decks of
# input/tether2d/study/ with tether2d and draws Figs. 4.3, 4.4, 4.7-4.22 as PNG files.
#   utils/studies/tether2d.sh --quick /tmp/fig      # ~15 s on 2 cores: 8 tiny runs
#   utils/studies/tether2d.sh docs/figures          # reduced (docs/figures): 64 points, tau 20
#   utils/studies/tether2d.sh --full /tmp/fig       # the 45 decks as written (256 points)
# utils/studies/tether2d.sh --help lists the options.
set -euo pipefail
STUDY=tether2d
APP=tether2d
DEFAULT_RANKS=1   # 24-64 points: one rank per run, two runs at a time, is the faster use of 2 cores
source "$(dirname "${BASH_SOURCE[0]}")/study-lib.sh"

EXPECTED=(
  tether2d_fig4.3_contours_over_time.png tether2d_fig4.4_final_contours_over_Ca.png
  tether2d_fig4.7_contour_length_over_Ca.png tether2d_fig4.8_contour_length_over_lambda.png
  tether2d_fig4.9_contour_length_over_ab.png tether2d_fig4.10_max_contour_length_vs_Ca.png
  tether2d_fig4.11_cell_length_over_Ca.png tether2d_fig4.12_cell_length_over_lambda.png
  tether2d_fig4.13_cell_length_over_ab.png tether2d_fig4.14_max_cell_length_vs_Ca.png
  tether2d_fig4.15_tether_force_over_Ca.png tether2d_fig4.16_tether_force_over_lambda.png
  tether2d_fig4.17_tether_force_over_ab.png tether2d_fig4.18_max_tether_force_vs_Ca.png
  tether2d_fig4.19_cell_velocity_over_Ca.png tether2d_fig4.20_cell_velocity_over_lambda.png
  tether2d_fig4.21_cell_velocity_over_ab.png tether2d_fig4.22_stress_along_s.png
)

deck() { echo "input/tether2d/study/ab${1}_lambda${2}_ca${3}.xml"; }

study_runs() {
  local ab lambda ca settings=()
  case "$mode" in
    quick)
      # 24 points, a short preparation, tau = 1 tethered: seconds per run.
      settings=(--set "Cell/Number of points=24" --set "Tether/Minimum preparation time=0.2"
                --set "Tether/Maximum preparation time=0.4" --set "Time integration/End time=1"
                --set "Output/Interval=0.05" --set "Output/Snapshot every=4")
      for ab in 1 0.25; do for lambda in 1 10; do for ca in 0.01 0.25; do
        queue_run "ab${ab}_lambda${lambda}_ca${ca}" "$(deck $ab $lambda $ca)" "${settings[@]}"
      done; done; done ;;
    reduced)
      # 64 points (the thesis: 256), preparation at most tau = 5, tau = 20 tethered (the
      # thesis: to equilibrium, up to 200); lambda = 10 at the two ends of the Ca range only.
      # a/b = 0.25 is tethered at the sharp lower end of its contour: at 64 points the force
      # right after tethering is a transient (0.01 tau) that is the summary's F_max at
      # Ca = 0.025, 0.05, 0.25 (docs/tether2d-results.md, a/b = 0.25); at 256 points it stays below
      # the later maximum.
      settings=(--set "Cell/Number of points=64" --set "Tether/Maximum preparation time=5"
                --set "Time integration/End time=20" --set "Output/Interval=0.25" --set "Output/Snapshot every=8")
      for ab in 1 0.25; do for ca in 0.01 0.025 0.05 0.1 0.25; do
        queue_run "ab${ab}_lambda1_ca${ca}" "$(deck $ab 1 $ca)" "${settings[@]}"
      done; done
      for ca in 0.01 0.25; do
        queue_run "ab1_lambda10_ca${ca}" "$(deck 1 10 $ca)" "${settings[@]}"
      done ;;
    full)
      # The cheap runs first (lambda = 1, then high Ca, whose steps are longest), so that a
      # study stopped part way has whole figures over Ca and a/b at lambda = 1.
      for lambda in 1 10 5; do for ab in 1 0.5 0.25; do for ca in 0.25 0.1 0.05 0.025 0.01; do
        queue_run "ab${ab}_lambda${lambda}_ca${ca}" "$(deck $ab $lambda $ca)"
      done; done; done ;;
  esac
}

study_figures() {
  draw tether2d_contours.py
  draw tether2d_histories.py
  draw tether2d_table.py   # FIGDIR/tether2d_table.md: the key numbers of every run
}

figure_study_main "$@"
