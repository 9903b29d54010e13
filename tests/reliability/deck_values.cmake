# Deck files with bad values, duplicate keys and runs with nothing to do: exit code 2 and a
# message naming the key and file (and the line, for what the file itself holds).
#
# The bad decks are the demo decks with one value replaced, written at configure time; a
# replacement that no longer finds its text (the demo changed) stops the configuration
# rather than testing a good deck.
function(capsula_bad_deck name demo from to)
  file(READ ${demo} _text)
  string(REPLACE "${from}" "${to}" _bad "${_text}")
  if(_bad STREQUAL _text)
    message(FATAL_ERROR "tests/reliability: '${from}' is not in ${demo}; update the bad deck '${name}'")
  endif()
  file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/decks/${name}.xml "${_bad}")
endfunction()

set(_cell3d_demo ${_decks}/cell3d/demo.xml)
set(_bad ${CMAKE_CURRENT_BINARY_DIR}/decks)
set(_out ${CMAKE_CURRENT_BINARY_DIR}/out)

# Teuchos alone would run each of these with a coerced value (0, level 0 or 2, Ca 0.3, a
# centre of {0, 1.6, 0}, an overflowed level) and exit 0.
foreach(_case
    "prestress_not_a_number|<Parameter name=\"Prestress\" type=\"double\" value=\"0.0\"/>|<Parameter name=\"Prestress\" type=\"double\" value=\"abc\"/>|'Cells/Cell 0/Prestress' = \"abc\" is not a finite real number"
    "mesh_level_not_a_number|<Parameter name=\"Mesh level\" type=\"int\" value=\"2\"/>|<Parameter name=\"Mesh level\" type=\"int\" value=\"abc\"/>|'Cells/Cell 0/Mesh level' = \"abc\" is not an integer"
    "mesh_level_with_a_fraction|<Parameter name=\"Mesh level\" type=\"int\" value=\"2\"/>|<Parameter name=\"Mesh level\" type=\"int\" value=\"2.5\"/>|'Cells/Cell 0/Mesh level' = \"2.5\" is not an integer"
    "mesh_level_overflowing|<Parameter name=\"Mesh level\" type=\"int\" value=\"2\"/>|<Parameter name=\"Mesh level\" type=\"int\" value=\"99999999999\"/>|'Cells/Cell 0/Mesh level' = \"99999999999\" is not an integer"
    "capillary_number_with_trailing_text|value=\"0.3\"/>|value=\"0.3abc\"/>|'Flow/Capillary number' = \"0.3abc\" is not a finite real number"
    "centre_with_a_letter|value=\"{0.0, 1.6, 0.0}\"|value=\"{a, 1.6, 0}\"|'Cells/Cell 0/Center' = \"{a, 1.6, 0}\" has element 1 = \"a\", which is not a finite real number"
    "centre_with_nan|value=\"{0.0, 1.6, 0.0}\"|value=\"{0, nan, 0}\"|'Cells/Cell 0/Center' = \"{0, nan, 0}\" has element 2 = \"nan\""
    "boolean_not_true_or_false|<Parameter name=\"Fixed height\" type=\"bool\" value=\"false\"/>|<Parameter name=\"Fixed height\" type=\"bool\" value=\"maybe\"/>|'Cells/Cell 0/Fixed height' = \"maybe\" is not a boolean")
  string(REPLACE "|" ";" _parts "${_case}")
  list(GET _parts 0 _name)
  list(GET _parts 1 _from)
  list(GET _parts 2 _to)
  list(GET _parts 3 _expected)
  capsula_bad_deck(${_name} ${_cell3d_demo} "${_from}" "${_to}")
  string(REGEX REPLACE "([][{}().*+?])" "\\\\\\1" _expected "${_expected}")
  capsula_add_reliability_test(reliability_deck_${_name} EXIT_CODE 2
    MATCHES "Deck '[^']*${_name}\\.xml', line [0-9]+: ${_expected}"
    COMMAND $<TARGET_FILE:cell3d> ${_bad}/${_name}.xml --output ${_out}/never)
endforeach()

# tether2d reads its deck the same way.
capsula_bad_deck(tether2d_capillary_number_not_a_number ${_decks}/tether2d/demo.xml
  "<Parameter name=\"Capillary number\" type=\"double\" value=\"0.25\"/>"
  "<Parameter name=\"Capillary number\" type=\"double\" value=\"abc\"/>")
capsula_add_reliability_test(reliability_deck_tether2d_capillary_number_not_a_number EXIT_CODE 2
  MATCHES "tether2d_capillary_number_not_a_number\\.xml', line 5: 'Flow/Capillary number' = \"abc\""
  COMMAND $<TARGET_FILE:tether2d> ${_bad}/tether2d_capillary_number_not_a_number.xml --output ${_out}/never)

