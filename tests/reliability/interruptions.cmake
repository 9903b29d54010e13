# Interruptions (SIGTERM, SIGINT, a kill during an output) and errors after set-up under MPI:
# the run stops cleanly, says why, and a restart continues it.
#
# interrupt_run.py sends the signal once the run has printed its output at t = 0.25 (the
# signal lands between two outputs, after a dozen steps of step-size control, and most of
# the run is left to absorb a slow machine), checks the exit code, the one "interrupted by"
# line, summary.json ("interrupted" at the time the line names) and that nothing outlives
# the launcher, then restarts and compares metrics.csv and snapshots.xdmf byte for byte
# with the uninterrupted run of the same rank count (2 ranks reduce sums in another order
# than 1, so each has its own reference).
set(_interrupt_out ${CMAKE_CURRENT_BINARY_DIR}/interruptions)
set(_interrupt_run /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/interrupt_run.py)
set(_mpiexec ${MPIEXEC_EXECUTABLE} ${CAPSULA_MPIEXEC_FLAGS} 2 ${CAPSULA_MPIEXEC_PREFLAGS})
# About 2 s on 1 rank, 1.5 s on 2.
set(_short_cell3d $<TARGET_FILE:cell3d> ${_decks}/cell3d/demo.xml --set "Cells/Cell 0/Mesh level=1"
                  --set "Time integration/End time=3" --set "Output/Interval=0.25")
set(_after_an_output "^t = 0\\.25 ")
set(_same_outputs --compare metrics.csv snapshots.xdmf)

add_test(NAME reliability_interrupt_reference_1_rank
  COMMAND ${_short_cell3d} --output ${_interrupt_out}/reference_1)
add_test(NAME reliability_interrupt_reference_2_ranks
  COMMAND ${_mpiexec} ${_short_cell3d} --output ${_interrupt_out}/reference_2)
set_tests_properties(reliability_interrupt_reference_1_rank PROPERTIES
  LABELS reliability FIXTURES_SETUP interrupt_reference_1 TIMEOUT 300)
set_tests_properties(reliability_interrupt_reference_2_ranks PROPERTIES
  LABELS reliability FIXTURES_SETUP interrupt_reference_2 PROCESSORS 2 TIMEOUT 300)

# capsula_add_interrupt_test(NAME RANKS SIGNAL TO EXIT_CODE [driver options...])
function(capsula_add_interrupt_test name ranks signal to exit_code)
  set(_command ${_short_cell3d})
  if(ranks GREATER 1)
    set(_command ${_mpiexec} ${_short_cell3d})
  endif()
  add_test(NAME reliability_${name}
    COMMAND ${_interrupt_run} --signal ${signal} --to ${to} --exit-code ${exit_code} --output ${_interrupt_out}/${name}
            --after ${_after_an_output} --reference ${_interrupt_out}/reference_${ranks} ${_same_outputs} ${ARGN}
            -- ${_command})
  set_tests_properties(reliability_${name} PROPERTIES
    LABELS reliability FIXTURES_REQUIRED interrupt_reference_${ranks} PROCESSORS ${ranks} TIMEOUT 300
    PASS_REGULAR_EXPRESSION "interrupt_run: OK" FAIL_REGULAR_EXPRESSION "interrupt_run: FAIL")
endfunction()

# One process: exit code 128 + signal; the restart also removes the temporary files a writer
# killed mid-output left (and keeps one of a live process).
capsula_add_interrupt_test(sigterm_1_rank 1 TERM process 143 --stale)
capsula_add_interrupt_test(sigint_1_rank 1 INT process 130)
# Two ranks signalled as a batch system does (every rank), and a signal that reaches one rank
# only: the ranks agree after every step, so both stop after the same one.
capsula_add_interrupt_test(sigterm_2_ranks_all 2 TERM ranks 143)
capsula_add_interrupt_test(sigint_2_ranks_one 2 INT rank1 130 --stale)
# Ctrl-C on mpiexec: Open MPI sends the ranks SIGTERM a second later and SIGKILL a second after
# that, and itself exits with 1. The ranks must stop, write and leave before that SIGKILL,
# and write nothing after mpiexec returned. A longer run, so that the delayed SIGTERM lands
# before its end; the restart is checked above.
add_test(NAME reliability_sigint_2_ranks_mpiexec
  COMMAND ${_interrupt_run} --signal INT --to launcher --exit-code 1 --output ${_interrupt_out}/sigint_mpiexec
          --after ${_after_an_output} --no-restart
          -- ${_mpiexec} ${_short_cell3d} --set "Time integration/End time=5")
