#!/usr/bin/env bash
# The tethered 3D cell against the tethered 2D cell (docs/cell3d-tether-results.md): the
# capsule of input/cell3d/tether/sphere-Ca0.1.xml (tethered at its lowest point, Ca = 0.1) at
# mesh levels 1 and 2, and the 2D study's matching case input/tether2d/study/ab1_lambda1_ca0.1.xml
# (a/b = 1, lambda = 1, Ca = 0.1); draws the force histories, their shapes and the pivoting
# (utils/plotting/cell3d_tether.py) and writes their numbers as a Markdown table.
#   utils/studies/cell3d-tether.sh --quick /tmp/fig   # ~1 min on 2 cores: level 1 to t = 1, 2D with 64 points
#   utils/studies/cell3d-tether.sh docs/figures       # reduced (docs/figures): level 1 to t = 30, level 2 to
#                                                     # t = 10, level 3 to t = 6 (ROS34PW2), the 2D deck as
#                                                     # written: ~1.5 h on 2 shared cores
#   utils/studies/cell3d-tether.sh --full /tmp/fig    # the 3D deck as written (level 2 to t = 20) and the 2D deck
# utils/studies/cell3d-tether.sh --help lists the options.
set -euo pipefail
STUDY=cell3d-tether
APP=cell3d
DEFAULT_RANKS=1   # level 1-2 meshes: single-rank runs side by side use 2 cores best
source "$(dirname "${BASH_SOURCE[0]}")/study-lib.sh"

EXPECTED=(cell3d_tether_force.png)   # and cell3d_tether_shapes.png where the 3D runs keep snapshots

# The 2D case runs with tether2d, straight into RUNS/tether2d-ab1-ca0.1 (the reduced and full
# modes keep a snapshot every tau for the shapes figure).
run_2d() {
  local app2d="$build/apps/tether2d/tether2d" name=tether2d-ab1-ca0.1 start=$SECONDS
  [[ -x "$app2d" ]] || die "no $app2d; build it first (cmake --build $build --target tether2d)"
  rm -rf "${runs:?}/$name"
  if "$app2d" "$here/input/tether2d/study/ab1_lambda1_ca0.1.xml" --output "$runs/$name" "$@" > "$runs/$name.log" 2>&1; then
    echo "  done    $name ($((SECONDS - start)) s)"
  else
    echo "  FAILED  $name: $(grep -m1 -i "error" "$runs/$name.log" | cut -c1-160)"
    echo "$name" >> "$runs/.failed"
    failed_runs=$((failed_runs + 1))
  fi
}

study_runs() {
  local deck=input/cell3d/tether/sphere-Ca0.1.xml
  case "$mode" in
    quick)
      queue_run level1 "$deck" --set "Cells/Cell 0/Mesh level=1" --set "Time integration/End time=1" \
        --set "Output/Checkpoint=false" --set "Output/Snapshots=false"
      run_2d --set "Cell/Number of points=64" --set "Time integration/End time=2" ;;
    reduced)
      queue_run level1 "$deck" --set "Cells/Cell 0/Mesh level=1" --set "Time integration/End time=30"
      queue_run level2 "$deck" --set "Time integration/End time=10"
      # Level 3 with the stiff method: RKF45's stability limit would take ~17 CPU hours.
      queue_run level3 "$deck" --set "Cells/Cell 0/Mesh level=3" --set "Time integration/Method=ROS34PW2" \
        --set "Time integration/End time=6"
      run_2d --set "Output/Snapshot every=2" ;;
    full)
      queue_run level2 "$deck"
      run_2d --set "Output/Snapshot every=2" ;;
  esac
}

study_figures() {
  draw cell3d_tether.py --table "$figures/cell3d_tether_table.md"
}

figure_study_main "$@"
