# Absurd values of the newest features, refused at start-up by name (exit code 2, the key, the
# value and what would work, the bound derived from the scene where it can be), keys without
# effect refused, explicit settings never overridden, and restarts that keep the run's whole
# record or refuse a damaged directory. Each test is named after the defect it pins.
set(_adhesion_deck ${_decks}/cell3d/adhesion/sphere-ligand-wall.xml)
set(_bad_out ${CMAKE_CURRENT_BINARY_DIR}/out/bad_input)
set(_level1 --set "Cells/Cell 0/Mesh level=1" --set "Output/Wall shear stress/Enabled=false")
set(_adhesion $<TARGET_FILE:cell3d> ${_adhesion_deck} --set "Time integration/End time=0.01")
set(_demo $<TARGET_FILE:cell3d> ${_cell3d_demo} ${_level1} --set "Time integration/End time=0.01")
set(_tether2d $<TARGET_FILE:tether2d> ${_decks}/tether2d/demo.xml)

# capsula_add_refusal_test(<name> [RANKS <n>] MATCHES <regex> COMMAND ...): exit code 2 with the
# message (once, without MPI_Abort's notice), then a second test that the run did not create
# its --output directory (one of its own, removed first): nothing is written.
function(capsula_add_refusal_test name)
  cmake_parse_arguments(ARG "" "RANKS;MATCHES" "COMMAND" ${ARGN})
  set(_dir ${_bad_out}/${name})
  set(_ranks)
  if(ARG_RANKS)
    set(_ranks RANKS ${ARG_RANKS})
  endif()
  add_test(NAME ${name}_clean COMMAND ${CMAKE_COMMAND} -E rm -rf ${_dir})
  set_tests_properties(${name}_clean PROPERTIES LABELS reliability FIXTURES_SETUP ${name}_clean)
  capsula_add_reliability_test(${name} EXIT_CODE 2 ${_ranks} MATCHES "${ARG_MATCHES}"
    NOT_MATCHES "MPI_ABORT|on rank [0-9]|bad_alloc|is not finite"
    COMMAND ${ARG_COMMAND} --output ${_dir})
  set_tests_properties(${name} PROPERTIES FIXTURES_REQUIRED ${name}_clean FIXTURES_SETUP ${name}_ran)
  add_test(NAME ${name}_left_no_output COMMAND bash -c "test ! -e ${_dir}")
  set_tests_properties(${name}_left_no_output PROPERTIES LABELS reliability FIXTURES_REQUIRED ${name}_ran)
endfunction()

# A receptor density whose receptors do not fit in memory: exit 1 with "std::bad_alloc" after
# 18 s. The bound is the cells' reference area (4 pi a^2, 12.5 a^2 at level 1) times the
# density against what the machine's memory and a receptor index hold.
foreach(_ranks 1 2)
  capsula_add_refusal_test(reliability_receptor_density_beyond_memory_${_ranks}_ranks RANKS ${_ranks}
    MATCHES "'Adhesion/Receptor density' = 1e\\+09 puts about 1\\.2[0-9]*e\\+10 receptors on the cells' 12\\.[0-9]+ a\\^2 of membrane. at most [0-9.e+]+ fit .*Give a density <= [0-9]"
    COMMAND ${_adhesion} --set "Adhesion/Receptor density=1e9")
endforeach()

# A patch so wide that its pulling point (the patch's weighted mean) lies near the cell's centre,
# out of the reach of the wall: 0 bonds at t = 0.1 where point receptors make 30. The widest
# radius offered keeps the pulling point within r_0 - lambda = 0.03 (about sqrt(8 x 0.03 a) =
# 0.49 on the unit sphere).
foreach(_radius 1.5 100)
  capsula_add_refusal_test(reliability_patch_radius_${_radius}_beyond_the_reach
    MATCHES "'Adhesion/Patch radius' = ${_radius} puts the pulling point of receptor [0-9]+ \\(the mean of its patch\\) 0\\.[0-9]+ a inside the unstressed membrane, more than 'Adhesion/Reaction distance' - 'Adhesion/Equilibrium length' = 0\\.05 - 0\\.02 = 0\\.03.*Give a radius below 0\\.4[0-9]*"
    COMMAND ${_adhesion} --set "Adhesion/Patch radius=${_radius}")