set_tests_properties(reliability_sigint_2_ranks_mpiexec PROPERTIES
  LABELS reliability PROCESSORS 2 TIMEOUT 300
  PASS_REGULAR_EXPRESSION "interrupt_run: OK" FAIL_REGULAR_EXPRESSION "interrupt_run: FAIL")

# tether2d, stopped in its free preparation stage (at its first output, of a 1.5 s run): the
# checkpoint holds the stage's state, and the continued run tethers the cell as the
# uninterrupted one does.
set(_short_tether2d $<TARGET_FILE:tether2d> ${_decks}/tether2d/demo.xml --set "Cell/Number of points=64"
                    --set "Tether/Minimum preparation time=0.5" --set "Tether/Maximum preparation time=1"
                    --set "Time integration/End time=8" --set "Output/Interval=0.2")
add_test(NAME reliability_interrupt_reference_tether2d
  COMMAND ${_short_tether2d} --output ${_interrupt_out}/reference_tether2d)
set_tests_properties(reliability_interrupt_reference_tether2d PROPERTIES
  LABELS reliability FIXTURES_SETUP interrupt_reference_tether2d TIMEOUT 300)
add_test(NAME reliability_sigterm_tether2d_preparation
  COMMAND ${_interrupt_run} --signal TERM --to process --exit-code 143 --output ${_interrupt_out}/sigterm_tether2d
          --after "^preparation = 0:" --reference ${_interrupt_out}/reference_tether2d
          --compare preparation.csv metrics.csv -- ${_short_tether2d})
set_tests_properties(reliability_sigterm_tether2d_preparation PROPERTIES
  LABELS reliability FIXTURES_REQUIRED interrupt_reference_tether2d TIMEOUT 300
  PASS_REGULAR_EXPRESSION "interrupt_run: OK" FAIL_REGULAR_EXPRESSION "interrupt_run: FAIL")

# Errors after set-up under MPI and the messages that must name the cause: exit code 2 for
# input, 1 for a failed run, the message once (rank 0), never MPI_Abort's notice.
set(_no_abort "MPI_ABORT|on rank [0-9]")
capsula_add_reliability_test(reliability_missing_deck_2_ranks EXIT_CODE 2 RANKS 2
  MATCHES "The deck '[^']*no-such-deck.xml' does not exist"
  NOT_MATCHES "${_no_abort}|does not exist.*does not exist"
  COMMAND $<TARGET_FILE:cell3d> ${_decks}/cell3d/no-such-deck.xml)
capsula_add_reliability_test(reliability_directory_as_deck EXIT_CODE 2
  MATCHES "The deck '[^']*input/cell3d' is a directory, not a deck file"
  COMMAND $<TARGET_FILE:cell3d> ${_decks}/cell3d)
# A failure one rank meets alone (here its deck is missing, given to it alone through
# mpiexec's MPMD syntax) while the other waits in a collective: after waiting 10 s for the
# other, the rank reports with its number and MPI_Abort ends the job with its code.
add_test(NAME reliability_error_on_one_rank_aborts
  COMMAND ${CMAKE_COMMAND} -DEXIT_CODE=2
          "-DMATCHES=error on rank 1 \\(the other ranks did not fail with it\\): The deck 'no-such-deck.xml' does not exist"
          -P ${CMAKE_CURRENT_SOURCE_DIR}/run_expecting.cmake --
          ${MPIEXEC_EXECUTABLE} ${CAPSULA_MPIEXEC_PREFLAGS}
          ${CAPSULA_MPIEXEC_FLAGS} 1 $<TARGET_FILE:cell3d> ${_decks}/cell3d/demo.xml --output ${_interrupt_out}/one_rank
          --set "Cells/Cell 0/Mesh level=1" :
          ${CAPSULA_MPIEXEC_FLAGS} 1 $<TARGET_FILE:cell3d> no-such-deck.xml --output ${_interrupt_out}/one_rank)
