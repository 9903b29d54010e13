# twocell3d: the two-cell app (thesis Chapter 6) at mesh level 1 on 1 and 2 ranks, a golden
# short run of the demo, the stop of cells coming too close, and touching cells rejected.
set(_twodecks ${PROJECT_SOURCE_DIR}/input/twocell3d)
set(_twoout ${CMAKE_CURRENT_BINARY_DIR}/twocell3d)
set(_twolevel1 --set "Cells/Cell 0/Mesh level=1" --set "Cells/Cell 1/Mesh level=1")

# Golden numbers of the demo deck (two cells side by side at h/a = 1.25, heights fixed):
# fixed RK4 steps, so only round-off (~1e-13) and deliberate changes of the discretisation
# (>= 1e-6) move them; 1e-8 absolute as for cell3d (1e-7 for the wall stress, a difference
# quotient). Cell 1 is cell 0 mirrored in z: the same D12 and opposite z.
capsula_add_mpi_command_test(regression_twocell3d_demo
  COMMAND $<TARGET_FILE:twocell3d> ${_twodecks}/demo.xml --output ${_twoout}/demo ${_twolevel1}
          --set "Time integration/Method=RK4" --set "Time integration/Initial step=0.01"
          --set "Time integration/End time=0.05" --set "Output/Interval=0.05"
  LABELS regression TIMEOUT 300)
set_tests_properties(regression_twocell3d_demo PROPERTIES FIXTURES_SETUP twocell3d_demo)
add_test(NAME regression_twocell3d_demo_golden
  COMMAND check_metrics expect ${_twoout}/demo/metrics.csv -
    D12_0=0.025131614455724833:1e-8 D12_1=0.02513161445572483:1e-8 y_c_0=1.2499999927190684:1e-8
    z_c_0=1.2500025070225058:1e-8 z_c_1=-1.2500025070225054:1e-8 volume_0=4.179539740660264:1e-8
    u_slip_0=0.020110597095194915:1e-8 mean_shear_stress_0=0.1914832387565429:1e-8
    dz_0_1=2.500005014045011:1e-8 dw_0_1=0.0003237952794749917:1e-8 gap_0_1=0.499975641314614:1e-8
    wall_stress_max=1.1578598492213377:1e-7)
set_tests_properties(regression_twocell3d_demo_golden PROPERTIES
  FIXTURES_REQUIRED twocell3d_demo LABELS "mpi;regression")

# The same adaptive (RKF45) two-cell run on 1 and 2 ranks agrees to round-off (1e-12
# relative, as cell3d: every rank computes whole rows of the boundary-integral equation).
set(_twoshort ${_twolevel1} --set "Time integration/End time=0.2" --set "Output/Interval=0.1")
add_test(NAME regression_twocell3d_one_rank
  COMMAND twocell3d ${_twodecks}/demo.xml --output ${_twoout}/one_rank ${_twoshort})
set_tests_properties(regression_twocell3d_one_rank PROPERTIES
  FIXTURES_SETUP twocell3d_ranks LABELS "mpi;regression")
capsula_add_mpi_command_test(regression_twocell3d_two_ranks
  COMMAND $<TARGET_FILE:twocell3d> ${_twodecks}/demo.xml --output ${_twoout}/two_ranks ${_twoshort}
  LABELS regression TIMEOUT 300)
set_tests_properties(regression_twocell3d_two_ranks PROPERTIES FIXTURES_SETUP twocell3d_ranks)
add_test(NAME regression_twocell3d_ranks_agree
  COMMAND check_metrics same ${_twoout}/one_rank/metrics.csv ${_twoout}/two_ranks/metrics.csv 1e-12)
set_tests_properties(regression_twocell3d_ranks_agree PROPERTIES
  FIXTURES_REQUIRED twocell3d_ranks LABELS "mpi;regression")

