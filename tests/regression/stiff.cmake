# The stiff time integrators in cell3d (docs/stiff-integration.md): golden numbers of short
# ROS34PW2 and Auto runs of the nearly rigid Goldman capsule (level 1, Ca = 0.005, to t = 0.1),
# 1 and 2 ranks bit for bit, a restart in the stiff phase bit for bit, Auto staying explicit
# on the soft demo capsule, and the inputs and failures that must stop with a clear message.
#
# Golden numbers: adaptive runs, so they depend on every accept/reject decision and on the
# GMRES iterations of the stage solves (stopped at 0.01 x the 1e-4 tolerance, their error's
# largest coordinate checked against twice that): a change of
# the Jacobian, the preconditioner or the method moves D12 and u_slip by 1e-6 or more;
# round-off by ~1e-13. Tolerance 1e-7 absolute (D12 ~0.0125, u_slip ~0.118).
set(_stiff ${CMAKE_CURRENT_BINARY_DIR}/stiff)
set(_goldman ${PROJECT_SOURCE_DIR}/input/cell3d/validation/goldman-rigid-h1.5431.xml
  --set "Cells/Cell 0/Mesh level=1" --set "Flow/Capillary number=0.005" --set "Time integration/Tolerance=1e-4"
  --set "Time integration/End time=0.1" --set "Output/Snapshots=false")

# ROS34PW2 from the start: 16 steps where RKF45's stability limit holds the step at 7e-4
# (about 140 steps).
add_test(NAME regression_stiff_ros34pw2
  COMMAND cell3d ${_goldman} --set "Time integration/Method=ROS34PW2" --output ${_stiff}/ros34pw2)
set_tests_properties(regression_stiff_ros34pw2 PROPERTIES LABELS "regression" FIXTURES_SETUP stiff_ros34pw2
  PASS_REGULAR_EXPRESSION "stiff Jacobian: single layer of the membranes' tangent stiffness.*Done: finished at t = 0\\.1 after 16 steps")
add_test(NAME regression_stiff_ros34pw2_golden
  COMMAND check_metrics expect ${_stiff}/ros34pw2/metrics.csv 0 D12=0.012489998797712103:1e-7
          u_slip=0.11814813374603306:1e-7 y_c=1.5430999830990961:1e-7 volume=4.179530185811981:1e-7)
set_tests_properties(regression_stiff_ros34pw2_golden PROPERTIES LABELS "regression" FIXTURES_REQUIRED stiff_ros34pw2)

# Auto: RKF45 until the stability limit has held it 5 steps (dt = 7e-4), then a trial step
# of ROS34PW2 of 5.4 times that meets the tolerance and ROS34PW2 goes on. On 1 and 2 ranks:
# the stage solves' Krylov vectors are replicated, so the runs agree bit for bit.
add_test(NAME regression_stiff_auto_one_rank
  COMMAND cell3d ${_goldman} --set "Time integration/Method=Auto" --output ${_stiff}/auto_one_rank)
set_tests_properties(regression_stiff_auto_one_rank PROPERTIES LABELS "regression" FIXTURES_SETUP stiff_auto
  PASS_REGULAR_EXPRESSION "switched to ROS34PW2: the stability limit held RKF45 at dt = 0\\.000703 for 5 steps")
add_test(NAME regression_stiff_auto_golden
  COMMAND check_metrics expect ${_stiff}/auto_one_rank/metrics.csv 0 D12=0.012490048312274283:1e-7
          u_slip=0.11814672363817502:1e-7 y_c=1.5430999918750896:1e-7 volume=4.179535731914041:1e-7)
set_tests_properties(regression_stiff_auto_golden PROPERTIES LABELS "regression" FIXTURES_REQUIRED stiff_auto)
capsula_add_mpi_command_test(regression_stiff_auto_two_ranks
  COMMAND $<TARGET_FILE:cell3d> ${_goldman} --set "Time integration/Method=Auto" --output ${_stiff}/auto_two_ranks
  LABELS regression TIMEOUT 300)
set_tests_properties(regression_stiff_auto_two_ranks PROPERTIES FIXTURES_SETUP stiff_auto_ranks)
add_test(NAME regression_stiff_auto_ranks_agree
  COMMAND check_metrics same ${_stiff}/auto_one_rank/metrics.csv ${_stiff}/auto_two_ranks/metrics.csv 0)
