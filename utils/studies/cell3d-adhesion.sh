#!/usr/bin/env bash
# The adhesion study (docs/cell3d-adhesion-results.md): a capsule released 0.03 a above a
# ligand-coated wall (input/cell3d/adhesion/sphere-ligand-wall.xml) with the same molecules at
# every membrane stiffness. Two parts:
#   state/  a near-rigid cell (Ca = 3e-4) over a grid of unstressed off-rates k_off0 / k and
#           reactive compliances gamma / a, and the same cell without adhesion: the regimes of
#           Chang, Tees & Hammer (PNAS 97:11262, 2000) in the plane of k_off0 and gamma;
#   rolling/ one (k_off0, gamma) at several membrane stiffnesses Ca: velocity and contact area
#           against stiffness (the trend of Pawar et al. 2008);
#   shear/  the cell and molecules of rolling/Ca0.003 at other shear rates k: Ca grows with k
#           while the molecules' constants in units of G stay, and their rates in units of k
#           fall as 1 / k.
# Classification, state diagram, rolling figure and tables: utils/plotting/cell3d_adhesion.py.
#   utils/studies/cell3d-adhesion.sh --quick /tmp/fig   # ~1 min on 2 cores: level 1, t = 0.3
#   utils/studies/cell3d-adhesion.sh docs/figures       # reduced: level 2 to t = 10, ~1 h on 2 cores
#   utils/studies/cell3d-adhesion.sh --full /tmp/fig    # level 2 to t = 20
# utils/studies/cell3d-adhesion.sh --help lists the options.
set -euo pipefail
STUDY=cell3d-adhesion
APP=cell3d
DEFAULT_RANKS=1   # level 1-2 meshes: two single-rank runs at a time use 2 cores best
source "$(dirname "${BASH_SOURCE[0]}")/study-lib.sh"

EXPECTED=(cell3d_adhesion_state_diagram.png cell3d_adhesion_rolling.png)

DECK=input/cell3d/adhesion/sphere-ligand-wall.xml

# The molecules in flow units (mu the viscosity, k the shear rate, a the radius): the deck's
# constants at its Ca = 0.3, so a bond's spring is 10 G = 33.3 mu k a and k_B T is 4e-3 G a^2 =
# 0.0133 mu k a^3; the repulsion's strength is 1000 G = 3333 mu k (with 100 G the ~130 bonds
# under a Ca = 3e-4 cell pulled its membrane to 1e-4 a of the wall and the steps collapsed). At
# another Ca the keys (in units of G) are these times Ca / 0.3: the same molecules on a
# stiffer or softer membrane.
DECK_CA=0.3
SPRING_AT_DECK_CA=10
THERMAL_AT_DECK_CA=4e-3
STRENGTH_AT_DECK_CA=1000

# The near-rigid cell: bond forces ~ 0.01-0.02 G a. At Ca = 3e-4 the level-2 cell's volume
# drifts too far (a free cell gains 1.8% by t = 5, growing 2.5-fold per unit time).
RIGID_CA=1e-3
OFF_RATES=(0.01 0.1 1 10)          # k_off0 / k
# gamma / a: Bell forces k_B T / gamma of 44, 4.4, 1.3 and 0.44 mu k a^2, against ~0.7 mu k a^2
# per bond under a firmly held cell (its ~180 bonds share ~120 mu k a^2); below 3e-4 gamma
# changes nothing (1e-4 gives the same bonds as 3e-4 to t = 5).
COMPLIANCES=(3e-4 3e-3 1e-2 3e-2)
# Two published molecules that mediate rolling, on the same cell, placed at a shear rate
# k = 100 / s, a = 4 um, mu = 1 mPa s (mu k a^2 = 1.6 pN) with k_B T = 4.1 pN nm: k_off0 =
# k_r0 / k, and the gamma that gives this study's k_B T (0.0133 mu k a^3) the molecule's Bell
# force k_B T / r_0 (utils/plotting/cell3d_adhesion.py marks the same points from the same
# numbers).
#   E-selectin - sialyl Lewis x (Tees, Waugh & Hammer, Biophys J 80:668, 2001; "in the range
#   required for rolling" by Adhesive Dynamics): k_r0 = 0.82 / s, r_0 = 0.034 nm, a Bell
#   force of 121 pN = 75.4 mu k a^2: k_off0 = 0.0082 k, gamma = 0.0133 / 75.4 a = 1.77e-4 a.
#   L-selectin - PSGL-1 (Evans, Leung, Hammer & Simon, PNAS 98:3784, 2001), the outer barrier,
#   which governs below ~40 pN: k_r0 = 3 / s, r_0 = 0.4 nm, 10.25 pN = 6.41 mu k a^2:
#   k_off0 = 0.03 k, gamma = 2.08e-3 a.
PUBLISHED_MOLECULES=("e-selectin 0.0082 1.77e-4" "l-selectin 0.03 2.08e-3")
ON_RATE=1                          # k_on0 / (k a^2), as in the deck
ROLLING_OFF_RATE=1                 # the rolling series' molecule (a rolling point of the grid)
ROLLING_COMPLIANCE=3e-4
ROLLING_CAS=(0.003 0.01)         # and the grid's own run at RIGID_CA
SHEAR_REFERENCE_CA=0.003           # the shear series' cell: rolling/Ca0.003 at k = k_ref
SHEAR_CAS=(0.001 0.01)             # k / k_ref = Ca / SHEAR_REFERENCE_CA