set_tests_properties(reliability_error_on_one_rank_aborts PROPERTIES LABELS reliability PROCESSORS 2 TIMEOUT 300)
# A failure every rank meets after the set-up (the first step's state is not finite).
capsula_add_reliability_test(reliability_tiny_capillary_number_2_ranks EXIT_CODE 1 RANKS 2
  MATCHES "'Flow/Capillary number' = 1e-300 is the cause"
  NOT_MATCHES "${_no_abort}|is the cause.*is the cause|Reduce 'Time integration/Tolerance'"
  COMMAND $<TARGET_FILE:cell3d> ${_decks}/cell3d/demo.xml --output ${_interrupt_out}/tiny_ca
          --set "Cells/Cell 0/Mesh level=1" --set "Flow/Capillary number=1e-300")
# tether2d given a cell3d checkpoint (the reference run above) names both apps.
capsula_add_reliability_test(reliability_restart_from_another_app EXIT_CODE 2
  MATCHES "it is a checkpoint of cell3d, not of tether2d"
  COMMAND $<TARGET_FILE:tether2d> ${_decks}/tether2d/demo.xml --restart ${_interrupt_out}/reference_1
          --output ${_interrupt_out}/another_app)
set_tests_properties(reliability_restart_from_another_app PROPERTIES FIXTURES_REQUIRED interrupt_reference_1)

# A full disk (full_disk.cpp, preloaded: the output directory may grow by 60 kB, enough for
# the set-up and the first outputs) on 2 ranks: exit code 1, the message says the disk is
# full and what to do, and summary.json records the failure although nothing new fits.
add_library(capsula_full_disk MODULE full_disk.cpp)
target_link_libraries(capsula_full_disk PRIVATE ${CMAKE_DL_LIBS})
set(_full ${_interrupt_out}/full_disk)
add_test(NAME reliability_full_disk_clean COMMAND ${CMAKE_COMMAND} -E rm -rf ${_full})
set_tests_properties(reliability_full_disk_clean PROPERTIES LABELS reliability FIXTURES_SETUP full_disk_clean)
capsula_add_reliability_test(reliability_full_disk_2_ranks EXIT_CODE 1 RANKS 2
  MATCHES "The disk is full \\(No space left on device\\): free space there, or write elsewhere with --output DIR"
  NOT_MATCHES "${_no_abort}|disk is full.*disk is full"
  COMMAND /usr/bin/env LD_PRELOAD=$<TARGET_FILE:capsula_full_disk> CAPSULA_FULL_DISK_DIR=${_full}
          CAPSULA_FULL_DISK_BYTES=60000 $<TARGET_FILE:cell3d> ${_decks}/cell3d/demo.xml --output ${_full}
          --set "Cells/Cell 0/Mesh level=1" --set "Time integration/End time=2" --set "Output/Interval=0.25")
set_tests_properties(reliability_full_disk_2_ranks PROPERTIES
  FIXTURES_REQUIRED full_disk_clean FIXTURES_SETUP full_disk_run)
add_test(NAME reliability_full_disk_summary
  COMMAND /usr/bin/python3 -c "import json, sys; s = json.load(open(sys.argv[1])); print(s); sys.exit(not (s['status'] == 'failed' and 'disk is full' in s['failure']))"
          ${_full}/summary.json)
set_tests_properties(reliability_full_disk_summary PROPERTIES LABELS reliability FIXTURES_REQUIRED full_disk_run)

# Restarts that drop snapshots written after the checkpoint give their space back.
add_test(NAME reliability_restart_reclaims_snapshot_space
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/snapshot_space.sh $<TARGET_FILE:check_snapshots>
          ${_interrupt_out}/reference_1 ${_interrupt_out}/snapshot_space -- ${_short_cell3d})
set_tests_properties(reliability_restart_reclaims_snapshot_space PROPERTIES
  LABELS reliability FIXTURES_REQUIRED interrupt_reference_1 TIMEOUT 300)
