# A pulsatile shear rate through the cell3d command line: a restart at t = 0.1, a quarter
# period in, continues the uninterrupted run bit for bit (tolerance 0). lambda = 5, so the
# GMRES warm start, whose right-hand sides change with k(t), goes through the checkpoint too.
set(_pulsatile_out ${CMAKE_CURRENT_BINARY_DIR}/pulsatile)
set(_pulsatile ${PROJECT_SOURCE_DIR}/input/cell3d/demo.xml --set "Cells/Cell 0/Mesh level=1"
  --set "Flow/Viscosity ratio=5" --set "Flow/Shear rate/Form=Pulsatile" --set "Flow/Shear rate/Amplitude=0.5"
  --set "Flow/Shear rate/Period=0.4" --set "Output/Interval=0.1")
add_test(NAME regression_pulsatile_cell3d_whole
  COMMAND cell3d ${_pulsatile} --output ${_pulsatile_out}/whole --set "Time integration/End time=0.3")
set_tests_properties(regression_pulsatile_cell3d_whole PROPERTIES
  FIXTURES_SETUP pulsatile_whole LABELS regression TIMEOUT 300)
add_test(NAME regression_pulsatile_cell3d_first_part
  COMMAND cell3d ${_pulsatile} --output ${_pulsatile_out}/restarted --set "Time integration/End time=0.1")
set_tests_properties(regression_pulsatile_cell3d_first_part PROPERTIES
  FIXTURES_SETUP pulsatile_first LABELS regression TIMEOUT 300)
add_test(NAME regression_pulsatile_cell3d_restart
  COMMAND cell3d ${_pulsatile} --restart ${_pulsatile_out}/restarted --set "Time integration/End time=0.3")
set_tests_properties(regression_pulsatile_cell3d_restart PROPERTIES
  FIXTURES_REQUIRED pulsatile_first FIXTURES_SETUP pulsatile_restart LABELS regression TIMEOUT 300)
add_test(NAME regression_pulsatile_cell3d_restart_reproduces
  COMMAND check_metrics same ${_pulsatile_out}/whole/metrics.csv ${_pulsatile_out}/restarted/metrics.csv 0)
set_tests_properties(regression_pulsatile_cell3d_restart_reproduces PROPERTIES
  FIXTURES_REQUIRED "pulsatile_whole;pulsatile_restart" LABELS regression)