# The ten cells near the wall of the suspension deck at level 2 with the treecode far field
# (its default tolerance 1e-5) on 1 and 2 ranks. The ranks split the targets, so the target
# blocks of the float single-layer sums and the clusters each block accepts differ: the runs
# agree to the rounding of those sums, not bit for bit (measured 3.6e-8 relative, in
# max_shear_stress). 1e-6 is ten times below the treecode's tolerance and far below what a
# cluster lost or counted twice on one rank moves (~1e-2).
set(_tenout ${_twoout}/ten_treecode)
set(_tensets --set "Time integration/Method=RKF45" --set "Time integration/Tolerance=1e-6"
    --set "Time integration/End time=0.01" --set "Output/Interval=0.005"
    --set "Output/Wall shear stress/Enabled=false" --set "Output/Snapshots=false")
foreach(_cell RANGE 9)
  list(APPEND _tensets --set "Cells/Cell ${_cell}/Mesh level=2")
endforeach()
add_test(NAME regression_twocell3d_treecode_one_rank
  COMMAND twocell3d ${_twodecks}/suspension/ten-cells-wall.xml --output ${_tenout}/one_rank ${_tensets})
set_tests_properties(regression_twocell3d_treecode_one_rank PROPERTIES
  FIXTURES_SETUP twocell3d_treecode_ranks LABELS "mpi;regression")
capsula_add_mpi_command_test(regression_twocell3d_treecode_two_ranks
  COMMAND $<TARGET_FILE:twocell3d> ${_twodecks}/suspension/ten-cells-wall.xml --output ${_tenout}/two_ranks ${_tensets}
  LABELS regression TIMEOUT 300)
set_tests_properties(regression_twocell3d_treecode_two_ranks PROPERTIES FIXTURES_SETUP twocell3d_treecode_ranks)
add_test(NAME regression_twocell3d_treecode_ranks_agree
  COMMAND check_metrics same ${_tenout}/one_rank/metrics.csv ${_tenout}/two_ranks/metrics.csv 1e-6)
set_tests_properties(regression_twocell3d_treecode_ranks_agree PROPERTIES
  FIXTURES_REQUIRED twocell3d_treecode_ranks LABELS "mpi;regression")

# Cell 0 above and behind cell 1 (centres 1.8 apart in x and y): the upper cell moves
# faster and catches up; the gap of the level-1 surfaces starts at 0.572 and shrinks by
# ~0.25 per unit time (tests/unit/scene/test_two_cells.cpp). With 'Cells/Minimum gap' 0.565
# the run stops within a few steps on 2 ranks, naming the cells, the gap and the time, exit 0.
capsula_add_mpi_command_test(app_twocell3d_stops_when_too_close
  COMMAND $<TARGET_FILE:twocell3d> ${_twodecks}/demo.xml --output ${_twoout}/too_close ${_twolevel1}
          --set "Cells/Cell 0/Center={-1.8, 3.05, 0}" --set "Cells/Cell 1/Center={0, 1.25, 0}"
          --set "Cells/Minimum gap=0.565" --set "Output/Wall shear stress/Enabled=false"
  LABELS app TIMEOUT 300)
set_tests_properties(app_twocell3d_stops_when_too_close PROPERTIES FIXTURES_SETUP twocell3d_too_close
  PASS_REGULAR_EXPRESSION "Stopped at t = [0-9.e-]+: the surfaces of 'Cells/Cell 0' and 'Cells/Cell 1' are [0-9.e-]+ apart, less than 'Cells/Minimum gap' = 0.565")
# The last row is the state where it stopped: just below the minimum gap.
add_test(NAME app_twocell3d_too_close_keeps_outputs
  COMMAND check_metrics expect ${_twoout}/too_close/metrics.csv - gap_0_1=0.5625:0.0025)
set_tests_properties(app_twocell3d_too_close_keeps_outputs PROPERTIES LABELS app
  FIXTURES_REQUIRED twocell3d_too_close)
add_test(NAME app_twocell3d_too_close_in_summary COMMAND ${CMAKE_COMMAND} -E cat ${_twoout}/too_close/summary.json)
set_tests_properties(app_twocell3d_too_close_in_summary PROPERTIES LABELS app
  FIXTURES_REQUIRED twocell3d_too_close PASS_REGULAR_EXPRESSION "\"status\": \"too close\"")
add_test(NAME app_twocell3d_too_close_keeps_checkpoint
  COMMAND ${CMAKE_COMMAND} -E md5sum ${_twoout}/too_close/checkpoint.h5)
