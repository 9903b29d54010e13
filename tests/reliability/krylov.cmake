# The Krylov method of the viscosity-ratio equation ('Solver/Method') and the Belos
# parameters handed to it ('Solver/Belos', checked against the chosen solver's own): a name
# or a key Belos does not have stops the run at start-up (exit 2), named; a Belos entry that
# cuts the solve short ends the run with the solve's message, which names it (exit 1).
set(_lambda5 ${_decks}/cell3d/viscosity-ratio/wall-h2/NeoHookean-Ca0.1-lambda5.xml)
set(_tether_lambda5 ${_decks}/tether2d/study/ab1_lambda5_ca0.25.xml)

capsula_add_reliability_test(reliability_unknown_krylov_method_lists_the_offered_ones EXIT_CODE 2
  MATCHES "'Solver/Method' = \"TFQMRR\" is invalid: it must be one of: Block GMRES, Pseudo Block GMRES, GCRODR, TFQMR, BiCGStab \\(did you mean \"TFQMR\"\\?\\)"
  COMMAND $<TARGET_FILE:cell3d> ${_lambda5} --set "Solver/Method=TFQMRR" --output ${_out}/never)

capsula_add_reliability_test(reliability_unknown_belos_key_is_named EXIT_CODE 2
  MATCHES "'Solver/Belos/Maximum Iteration' is not a parameter of the Belos solver 'TFQMR' \\('Solver/Method'\\)\\. Did you mean 'Solver/Belos/Maximum Iterations'\\?"
  COMMAND $<TARGET_FILE:cell3d> ${_lambda5} --set "Solver/Method=TFQMR" --set "Solver/Belos/Maximum Iteration=5"
          --output ${_out}/never)

# tether2d reads the same keys from its own 'Solver' list: a GMRES parameter is not BiCGStab's.
capsula_add_reliability_test(reliability_tether2d_belos_key_of_another_method_is_named EXIT_CODE 2
  MATCHES "'Solver/Belos/Num Blocks' is not a parameter of the Belos solver 'BiCGStab'"
  COMMAND $<TARGET_FILE:tether2d> ${_tether_lambda5} --set "Solver/Method=BiCGStab" --set "Solver/Belos/Num Blocks=40"
          --output ${_out}/never)

capsula_add_reliability_test(reliability_belos_entry_limits_the_solve EXIT_CODE 1
  MATCHES "'Solver/Method' = Block GMRES for the viscosity-ratio equation stopped after 1 iterations at relative residual [^ ]+ > 'Solver/Tolerance' = 1e-09.*The entries of 'Solver/Belos' \\('Maximum Iterations'\\) take precedence over those keys\\."
  COMMAND $<TARGET_FILE:cell3d> ${_lambda5} --set "Solver/Belos/Maximum Iterations=1"
          --output ${_out}/belos_one_iteration)

capsula_add_reliability_test(reliability_unknown_preconditioner_lists_the_offered_ones EXIT_CODE 2
  MATCHES "'Solver/Preconditioner' = \"Cell block\" is invalid: it must be one of: None, Cell blocks \\(did you mean \"Cell blocks\"\\?\\)"
  COMMAND $<TARGET_FILE:cell3d> ${_lambda5} --set "Solver/Preconditioner=Cell block" --output ${_out}/never)

# With the cell blocks the solve is flexible GMRES whatever 'Solver/Method' says: the message of
# a solve cut short names the preconditioner, not the method.
capsula_add_reliability_test(reliability_cell_block_solve_cut_short_names_the_preconditioner EXIT_CODE 1
  MATCHES "Flexible GMRES \\('Solver/Preconditioner' = Cell blocks\\) for the viscosity-ratio equation stopped after 1 iterations at relative residual [^ ]+ > 'Solver/Tolerance' = 1e-09"
  COMMAND $<TARGET_FILE:cell3d> ${_lambda5} --set "Solver/Preconditioner=Cell blocks"
          --set "Solver/Maximum iterations=1" --output ${_out}/cell_blocks_one_iteration)
