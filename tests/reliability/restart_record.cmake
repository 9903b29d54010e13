# A restart carries every record the uninterrupted run would have, and refuses a damaged
# directory as bad input (exit code 2, the file named) before it writes anything.
set(_record_out ${CMAKE_CURRENT_BINARY_DIR}/out/restart_record)

# Auto's switches in summary.json ('time integration/switches'): a restarted run lost them,
# though its metrics.csv equalled the uninterrupted run's. The nearly rigid Goldman capsule
# (tests/regression/stiff.cmake) switches to ROS34PW2 at t = 0.0073; the first half stops at
# the output t = 0.01, after the switch, and the restart goes on to 0.02.
set(_auto $<TARGET_FILE:cell3d> ${_decks}/cell3d/validation/goldman-rigid-h1.5431.xml
  --set "Cells/Cell 0/Mesh level=1" --set "Flow/Capillary number=0.005" --set "Time integration/Tolerance=1e-4"
  --set "Time integration/Method=Auto" --set "Output/Snapshots=false" --set "Output/Interval=0.01")
add_test(NAME reliability_auto_switches_whole_run
  COMMAND ${_auto} --set "Time integration/End time=0.02" --output ${_record_out}/auto_whole)
add_test(NAME reliability_auto_switches_first_half
  COMMAND ${_auto} --set "Time integration/End time=0.01" --output ${_record_out}/auto_restarted)
add_test(NAME reliability_auto_switches_second_half
  COMMAND ${_auto} --set "Time integration/End time=0.02" --restart ${_record_out}/auto_restarted)
set_tests_properties(reliability_auto_switches_whole_run reliability_auto_switches_first_half
  reliability_auto_switches_second_half PROPERTIES LABELS reliability TIMEOUT 300)
set_tests_properties(reliability_auto_switches_whole_run PROPERTIES FIXTURES_SETUP auto_switches_whole)
set_tests_properties(reliability_auto_switches_first_half PROPERTIES FIXTURES_SETUP auto_switches_half)
set_tests_properties(reliability_auto_switches_second_half PROPERTIES
  FIXTURES_REQUIRED auto_switches_half FIXTURES_SETUP auto_switches_restarted)
add_test(NAME reliability_restart_keeps_the_auto_switches
  COMMAND /usr/bin/python3 -c "import json, sys; s = [json.load(open(f + '/summary.json'))['time integration'].get('switches') for f in sys.argv[1:]]; print(s); sys.exit(not (s[0] and s[0] == s[1]))"
          ${_record_out}/auto_whole ${_record_out}/auto_restarted)
set_tests_properties(reliability_restart_keeps_the_auto_switches PROPERTIES LABELS reliability
  FIXTURES_REQUIRED "auto_switches_whole;auto_switches_restarted")

# A restart directory without metrics.csv exited 1 (after rewriting run.json); one with a row
# missing was continued with a gap. The source run writes rows at t = 0, 0.025 and 0.05; each
# damaged copy is kept beside a second copy, and the refused restart must leave it equal to it.
set(_source_run $<TARGET_FILE:cell3d> ${_cell3d_demo} ${_level1} --set "Time integration/End time=0.05"
  --set "Output/Interval=0.025")
add_test(NAME reliability_damaged_restart_source COMMAND ${_source_run} --output ${_record_out}/source)
set_tests_properties(reliability_damaged_restart_source PROPERTIES LABELS reliability FIXTURES_SETUP damaged_source)
set(_damage_missing "rm metrics.csv")
set(_damage_gap "sed -i 3d metrics.csv")
foreach(_case missing gap)
  set(_dir ${_record_out}/${_case})
  add_test(NAME reliability_damaged_restart_${_case}_prepare
    COMMAND bash -c "rm -rf ${_dir} ${_dir}.before && cp -r ${_record_out}/source ${_dir} && cd ${_dir} && ${_damage_${_case}} && cp -r ${_dir} ${_dir}.before")
  set_tests_properties(reliability_damaged_restart_${_case}_prepare PROPERTIES LABELS reliability
    FIXTURES_REQUIRED damaged_source FIXTURES_SETUP damaged_${_case})
  add_test(NAME reliability_damaged_restart_${_case}_left_as_it_was COMMAND diff -r ${_dir}.before ${_dir})
  set_tests_properties(reliability_damaged_restart_${_case}_left_as_it_was PROPERTIES LABELS reliability
    FIXTURES_REQUIRED damaged_${_case}.refused)
endforeach()
foreach(_ranks 1 2)
  capsula_add_reliability_test(reliability_restart_without_metrics_${_ranks}_ranks EXIT_CODE 2 RANKS ${_ranks}
    MATCHES "--restart [^ ]*missing: '[^']*missing/metrics\\.csv' is missing. the checkpoint at t = 0\\.05 continues its 3 rows"
    NOT_MATCHES "MPI_ABORT|on rank [0-9]"
    COMMAND ${_source_run} --set "Time integration/End time=0.1" --restart ${_record_out}/missing)
  set_tests_properties(reliability_restart_without_metrics_${_ranks}_ranks PROPERTIES
    FIXTURES_REQUIRED damaged_missing FIXTURES_SETUP damaged_missing.refused)
endforeach()
capsula_add_reliability_test(reliability_restart_with_a_row_missing EXIT_CODE 2
  MATCHES "'[^']*gap/metrics\\.csv' holds 2 rows up to the checkpoint at t = 0\\.05, where the run wrote 3: the record is damaged"
  COMMAND ${_source_run} --set "Time integration/End time=0.1" --restart ${_record_out}/gap)
set_tests_properties(reliability_restart_with_a_row_missing PROPERTIES
  FIXTURES_REQUIRED damaged_gap FIXTURES_SETUP damaged_gap.refused)
