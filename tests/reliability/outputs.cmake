# Reported metrics that must not depend on output settings: the velocity columns a user reads
# first (u_slip, u_migr) are properties of the state, the same whatever Output/Interval.
set(_interval_runs --set "Cells/Cell 0/Mesh level=1" --set "Time integration/End time=0.3"
  --set "Output/Wall shear stress/Enabled=false")
foreach(_interval 0.05 0.1)
  add_test(NAME reliability_output_interval_${_interval}
    COMMAND $<TARGET_FILE:cell3d> ${_cell3d_demo} ${_interval_runs} --set "Output/Interval=${_interval}"
            --output ${_out}/interval_${_interval})
  set_tests_properties(reliability_output_interval_${_interval} PROPERTIES LABELS reliability
    FIXTURES_SETUP reliability_output_intervals)
endforeach()
# Measured at t = 0.1, 0.2, 0.3: u_slip agrees to 4.6e-7 and u_migr to 9.4e-7 (the step
# sequences differ, each held to Tolerance 1e-5); 1e-5 leaves a 10x margin.
add_test(NAME reliability_slip_velocity_does_not_depend_on_the_output_interval
  COMMAND check_metrics agree ${_out}/interval_0.05/metrics.csv ${_out}/interval_0.1/metrics.csv 1e-5 u_slip u_migr)
# The spline form (thesis Section 3.11.2) does: u_slip_spline differs by 46% at t = 0.1 and
# 3% at t = 0.3. This test passes when the comparison fails, so the one above can tell.
add_test(NAME reliability_spline_slip_velocity_depends_on_the_output_interval
  COMMAND check_metrics agree ${_out}/interval_0.05/metrics.csv ${_out}/interval_0.1/metrics.csv 1e-3 u_slip_spline)
set_tests_properties(reliability_slip_velocity_does_not_depend_on_the_output_interval
  reliability_spline_slip_velocity_depends_on_the_output_interval PROPERTIES LABELS reliability
  FIXTURES_REQUIRED reliability_output_intervals)
set_tests_properties(reliability_spline_slip_velocity_depends_on_the_output_interval PROPERTIES WILL_FAIL TRUE)
