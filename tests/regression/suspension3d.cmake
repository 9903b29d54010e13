# suspension3d, scaled down from the demo deck (input/suspension3d/demo.xml): two level-1 red
# cells at viscosity ratio 5 (hematocrit 0.054 of the box 5 x 6 x 5, 0.05396 reached) and one
# platelet at viscosity ratio 1 (shear modulus 2, so that RK4 steps of 0.0025 are stable) in
# the periodic Poiseuille channel, two steps to t = 0.005: the placement, the double layer
# with cells of two viscosity ratios, the suspension's columns, on 1 and 2 ranks and across a
# restart. The GMRES tolerance 1e-6 and the Ewald sums at 1e-4 keep a run near 20 s.
#
# Goldens (measured at the last row): the placement fixes the first red cell's x_c and the
# platelet's height to round-off (a change of the random sequence or of the body shapes moves
# them by O(1)); the per-type means, the cell-free layers and the relative viscosity to 1e-8.
# A red cell at viscosity ratio 1 moves u_mean_red_cell by 1e-3 in these two steps, a wrong
# per-type sum by O(1). The relative viscosity is 1.0345 at t = 0, where the membranes carry no
# load and the red cells' double layer alone makes it: without that term it would be 1.
set(_suspension_out ${CMAKE_CURRENT_BINARY_DIR}/suspension3d)
set(_suspension_run ${PROJECT_SOURCE_DIR}/input/suspension3d/demo.xml --set "Domain/Periodic length x=5"
    --set "Domain/Periodic length z=5" --set "Suspension/Hematocrit=0.054"
    --set "Suspension/Cell types/platelet/Count=1" --set "Suspension/Cell types/platelet/Shear modulus=2"
    --set "Suspension/Cell types/red_cell/Viscosity ratio=5" --set "Time integration/Method=RK4"
    --set "Time integration/Initial step=0.0025" --set "Output/Interval=0.0025" --set "Solver/Tolerance=1e-6"
    --set "Operator/PeriodicChannel/Tolerance=1e-4")
add_test(NAME regression_suspension3d_one_rank
  COMMAND suspension3d ${_suspension_run} --set "Time integration/End time=0.005"
          --output ${_suspension_out}/one_rank)
set_tests_properties(regression_suspension3d_one_rank PROPERTIES FIXTURES_SETUP suspension3d_one_rank
  LABELS regression)
add_test(NAME regression_suspension3d_goldens
  COMMAND check_metrics expect ${_suspension_out}/one_rank/metrics.csv -
          time=0.005:1e-12 x_c_0=0.11182523615569401:1e-8 y_mean_platelet=3.8974966090081313:1e-8
          u_mean_red_cell=1.2388498494694713:1e-8 y_mean_red_cell=2.172753100719201:1e-8
          u_mean_platelet=1.3005188881056886:1e-8 cell_free_layer_lower=2.6245625589077926:1e-8
          cell_free_layer_upper=2.95962676998557:1e-8 relative_viscosity=1.0359125729696543:1e-8)
set_tests_properties(regression_suspension3d_goldens PROPERTIES FIXTURES_REQUIRED suspension3d_one_rank
  LABELS regression)
# 1 vs 2 ranks: `<name>_two_ranks` runs the case of `<name>` (its output folder `<case>`,
# its fixture suspension3d_<case>, the extra arguments after the tolerance) on 2 ranks, and
# `<name>_one_and_two_ranks_agree` holds every column below to `tolerance` between the two.
function(_suspension3d_on_two_ranks name case tolerance)
  set(columns x_c_0 x_c_2 y_c_0 y_c_2 D12_0 u_mean_red_cell u_mean_platelet cell_free_layer_lower
      cell_free_layer_upper relative_viscosity)
  list(TRANSFORM columns APPEND "=0:${tolerance}")
  capsula_add_mpi_command_test(${name}_two_ranks
    COMMAND $<TARGET_FILE:suspension3d> ${_suspension_run} --set "Time integration/End time=0.005" ${ARGN}
            --output ${_suspension_out}/${case}_two_ranks
    LABELS regression TIMEOUT 600)
  set_tests_properties(${name}_two_ranks PROPERTIES FIXTURES_SETUP suspension3d_${case}_two_ranks)
  add_test(NAME ${name}_one_and_two_ranks_agree
    COMMAND check_metrics shifted ${_suspension_out}/${case}/metrics.csv
            ${_suspension_out}/${case}_two_ranks/metrics.csv ${columns})
  set_tests_properties(${name}_one_and_two_ranks_agree PROPERTIES
    FIXTURES_REQUIRED "suspension3d_${case};suspension3d_${case}_two_ranks" LABELS "mpi;regression")