set_tests_properties(regression_stiff_auto_ranks_agree PROPERTIES LABELS "mpi;regression"
  FIXTURES_REQUIRED "stiff_auto;stiff_auto_ranks")

# Restart in the stiff phase on 2 ranks: stopped at t = 0.05 (the deck's first output, so the
# stop lands where the uninterrupted run's output does), continued to 0.1: bit for bit.
capsula_add_mpi_command_test(regression_stiff_restart_first_half
  COMMAND $<TARGET_FILE:cell3d> ${_goldman} --set "Time integration/Method=Auto"
          --set "Time integration/End time=0.05" --output ${_stiff}/restarted
  LABELS regression TIMEOUT 300)
set_tests_properties(regression_stiff_restart_first_half PROPERTIES FIXTURES_SETUP stiff_restart_half)
capsula_add_mpi_command_test(regression_stiff_restart_second_half
  COMMAND $<TARGET_FILE:cell3d> ${_goldman} --set "Time integration/Method=Auto" --restart ${_stiff}/restarted
  LABELS regression TIMEOUT 300)
set_tests_properties(regression_stiff_restart_second_half PROPERTIES
  FIXTURES_REQUIRED stiff_restart_half FIXTURES_SETUP stiff_restart)
add_test(NAME regression_stiff_restart_reproduces
  COMMAND check_metrics same ${_stiff}/auto_two_ranks/metrics.csv ${_stiff}/restarted/metrics.csv 0)
set_tests_properties(regression_stiff_restart_reproduces PROPERTIES LABELS "mpi;regression"
  FIXTURES_REQUIRED "stiff_restart;stiff_auto_ranks")

# Stage solves that start from the step's kept products of J~ ('Solver/Stiff/Recycled
# products' = 40): fewer GMRES iterations (1.2 per solve against 2.4) for the same steps'
# accuracy; the kept products are forgotten at every step's linearisation, so 1 and 2 ranks
# and a restart at t = 0.05 (2 ranks) give the same bits as the uninterrupted run. Golden
# numbers as above (1e-7); against the run without kept products (the goldens of
# regression_stiff_ros34pw2) D12 and u_slip differ by 7e-6 and 4e-5, within the 1e-4
# tolerance's effect on them (a wrong residual would move them by O(1e-2)).
set(_recycled --set "Time integration/Method=ROS34PW2" --set "Solver/Stiff/Recycled products=40")
add_test(NAME regression_stiff_recycled_one_rank
  COMMAND cell3d ${_goldman} ${_recycled} --output ${_stiff}/recycled_one_rank)
set_tests_properties(regression_stiff_recycled_one_rank PROPERTIES LABELS "regression"
  FIXTURES_SETUP stiff_recycled PASS_REGULAR_EXPRESSION "Done: finished at t = 0\\.1")
add_test(NAME regression_stiff_recycled_golden
  COMMAND check_metrics expect ${_stiff}/recycled_one_rank/metrics.csv 0 D12=0.012486899849350076:1e-7
          u_slip=0.11812414701026919:1e-7 y_c=1.5430996012843003:1e-7 volume=4.179449867143834:1e-7)
set_tests_properties(regression_stiff_recycled_golden PROPERTIES LABELS "regression" FIXTURES_REQUIRED stiff_recycled)
add_test(NAME regression_stiff_recycled_near_plain_solves
  COMMAND check_metrics expect ${_stiff}/recycled_one_rank/metrics.csv 0 D12=0.012489998797712103:1e-4
          u_slip=0.11814813374603306:1e-4)
set_tests_properties(regression_stiff_recycled_near_plain_solves PROPERTIES LABELS "regression"
  FIXTURES_REQUIRED stiff_recycled)
capsula_add_mpi_command_test(regression_stiff_recycled_two_ranks
  COMMAND $<TARGET_FILE:cell3d> ${_goldman} ${_recycled} --output ${_stiff}/recycled_two_ranks
  LABELS regression TIMEOUT 300)