# molecules CA: the --set arguments of the molecules on a membrane of capillary number CA.
molecules() {
  local ca="$1" scale
  scale=$(awk -v c="$ca" -v d="$DECK_CA" 'BEGIN { printf "%.10g", c / d }')
  printf '%s\n' --set "Flow/Capillary number=$ca" \
    --set "Adhesion/Spring constant=$(awk -v s="$scale" -v v="$SPRING_AT_DECK_CA" 'BEGIN { printf "%.10g", s * v }')" \
    --set "Adhesion/Thermal energy=$(awk -v s="$scale" -v v="$THERMAL_AT_DECK_CA" 'BEGIN { printf "%.10g", s * v }')" \
    --set "Contact/Strength=$(awk -v s="$scale" -v v="$STRENGTH_AT_DECK_CA" 'BEGIN { printf "%.10g", s * v }')"
}

study_runs() {
  local settings=() off gamma ca offs=("${OFF_RATES[@]}") gammas=("${COMPLIANCES[@]}") cas=("${ROLLING_CAS[@]}")
  local shears=("${SHEAR_CAS[@]}") rate
  # Bond patches of 0.17 a and the virtual-work contact load hold a level-2 membrane under
  # the bonds' loads (docs/cell3d.md, "Adhesion"); ROS34PW2 takes the stiff membrane.
  settings=(--set "Contact/Load=Virtual work" --set "Adhesion/Patch radius=0.17"
            --set "Time integration/Method=ROS34PW2" --set "Output/Snapshot stride=10")
  case "$mode" in
    quick)
      # Level 1 to t = 0.3, two corners of the grid, the free cell and one softer cell.
      settings+=(--set "Cells/Cell 0/Mesh level=1" --set "Adhesion/Patch radius=0.3"
                 --set "Time integration/End time=0.3" --set "Output/Checkpoint=false")
      offs=(0.01 10); gammas=(3e-4); cas=(0.01); shears=() ;;
    reduced)
      settings+=(--set "Cells/Cell 0/Mesh level=2" --set "Time integration/End time=10") ;;
    full)
      settings+=(--set "Cells/Cell 0/Mesh level=2" --set "Time integration/End time=20") ;;
  esac
  mapfile -t rigid < <(molecules "$RIGID_CA")
  queue_run "state/free" "$DECK" "${settings[@]}" "${rigid[@]}" --set "Adhesion/Enabled=false"
  for off in "${offs[@]}"; do
    for gamma in "${gammas[@]}"; do
      queue_run "state/koff$off-gamma$gamma" "$DECK" "${settings[@]}" "${rigid[@]}" \
        --set "Adhesion/Off-rate=$off" --set "Adhesion/Reactive compliance=$gamma"
    done
  done
  local molecule name
  for molecule in "${PUBLISHED_MOLECULES[@]}"; do
    [[ "$mode" == quick ]] && break
    read -r name off gamma <<< "$molecule"
    queue_run "state/$name" "$DECK" "${settings[@]}" "${rigid[@]}" \
      --set "Adhesion/Off-rate=$off" --set "Adhesion/Reactive compliance=$gamma"
  done
  for ca in "${cas[@]}"; do
    mapfile -t soft < <(molecules "$ca")
    queue_run "rolling/Ca$ca" "$DECK" "${settings[@]}" "${soft[@]}" \
      --set "Adhesion/Off-rate=$ROLLING_OFF_RATE" --set "Adhesion/Reactive compliance=$ROLLING_COMPLIANCE"
    queue_run "rolling/Ca$ca-free" "$DECK" "${settings[@]}" "${soft[@]}" --set "Adhesion/Enabled=false"
  done
  mapfile -t reference < <(molecules "$SHEAR_REFERENCE_CA")
  for ca in "${shears[@]}"; do
    # The reference molecules and membrane (keys in units of G) at the shear rate Ca / Ca_ref
    # times k_ref: the rates in units of k scale by Ca_ref / Ca.
    rate=$(awk -v c="$ca" -v r="$SHEAR_REFERENCE_CA" 'BEGIN { printf "%.10g", r / c }')
    queue_run "shear/Ca$ca" "$DECK" "${settings[@]}" "${reference[@]}" --set "Flow/Capillary number=$ca" \
      --set "Adhesion/Off-rate=$(awk -v s="$rate" -v v="$ROLLING_OFF_RATE" 'BEGIN { printf "%.10g", s * v }')" \
      --set "Adhesion/On-rate=$(awk -v s="$rate" -v v="$ON_RATE" 'BEGIN { printf "%.10g", s * v }')" \
      --set "Adhesion/Reactive compliance=$ROLLING_COMPLIANCE"
    queue_run "shear/Ca$ca-free" "$DECK" "${settings[@]}" "${reference[@]}" --set "Flow/Capillary number=$ca" \
      --set "Adhesion/Enabled=false"
  done
}

study_figures() {
  draw cell3d_adhesion.py --check-trends --table "$figures/cell3d_adhesion_table.md"
}

figure_study_main "$@"