set_tests_properties(app_twocell3d_too_close_keeps_checkpoint PROPERTIES LABELS app
  FIXTURES_REQUIRED twocell3d_too_close)

# Touching cells (centres 2 radii apart) are rejected before any work.
add_test(NAME app_twocell3d_rejects_touching_cells
  COMMAND twocell3d ${_twodecks}/demo.xml --output ${_twoout}/rejected ${_twolevel1}
          --set "Cells/Cell 0/Center={0, 1.25, 1}" --set "Cells/Cell 1/Center={0, 1.25, -1}")
set_tests_properties(app_twocell3d_rejects_touching_cells PROPERTIES LABELS app
  PASS_REGULAR_EXPRESSION "'Cells/Cell 0' and 'Cells/Cell 1' touch at the start: their surfaces are [0-9.e-]+ apart")

# The sweep helper gathers the demo run above (OUT/<deck folder>/<deck name> is where the
# regression wrote it) into one table: one row per cell with the start geometry (h0 = 1.25,
# centres 2.5 apart in z, surfaces 0.5 apart) and the pair columns filled (distance 2.5000...).
add_test(NAME app_twocell3d_sweep_gathers_the_table
  COMMAND /usr/bin/python3 ${PROJECT_SOURCE_DIR}/utils/studies/twocell3d_sweep.py --gather-only
          --out ${CMAKE_CURRENT_BINARY_DIR} --table ${_twoout}/sweep.csv ${_twodecks}/demo.xml)
set_tests_properties(app_twocell3d_sweep_gathers_the_table PROPERTIES LABELS app
  FIXTURES_REQUIRED twocell3d_demo FIXTURES_SETUP twocell3d_sweep PASS_REGULAR_EXPRESSION "sweep.csv \\(2 rows\\)")
add_test(NAME app_twocell3d_sweep_table_content COMMAND ${CMAKE_COMMAND} -E cat ${_twoout}/sweep.csv)
set_tests_properties(app_twocell3d_sweep_table_content PROPERTIES LABELS app FIXTURES_REQUIRED twocell3d_sweep
  PASS_REGULAR_EXPRESSION "demo.xml,finished,0.05,final,1,1.25,0.0,0.0,2.5,0.5,[^\n]*,2\\.5000[0-9]+,")

# Cells of two kinds in one scene: Cell 0 with its own 'Viscosity ratio' 5, Cell 1 with the
# flow's 1 (tests/unit/scene/test_scene.cpp checks each moves as alone with its ratio). The
# run reports both ratios; 1 and 2 ranks agree to 1e-10 as the lambda = 5 cell3d runs do (the
# GMRES inner products are summed in a rank-dependent order).
set(_mixed ${_twoshort} --set "Cells/Cell 0/Viscosity ratio=5")
add_test(NAME regression_twocell3d_mixed_ratios_one_rank
  COMMAND twocell3d ${_twodecks}/demo.xml --output ${_twoout}/mixed_one_rank ${_mixed})
set_tests_properties(regression_twocell3d_mixed_ratios_one_rank PROPERTIES
  FIXTURES_SETUP twocell3d_mixed_ratios LABELS "mpi;regression"
  PASS_REGULAR_EXPRESSION "viscosity ratio 5 \\(Cell 0\\), 1 \\(Cell 1\\): double layer.*Done: finished at t = 0\\.2")
capsula_add_mpi_command_test(regression_twocell3d_mixed_ratios_two_ranks
  COMMAND $<TARGET_FILE:twocell3d> ${_twodecks}/demo.xml --output ${_twoout}/mixed_two_ranks ${_mixed}
  LABELS regression TIMEOUT 300)
set_tests_properties(regression_twocell3d_mixed_ratios_two_ranks PROPERTIES FIXTURES_SETUP twocell3d_mixed_ratios)
add_test(NAME regression_twocell3d_mixed_ratios_ranks_agree
  COMMAND check_metrics same ${_twoout}/mixed_one_rank/metrics.csv ${_twoout}/mixed_two_ranks/metrics.csv 1e-10)
set_tests_properties(regression_twocell3d_mixed_ratios_ranks_agree PROPERTIES
  FIXTURES_REQUIRED twocell3d_mixed_ratios LABELS "mpi;regression")