endforeach()

# Bonds that rest beyond their own reach, or where the repulsion never lets the membrane go:
# 0 bonds (the deck: r_0 = 0.05, 'Contact/Range' = 0.03).
capsula_add_refusal_test(reliability_equilibrium_length_above_the_reaction_distance
  MATCHES "'Adhesion/Equilibrium length' = 0\\.06 is above 'Adhesion/Reaction distance' = 0\\.05.*Give a length <= 0\\.05"
  COMMAND ${_adhesion} --set "Adhesion/Equilibrium length=0.06")
capsula_add_refusal_test(reliability_equilibrium_length_above_the_contact_range
  MATCHES "'Adhesion/Equilibrium length' = 0\\.04 is above 'Contact/Range' = 0\\.03.*Give a length <= 0\\.03"
  COMMAND ${_adhesion} --set "Adhesion/Equilibrium length=0.04")

# A contact range wider than the cell: the membrane folded at t = 0.0025.
capsula_add_refusal_test(reliability_contact_range_wider_than_the_cell
  MATCHES "'Contact/Range' = 5 is not below the smallest semi-axis of 'Cells/Cell 0', (0\\.9[0-9]*|1) a.*Give a range below"
  COMMAND ${_demo} --set "Contact/Enabled=true" --set "Contact/Range=5")

# Bending beyond the range of doubles: exit 1 "right-hand side is not finite at t = 0" and a
# -nan row in metrics.csv; tether2d reported a node below the wall at y = -3e281.
foreach(_ranks 1 2)
  capsula_add_refusal_test(reliability_bending_modulus_overflowing_${_ranks}_ranks RANKS ${_ranks}
    MATCHES "'Cells/Cell 0/Bending modulus' = 1e\\+300 makes the bending loads of order .* beyond 1e\\+100, where the run's arithmetic overflows: give a modulus <= [0-9.]+e\\+9[0-9]"
    COMMAND ${_demo} --set "Cells/Cell 0/Bending modulus=1e300")
endforeach()
capsula_add_refusal_test(reliability_spontaneous_curvature_overflowing
  MATCHES "'Cells/Cell 0/Spontaneous curvature' = 1e\\+308 makes the bending loads of order .* = inf .*give \\|c0\\| <= [0-9.]+e\\+3[0-9]"
  COMMAND ${_demo} --set "Cells/Cell 0/Bending modulus=0.01" --set "Cells/Cell 0/Spontaneous curvature=1e308")
capsula_add_refusal_test(reliability_tether2d_bending_modulus_overflowing
  MATCHES "'Cell/Bending modulus' = 1e\\+300 makes the bending loads of order .*give a modulus <="
  COMMAND ${_tether2d} --set "Cell/Bending modulus=1e300" --set "Cell/Tether spline ends=NotAKnot")

# A length tolerance of order the cell: ROS34PW2 at Tolerance 2 ran 4 steps to D12 34% low at
# t = 0.1, without a word.
capsula_add_refusal_test(reliability_tolerance_of_order_the_cell
  MATCHES "'Time integration/Tolerance' = 2 lets a step err in the node positions by as much as [0-9.]+% of the smallest semi-axis of 'Cells/Cell 0'.*Give a tolerance <= 0\\.00[0-9]+"
  COMMAND ${_demo} --set "Time integration/Method=ROS34PW2" --set "Time integration/Tolerance=2")

# An explicit setting silently overridden: Auto set 'Stability limit' back to true (deck.xml
# kept false).
capsula_add_refusal_test(reliability_auto_overriding_the_stability_limit
  MATCHES "'Time integration/Stability limit' = false cannot hold with 'Time integration/Method' = Auto"
  COMMAND ${_demo} --set "Time integration/Method=Auto" --set "Time integration/Stability limit=false")