# A key given twice: Teuchos keeps the last without a word.
capsula_bad_deck(key_given_twice ${_cell3d_demo}
  "<Parameter name=\"Capillary number\" type=\"double\" value=\"0.3\"/>"
  "<Parameter name=\"Capillary number\" type=\"double\" value=\"0.3\"/>\n    <Parameter name=\"Capillary number\" type=\"double\" value=\"0.9\"/>")
capsula_add_reliability_test(reliability_deck_key_given_twice EXIT_CODE 2
  MATCHES "key_given_twice\\.xml': 'Flow/Capillary number' is given twice \\(lines 6 and 7\\)"
  COMMAND $<TARGET_FILE:cell3d> ${_bad}/key_given_twice.xml --output ${_out}/never)

# An end before the start: the run used to print "finished at t = 0 after 0 steps" and exit 0.
capsula_bad_deck(end_time_negative ${_cell3d_demo}
  "<Parameter name=\"End time\" type=\"double\" value=\"2.0\"/>"
  "<Parameter name=\"End time\" type=\"double\" value=\"-1\"/>")
capsula_add_reliability_test(reliability_deck_end_time_negative EXIT_CODE 2
  MATCHES "Time integration/End time must be > 0 \\(runs start at t = 0\\), got -1"
  COMMAND $<TARGET_FILE:cell3d> ${_bad}/end_time_negative.xml --output ${_out}/never)
capsula_add_reliability_test(reliability_deck_tether2d_negative_bending_modulus EXIT_CODE 2
  MATCHES "'Cell/Bending modulus' = -0\\.01 is invalid: it must be a finite real number >= 0"
  COMMAND $<TARGET_FILE:tether2d> ${_decks}/tether2d/demo.xml --set "Cell/Bending modulus=-0.01" --output ${_out}/never)
# Bending with the natural tether ends: kappa = 0 forced at the tether gives a spurious tether force.
capsula_add_reliability_test(reliability_deck_tether2d_bending_with_natural_ends EXIT_CODE 2
  MATCHES "'Cell/Bending modulus' = 0\\.01 needs 'Cell/Tether spline ends' = NotAKnot"
  COMMAND $<TARGET_FILE:tether2d> ${_decks}/tether2d/demo.xml --set "Cell/Bending modulus=0.01" --output ${_out}/never)
capsula_add_reliability_test(reliability_deck_tether2d_end_time_zero EXIT_CODE 2
  MATCHES "Time integration/End time must be > 0 \\(runs start at t = 0\\), got 0"
  COMMAND $<TARGET_FILE:tether2d> ${_decks}/tether2d/demo.xml --set "Time integration/End time=0" --output ${_out}/never)

# A restart with nothing to do (the checkpoint is at the End time): exit 2 naming the times,
# where it used to exit 0 having done nothing. The first run is a fixture.
set(_short --set "Cells/Cell 0/Mesh level=1" --set "Time integration/End time=0.05" --set "Output/Interval=0.05"
  --set "Output/Wall shear stress/Enabled=false")
add_test(NAME reliability_restart_source_cell3d
  COMMAND $<TARGET_FILE:cell3d> ${_cell3d_demo} ${_short} --output ${_out}/restart_source)
set_tests_properties(reliability_restart_source_cell3d PROPERTIES LABELS reliability
  FIXTURES_SETUP reliability_restart_cell3d)
capsula_add_reliability_test(reliability_restart_with_nothing_to_do EXIT_CODE 2
  MATCHES "--restart [^:]*restart_source: the checkpoint is at t = 0\\.05, at or past 'Time integration/End time' = 0\\.05. nothing to do"
  COMMAND $<TARGET_FILE:cell3d> ${_cell3d_demo} ${_short} --output ${_out}/restart_source --restart ${_out}/restart_source)
set_tests_properties(reliability_restart_with_nothing_to_do PROPERTIES
  FIXTURES_REQUIRED "reliability_restart_cell3d;reliability_restart_record_cell3d"
  FIXTURES_SETUP reliability_restart_record_cell3d.refused)
capsula_add_reliability_test(reliability_restart_before_the_checkpoint EXIT_CODE 2
  MATCHES "the checkpoint is at t = 0\\.05, at or past 'Time integration/End time' = 0\\.02. nothing to do"
  COMMAND $<TARGET_FILE:cell3d> ${_cell3d_demo} ${_short} --set "Time integration/End time=0.02"
          --output ${_out}/restart_source --restart ${_out}/restart_source)
set_tests_properties(reliability_restart_before_the_checkpoint PROPERTIES FIXTURES_REQUIRED reliability_restart_cell3d)

set(_tether_short --set "Cell/Number of points=32" --set "Tether/Minimum preparation time=0.05"
  --set "Tether/Maximum preparation time=0.1" --set "Time integration/End time=0.05" --set "Output/Interval=0.05")
add_test(NAME reliability_restart_source_tether2d
  COMMAND $<TARGET_FILE:tether2d> ${_decks}/tether2d/demo.xml ${_tether_short} --output ${_out}/restart_source_tether2d)
