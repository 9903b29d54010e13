# A restart that changes a key of the run: tether2d went on with the new value without a
# word (exit 0), where cell3d refused it. Every app now refuses a changed key other than
# 'Time integration/End time' and 'Output/Directory' with exit code 2 and the key named
# (RestartCheckpoint.hpp), before it touches the output directory: the checksum of every
# file there, taken after the source run, must hold after the refusal. A restart that
# changes only the End time then continues the same directory.
set(_changed_out ${CMAKE_CURRENT_BINARY_DIR}/out/restart_changed_key)
set(_changed_cell3d $<TARGET_FILE:cell3d> ${_decks}/cell3d/demo.xml --set "Cells/Cell 0/Mesh level=1"
  --set "Output/Wall shear stress/Enabled=false" --set "Output/Interval=0.025")
set(_changed_twocell3d $<TARGET_FILE:twocell3d> ${_decks}/twocell3d/demo.xml --set "Cells/Cell 0/Mesh level=1"
  --set "Cells/Cell 1/Mesh level=1" --set "Output/Wall shear stress/Enabled=false" --set "Output/Interval=0.025")
# suspension3d: the demo's red cells at Ca = 1 and one soft spherical platelet, so that RK4
# steps of 0.005 are stable (the demo's stiff platelets and Ca = 0.1 need the stiff methods).
set(_changed_suspension3d $<TARGET_FILE:suspension3d> ${_decks}/suspension3d/demo.xml
  --set "Suspension/Hematocrit=0.04" --set "Suspension/Cell types/platelet/Count=1" --set "Flow/Capillary number=1"
  --set "Suspension/Cell types/platelet/Shape=Sphere" --set "Suspension/Cell types/platelet/Radius=0.5"
  --set "Suspension/Cell types/platelet/Shear modulus=1" --set "Time integration/Method=RK4"
  --set "Time integration/Initial step=0.005" --set "Output/Interval=0.025")
set(_changed_tether2d $<TARGET_FILE:tether2d> ${_decks}/tether2d/demo.xml --set "Cell/Number of points=32"
  --set "Tether/Minimum preparation time=0.05" --set "Tether/Maximum preparation time=0.1"
  --set "Output/Interval=0.025")
# Where each app says it continues ("Restarted from DIR at t = ...", "Restarting from DIR/checkpoint.h5").
set(_continued_cell3d "Restarted from [^ ]*/cell3d at t = 0\\.05")
set(_continued_twocell3d "Restarted from [^ ]*/twocell3d at t = 0\\.05")
set(_continued_suspension3d "Restarted from [^ ]*/suspension3d at t = 0\\.05")
set(_continued_tether2d "Restarting from [^ ]*/tether2d/checkpoint\\.h5 at tau = 0\\.05")
foreach(_app cell3d twocell3d suspension3d tether2d)
  set(_dir ${_changed_out}/${_app})
  set(_run ${_changed_${_app}})
  set(_prefix reliability_restart_changing_a_key_${_app})
  add_test(NAME ${_prefix}_source
    COMMAND bash -c "rm -rf ${_dir} ${_dir}.sha256 && \"$0\" \"$@\"" ${_run} --set "Time integration/End time=0.05"
            --output ${_dir})
  # The checksums of every file in the directory (file names included), sorted by name.
  add_test(NAME ${_prefix}_checksums
    COMMAND bash -c "cd ${_dir} && find . -type f | LC_ALL=C sort | xargs sha256sum > ${_dir}.sha256 && test -s ${_dir}.sha256")
  capsula_add_reliability_test(${_prefix}_is_refused EXIT_CODE 2
    MATCHES "Cannot restart from '[^']*/${_app}/checkpoint\\.h5': the deck differs from the one the run was started with at 'Flow/Capillary number'"
    COMMAND ${_run} --set "Time integration/End time=0.1" --set "Flow/Capillary number=0.05" --restart ${_dir})
  add_test(NAME ${_prefix}_leaves_every_file_byte_for_byte
    COMMAND bash -c "cd ${_dir} && find . -type f | LC_ALL=C sort | xargs sha256sum | diff ${_dir}.sha256 -")
  # Only the End time changed: the run continues from the checkpoint at 0.05.
  capsula_add_reliability_test(${_prefix}_end_time_only_continues EXIT_CODE 0
    MATCHES "${_continued_${_app}}"
    COMMAND ${_run} --set "Time integration/End time=0.1" --restart ${_dir})
  set_tests_properties(${_prefix}_source ${_prefix}_checksums ${_prefix}_leaves_every_file_byte_for_byte PROPERTIES
    LABELS reliability TIMEOUT 300)
  set_tests_properties(${_prefix}_source PROPERTIES FIXTURES_SETUP changed_key_${_app}_source)
  set_tests_properties(${_prefix}_checksums PROPERTIES
    FIXTURES_REQUIRED changed_key_${_app}_source FIXTURES_SETUP changed_key_${_app}_sums)
  set_tests_properties(${_prefix}_is_refused PROPERTIES
    FIXTURES_REQUIRED "changed_key_${_app}_source;changed_key_${_app}_sums" FIXTURES_SETUP changed_key_${_app}_refused)
  set_tests_properties(${_prefix}_leaves_every_file_byte_for_byte PROPERTIES
    FIXTURES_REQUIRED "changed_key_${_app}_source;changed_key_${_app}_refused" FIXTURES_SETUP changed_key_${_app}_checked)
  set_tests_properties(${_prefix}_end_time_only_continues PROPERTIES
    FIXTURES_REQUIRED "changed_key_${_app}_source;changed_key_${_app}_checked")
endforeach()
# suspension3d places its cells again at a restart, from the deck's seed: another seed would
# place other cells, and the refusal names the seed, not the first cell whose centre moved.
capsula_add_reliability_test(reliability_restart_changing_the_seed_suspension3d_is_refused EXIT_CODE 2
  MATCHES "the deck differs from the one the run was started with at 'Suspension/Seed'"
  COMMAND ${_changed_suspension3d} --set "Time integration/End time=0.1" --set "Suspension/Seed=2"
          --restart ${_changed_out}/suspension3d)
set_tests_properties(reliability_restart_changing_the_seed_suspension3d_is_refused PROPERTIES
  FIXTURES_REQUIRED "changed_key_suspension3d_source;changed_key_suspension3d_sums"
  FIXTURES_SETUP changed_key_suspension3d_seed)
set_tests_properties(reliability_restart_changing_a_key_suspension3d_leaves_every_file_byte_for_byte PROPERTIES
  FIXTURES_REQUIRED "changed_key_suspension3d_source;changed_key_suspension3d_refused;changed_key_suspension3d_seed")