endfunction()
# The same cells (placed on every rank from the same seed) and the same motion, to the 1e-8
# margin of the other 1 vs 2 rank comparisons (regression_periodic_crossing).
_suspension3d_on_two_ranks(regression_suspension3d one_rank 1e-8)
# A restart places the same cells again and continues bit for bit: one step, then the second
# from the checkpoint, against the uninterrupted run, every number of metrics.csv equal.
add_test(NAME regression_suspension3d_restart_source
  COMMAND bash -c "rm -rf ${_suspension_out}/restarted && \"$0\" \"$@\"" $<TARGET_FILE:suspension3d>
          ${_suspension_run} --set "Time integration/End time=0.0025" --output ${_suspension_out}/restarted)
set_tests_properties(regression_suspension3d_restart_source PROPERTIES FIXTURES_SETUP suspension3d_restart_source
  LABELS regression)
add_test(NAME regression_suspension3d_restart_continues
  COMMAND suspension3d ${_suspension_run} --set "Time integration/End time=0.005"
          --output ${_suspension_out}/restarted --restart ${_suspension_out}/restarted)
set_tests_properties(regression_suspension3d_restart_continues PROPERTIES
  FIXTURES_REQUIRED suspension3d_restart_source FIXTURES_SETUP suspension3d_restarted LABELS regression)
add_test(NAME regression_suspension3d_restart_is_bit_for_bit
  COMMAND check_metrics same ${_suspension_out}/one_rank/metrics.csv ${_suspension_out}/restarted/metrics.csv 0)
set_tests_properties(regression_suspension3d_restart_is_bit_for_bit PROPERTIES
  FIXTURES_REQUIRED "suspension3d_one_rank;suspension3d_restarted" LABELS regression)
# The same run with 'Solver/Preconditioner' = "Cell blocks" (flexible GMRES, 53 double-layer
# applications against 112): the same equation solved to the same tolerance 1e-6, so the
# same motion within what that tolerance allows. Measured against the plain run: centroids
# and D12 2.9e-9, the mean velocities 4.8e-7 (0.5 x the tolerance), the relative viscosity
# 5e-8, the cell-free layers 1.9e-10. On 2 ranks the blocks are the same and the runs differ
# by the round-off of the distributed sums, carried through GMRES: up to 1e-10 in the
# platelet's velocity (summing the Ewald grids in another order on one rank moves it as much,
# 9e-11). Held to 1e-8 as the plain run: 100 times below the solve's tolerance, which a block
# that differed between the ranks would reach.
add_test(NAME regression_suspension3d_cell_blocks
  COMMAND suspension3d ${_suspension_run} --set "Time integration/End time=0.005"
          --set "Solver/Preconditioner=Cell blocks" --output ${_suspension_out}/cell_blocks)
set_tests_properties(regression_suspension3d_cell_blocks PROPERTIES FIXTURES_SETUP suspension3d_cell_blocks
  LABELS regression)
add_test(NAME regression_suspension3d_cell_blocks_solve_the_same_equation
  COMMAND check_metrics shifted ${_suspension_out}/one_rank/metrics.csv ${_suspension_out}/cell_blocks/metrics.csv
          x_c_0=0:1e-8 x_c_2=0:1e-8 y_c_0=0:1e-8 y_c_2=0:1e-8 D12_0=0:1e-8 u_mean_red_cell=0:2e-6
          u_mean_platelet=0:2e-6 cell_free_layer_lower=0:1e-8 cell_free_layer_upper=0:1e-8
          relative_viscosity=0:5e-7)
set_tests_properties(regression_suspension3d_cell_blocks_solve_the_same_equation PROPERTIES
  FIXTURES_REQUIRED "suspension3d_one_rank;suspension3d_cell_blocks" LABELS regression)
_suspension3d_on_two_ranks(regression_suspension3d_cell_blocks cell_blocks 1e-8
  --set "Solver/Preconditioner=Cell blocks")
