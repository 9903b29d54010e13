# cell3d in a box periodic along x and z (docs/domains.md; the kernel PeriodicWall): the demo
# capsule at mesh level 1, RK4 steps of 0.02 to t = 0.4 in a box 4 x 4, once with its centre
# at x = 3.5, so that it crosses the boundary x = L_x = 4 at t ~ 0.3 (shear at its height
# 1.6 carries it ~0.6 by t = 0.4; the surface from t = 0), on 2 ranks, and once 2 behind, at
# x = 1.5, where no node leaves the box, on 1 rank. The box is periodic, so the two runs are
# the same run moved by 2 along x: x_c stays 2 ahead and keeps growing through the boundary
# (positions are never folded), every other metric is the same at every output time. What
# differs is where the points fall on the Ewald grid (the sums' tolerance, 1e-6 of the
# largest velocity, by default, moves each velocity by ~1e-7 of it, mostly the same way in
# both runs) and the ranks' round-off: measured, the runs differ by at most 2.4e-10 (u_slip;
# x_c 7e-12, D12 6e-12, the volume 2e-11), and 1 and 2 ranks by 1.6e-9. 1e-8 leaves a margin
# of 40. A cell folded back into the box, a jump of the near-singular treatment or of x_c at
# the boundary shows as a difference of 1e-3 or more (x_c by 4).
set(_periodic_out ${CMAKE_CURRENT_BINARY_DIR}/periodic)
set(_periodic_run ${PROJECT_SOURCE_DIR}/input/cell3d/demo.xml --set "Cells/Cell 0/Mesh level=1"
    --set "Domain/Periodic length x=4" --set "Domain/Periodic length z=4"
    --set "Output/Wall shear stress/Enabled=false" --set "Time integration/Method=RK4"
    --set "Time integration/Initial step=0.02" --set "Time integration/End time=0.4" --set "Output/Interval=0.04")
capsula_add_mpi_command_test(regression_periodic_crossing
  COMMAND $<TARGET_FILE:cell3d> ${_periodic_run} --output ${_periodic_out}/crossing
          --set "Cells/Cell 0/Center={3.5, 1.6, 0}" --set "Output/Fold into box=true"
  LABELS regression TIMEOUT 600)
set_tests_properties(regression_periodic_crossing PROPERTIES FIXTURES_SETUP periodic_crossing)
add_test(NAME regression_periodic_inside
  COMMAND cell3d ${_periodic_run} --output ${_periodic_out}/inside --set "Cells/Cell 0/Center={1.5, 1.6, 0}")
set_tests_properties(regression_periodic_inside PROPERTIES FIXTURES_SETUP periodic_inside LABELS "mpi;regression")
add_test(NAME regression_periodic_crossing_is_the_run_moved
  COMMAND check_metrics shifted ${_periodic_out}/crossing/metrics.csv ${_periodic_out}/inside/metrics.csv
          x_c=2:1e-8 y_c=0:1e-8 z_c=0:1e-8 D12=0:1e-8 volume=0:1e-8 area=0:1e-8 u_slip=0:1e-8 omega_z=0:1e-8)
set_tests_properties(regression_periodic_crossing_is_the_run_moved PROPERTIES
  FIXTURES_REQUIRED "periodic_crossing;periodic_inside" LABELS "mpi;regression")
# The crossing run draws its snapshots folded ('Output/Fold into box'): the capsule, whose
# nodes reach past x = 4 from the start, is drawn whole with its node mean inside the box
# (at t = 0.4 the unfolded mean is at x = 4.1), while its metrics keep the true travel.
add_test(NAME regression_periodic_crossing_snapshots_are_folded
  COMMAND check_snapshots folded ${_periodic_out}/crossing/snapshots.h5 4 4)
set_tests_properties(regression_periodic_crossing_snapshots_are_folded PROPERTIES
  FIXTURES_REQUIRED periodic_crossing LABELS "mpi;regression")
# x_c grows through the boundary: from 3.5 to 4.0985 at t = 0.4 (the capsule moves at ~1.5);
# 0.05 is far below the 4 a folded x_c would lose.
add_test(NAME regression_periodic_crossing_x_c_grows
  COMMAND check_metrics expect ${_periodic_out}/crossing/metrics.csv 0 x_c=4.0985:0.05)
set_tests_properties(regression_periodic_crossing_x_c_grows PROPERTIES
  FIXTURES_REQUIRED periodic_crossing LABELS "mpi;regression")