set_tests_properties(regression_stiff_recycled_two_ranks PROPERTIES FIXTURES_SETUP stiff_recycled_ranks)
add_test(NAME regression_stiff_recycled_ranks_agree
  COMMAND check_metrics same ${_stiff}/recycled_one_rank/metrics.csv ${_stiff}/recycled_two_ranks/metrics.csv 0)
set_tests_properties(regression_stiff_recycled_ranks_agree PROPERTIES LABELS "mpi;regression"
  FIXTURES_REQUIRED "stiff_recycled;stiff_recycled_ranks")
capsula_add_mpi_command_test(regression_stiff_recycled_restart_first_half
  COMMAND $<TARGET_FILE:cell3d> ${_goldman} ${_recycled} --set "Time integration/End time=0.05"
          --output ${_stiff}/recycled_restarted
  LABELS regression TIMEOUT 300)
set_tests_properties(regression_stiff_recycled_restart_first_half PROPERTIES FIXTURES_SETUP stiff_recycled_half)
capsula_add_mpi_command_test(regression_stiff_recycled_restart_second_half
  COMMAND $<TARGET_FILE:cell3d> ${_goldman} ${_recycled} --restart ${_stiff}/recycled_restarted
  LABELS regression TIMEOUT 300)
set_tests_properties(regression_stiff_recycled_restart_second_half PROPERTIES
  FIXTURES_REQUIRED stiff_recycled_half FIXTURES_SETUP stiff_recycled_restart)
add_test(NAME regression_stiff_recycled_restart_reproduces
  COMMAND check_metrics same ${_stiff}/recycled_two_ranks/metrics.csv ${_stiff}/recycled_restarted/metrics.csv 0)
set_tests_properties(regression_stiff_recycled_restart_reproduces PROPERTIES LABELS "mpi;regression"
  FIXTURES_REQUIRED "stiff_recycled_restart;stiff_recycled_ranks")

# Auto on the soft demo capsule (Ca = 0.3, level 1, to t = 1): its trial steps of ROS34PW2
# meet at best the tolerance, not half of it, so RKF45 stays in use.
add_test(NAME regression_stiff_auto_stays_explicit_when_soft
  COMMAND cell3d ${PROJECT_SOURCE_DIR}/input/cell3d/demo.xml --set "Cells/Cell 0/Mesh level=1"
          --set "Time integration/Method=Auto" --set "Time integration/End time=1" --set "Output/Snapshots=false"
          --set "Output/Wall shear stress/Enabled=false" --output ${_stiff}/soft)
set_tests_properties(regression_stiff_auto_stays_explicit_when_soft PROPERTIES LABELS "regression"
  PASS_REGULAR_EXPRESSION "Done: finished at t = 1" FAIL_REGULAR_EXPRESSION "switched to")

# The contour-integral load has no tangent stiffness: refused at start-up, naming the key.
add_test(NAME app_stiff_contour_integral_is_refused
  COMMAND cell3d ${_goldman} --set "Time integration/Method=ROS34PW2"
          --set "Cells/Cell 0/Membrane forces=Contour integral" --output ${_stiff}/refused)
set_tests_properties(app_stiff_contour_integral_is_refused PROPERTIES LABELS "app"
  PASS_REGULAR_EXPRESSION "error: The stiff time integration .*'Cells/Cell 0/Membrane forces' = 'Contour integral' is not an energy gradient")

# Stage solves that cannot converge (2 unpreconditioned GMRES iterations at Ca = 0.002)
# reject every step down to 'Minimum step': the run stops with the last good checkpoint and
# names the keys to change.
add_test(NAME app_stiff_unconverged_solves_stop_the_run
  COMMAND cell3d ${_goldman} --set "Flow/Capillary number=0.002" --set "Time integration/Method=ROS34PW2"
          --set "Time integration/Initial step=0.01" --set "Time integration/Minimum step=0.001"
          --set "Solver/Stiff/Preconditioner=None" --set "Solver/Stiff/Maximum iterations=2"
          --output ${_stiff}/unconverged)
set_tests_properties(app_stiff_unconverged_solves_stop_the_run PROPERTIES LABELS "app"
  PASS_REGULAR_EXPRESSION "error: Time integration failed at t = 0: the solve of stage 1 stopped after 2 iterations.*raise 'Solver/Stiff/Maximum iterations' = 2")