# Keys without effect in the scene are refused, as an unused 'Spontaneous curvature' is
# (bending.cmake); these three were ignored without a word.
capsula_add_refusal_test(reliability_bending_reference_without_bending
  MATCHES "'Cells/Cell 0/Bending reference' = 'Initial shape' has no effect without bending: set 'Cells/Cell 0/Bending modulus' > 0"
  COMMAND ${_demo} --set "Cells/Cell 0/Bending reference=Initial shape")
capsula_add_refusal_test(reliability_tether2d_bending_reference_without_bending
  MATCHES "'Cell/Bending reference' = 'Initial shape' has no effect without bending"
  COMMAND ${_tether2d} --set "Cell/Bending reference=Initial shape")
capsula_add_refusal_test(reliability_treecode_tolerance_under_direct_summation
  MATCHES "'Operator/Treecode/Tolerance' = 0\\.001 has no effect with 'Operator/Summation' = Direct: set 'Operator/Summation' = Treecode"
  COMMAND ${_demo} --set "Operator/Treecode/Tolerance=1e-3")
foreach(_app cell3d tether2d)
  capsula_add_refusal_test(reliability_${_app}_amplitude_with_a_steady_shear_rate
    MATCHES "'Flow/Shear rate/Amplitude' = 0\\.3 has no effect with 'Flow/Shear rate/Form' = Steady: it is read by Form Pulsatile"
    COMMAND $<TARGET_FILE:${_app}> ${_decks}/${_app}/demo.xml --set "Flow/Shear rate/Amplitude=0.3")
endforeach()

# 'Output/Interval' = 0 ("only the start and the end") under a pulsatile shear rate was refused,
# advising to set it to 0. It runs, and writes the two rows.
set(_interval_zero ${_bad_out}/pulsatile_interval_zero)
capsula_add_reliability_test(reliability_pulsatile_output_interval_zero_runs EXIT_CODE 0
  MATCHES "Done: finished at t = 0\\.02 after"
  COMMAND ${_demo} --set "Flow/Shear rate/Form=Pulsatile" --set "Flow/Shear rate/Period=1" --set "Output/Interval=0"
          --set "Time integration/End time=0.02" --output ${_interval_zero})
set_tests_properties(reliability_pulsatile_output_interval_zero_runs PROPERTIES FIXTURES_SETUP pulsatile_interval_zero)
add_test(NAME reliability_pulsatile_output_interval_zero_writes_start_and_end
  COMMAND /usr/bin/python3 -c "import sys; rows = open(sys.argv[1]).read().split()[1:]; times = [float(r.split(',')[0]) for r in rows]; print(times); sys.exit(times != [0.0, 0.02])"
          ${_interval_zero}/metrics.csv)
set_tests_properties(reliability_pulsatile_output_interval_zero_writes_start_and_end PROPERTIES LABELS reliability
  FIXTURES_REQUIRED pulsatile_interval_zero)

# Command-line mistakes named for what they are.
capsula_add_reliability_test(reliability_set_without_its_value EXIT_CODE 2
  MATCHES "Option --set needs a value, but the next argument is the option '--output'"
  NOT_MATCHES "Two decks given"
  COMMAND $<TARGET_FILE:cell3d> ${_cell3d_demo} --set --output ${_bad_out}/never)
capsula_add_reliability_test(reliability_stiff_quadrature_points_names_its_key EXIT_CODE 2
  MATCHES "'Solver/Stiff/Quadrature points' = 2 has no symmetric triangle rule. use one of 1, 3"
  NOT_MATCHES "Discretisation/Quadrature points' = 2"
  COMMAND ${_demo} --set "Time integration/Method=ROS34PW2" --set "Solver/Stiff/Quadrature points=2"
          --output ${_bad_out}/never)