set_tests_properties(reliability_restart_source_tether2d PROPERTIES LABELS reliability
  FIXTURES_SETUP reliability_restart_tether2d)
# A refused restart leaves the directory it names as it was: its record of the run
# (run.json, summary.json, metrics.csv) is copied before and compared after.
foreach(_app cell3d tether2d)
  set(_dir ${_out}/restart_source)
  if(_app STREQUAL tether2d)
    set(_dir ${_out}/restart_source_tether2d)
  endif()
  add_test(NAME reliability_restart_record_before_${_app}
    COMMAND bash -c "mkdir -p ${_out}/record_${_app} && cp ${_dir}/run.json ${_dir}/summary.json ${_dir}/metrics.csv ${_out}/record_${_app}/")
  set_tests_properties(reliability_restart_record_before_${_app} PROPERTIES LABELS reliability
    FIXTURES_REQUIRED reliability_restart_${_app} FIXTURES_SETUP reliability_restart_record_${_app})
  add_test(NAME reliability_refused_restart_leaves_the_record_${_app}
    COMMAND bash -c "for f in run.json summary.json metrics.csv; do cmp ${_out}/record_${_app}/$f ${_dir}/$f || exit 1; done")
  set_tests_properties(reliability_refused_restart_leaves_the_record_${_app} PROPERTIES LABELS reliability
    FIXTURES_REQUIRED reliability_restart_record_${_app}.refused)
endforeach()

capsula_add_reliability_test(reliability_restart_tether2d_with_nothing_to_do EXIT_CODE 2
  MATCHES "the checkpoint is at tau = 0\\.05, at or past 'Time integration/End time' = 0\\.05. nothing to do"
  COMMAND $<TARGET_FILE:tether2d> ${_decks}/tether2d/demo.xml ${_tether_short}
          --output ${_out}/restart_source_tether2d --restart ${_out}/restart_source_tether2d)
set_tests_properties(reliability_restart_tether2d_with_nothing_to_do PROPERTIES
  FIXTURES_REQUIRED "reliability_restart_tether2d;reliability_restart_record_tether2d"
  FIXTURES_SETUP reliability_restart_record_tether2d.refused)

# The wall's own safety gap at the start (as 'Cells/Minimum gap' is for two cells). A centre
# at height 1 puts the lowest node on the wall: it was told to rise "by more than -0".
capsula_add_reliability_test(reliability_cell_started_just_above_the_wall EXIT_CODE 2
  MATCHES "'Cells/Cell 0' starts too close to the wall: its lowest node \\([0-9]+\\) lies at y = 1e-05, not more than 'Wall/Minimum gap' = 0\\.025"
  COMMAND $<TARGET_FILE:cell3d> ${_cell3d_demo} --set "Cells/Cell 0/Center={0, 1.00001, 0}" --output ${_out}/never)
capsula_add_reliability_test(reliability_cell_centre_at_height_one_is_told_a_positive_rise EXIT_CODE 2
  MATCHES "'Cells/Cell 0' touches the wall: its lowest node \\([0-9]+\\) lies at y = 0, .* by more than 0\\.025, lower 'Wall/Minimum gap'"
  NOT_MATCHES "more than -|more than 0,"
  COMMAND $<TARGET_FILE:cell3d> ${_cell3d_demo} --set "Cells/Cell 0/Center={0, 1, 0}" --output ${_out}/never)
capsula_add_reliability_test(reliability_wall_gap_can_be_lowered EXIT_CODE 0
  MATCHES "Done: finished at t = 0\\.001 after 1 steps"
  COMMAND $<TARGET_FILE:cell3d> ${_cell3d_demo} --set "Cells/Cell 0/Center={0, 1.01, 0}" --set "Wall/Minimum gap=0.005"
          --set "Cells/Cell 0/Mesh level=1" --set "Time integration/End time=0.001"
          --set "Output/Wall shear stress/Enabled=false" --output ${_out}/lowered_gap)

# The deck --print-defaults prints is a starting point that runs (one step here).
foreach(_app cell3d twocell3d)
  add_test(NAME reliability_print_defaults_deck_runs_${_app}
    COMMAND ${CMAKE_COMMAND} -DEXIT_CODE=0 "-DMATCHES=Done: finished at t = 0\\.001 after 1 steps"
            -P ${CMAKE_CURRENT_SOURCE_DIR}/run_expecting.cmake --
            bash -c "$<TARGET_FILE:${_app}> --print-defaults > defaults-${_app}.xml && $<TARGET_FILE:${_app}> defaults-${_app}.xml --set 'Time integration/End time=0.001' --output ${_out}/defaults-${_app}"
    WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  set_tests_properties(reliability_print_defaults_deck_runs_${_app} PROPERTIES LABELS reliability TIMEOUT 300)
endforeach()