# The two-cell gap stop with the stiff method (the twocell3d demo's catching-up pair,
# tests/regression/twocell3d.cmake), on 2 ranks: the stop comes after the step that crossed
# 'Cells/Minimum gap', with the state there written, as with RKF45.
capsula_add_mpi_command_test(app_stiff_twocell3d_stops_when_too_close
  COMMAND $<TARGET_FILE:twocell3d> ${PROJECT_SOURCE_DIR}/input/twocell3d/demo.xml --output ${_stiff}/too_close
          --set "Cells/Cell 0/Mesh level=1" --set "Cells/Cell 1/Mesh level=1"
          --set "Cells/Cell 0/Center={-1.8, 3.05, 0}" --set "Cells/Cell 1/Center={0, 1.25, 0}"
          --set "Cells/Minimum gap=0.565" --set "Output/Wall shear stress/Enabled=false"
          --set "Time integration/Method=ROS34PW2" --set "Time integration/Tolerance=1e-4"
  LABELS app TIMEOUT 300)
set_tests_properties(app_stiff_twocell3d_stops_when_too_close PROPERTIES FIXTURES_SETUP stiff_too_close
  PASS_REGULAR_EXPRESSION "Stopped at t = [0-9.e-]+: the surfaces of 'Cells/Cell 0' and 'Cells/Cell 1' are [0-9.e-]+ apart, less than 'Cells/Minimum gap' = 0.565")
add_test(NAME app_stiff_twocell3d_too_close_keeps_outputs
  COMMAND check_metrics expect ${_stiff}/too_close/metrics.csv - gap_0_1=0.5625:0.0025)
set_tests_properties(app_stiff_twocell3d_too_close_keeps_outputs PROPERTIES LABELS app
  FIXTURES_REQUIRED stiff_too_close)

# A hard case that must stay stable with steps ~200 times the explicit limit: the nearly
# rigid neo-Hookean capsule (Ca = 0.002, h/a = 1.543081, level 1, no prestress) with
# ROS34PW2 at 1e-4 to t = 3. Measured: 63 steps (RKF45's stability limit: ~3e-4, ~10^4
# steps), D12 0.005094-0.005096 from t = 0.5 on, volume drift <= 2.4e-5, smallest angle
# 55.27 (55.57 at rest), smallest tension -0.009. Bounds: a stiff mode growing under the
# large steps would fold the mesh (the angle falls) and break the volume; 4x the measured
# drift, the angle within 1.3 degrees of rest, 80 steps.
add_test(NAME stability_stiff_rigid_capsule
  COMMAND cell3d ${PROJECT_SOURCE_DIR}/input/cell3d/validation/goldman-rigid-h1.5431.xml
          --set "Cells/Cell 0/Mesh level=1" --set "Flow/Capillary number=0.002"
          --set "Cells/Cell 0/Center={0.0, 1.543081, 0.0}" --set "Time integration/Method=ROS34PW2"
          --set "Time integration/Tolerance=1e-4" --set "Time integration/End time=3" --set "Output/Interval=0.5"
          --set "Output/Snapshots=false" --output ${_stiff}/rigid_capsule)
set_tests_properties(stability_stiff_rigid_capsule PROPERTIES LABELS stability FIXTURES_SETUP stiff_rigid_capsule)
add_test(NAME stability_stiff_rigid_capsule_bounds
  COMMAND check_metrics within ${_stiff}/rigid_capsule/metrics.csv volume_change=-1e-4:1e-4
          min_angle_deg=54.3:60 D12=0:0.0052 step=0:80)
set_tests_properties(stability_stiff_rigid_capsule_bounds PROPERTIES LABELS stability
  FIXTURES_REQUIRED stiff_rigid_capsule)
add_test(NAME stability_stiff_rigid_capsule_trend
  COMMAND check_metrics expect ${_stiff}/rigid_capsule/metrics.csv 0 time=3:1e-12 D12=0.005095:2e-5
          u_slip=0.1204:0.002)
set_tests_properties(stability_stiff_rigid_capsule_trend PROPERTIES LABELS stability
  FIXTURES_REQUIRED stiff_rigid_capsule)
