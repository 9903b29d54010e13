# Bending keys with bad values or that contradict each other: exit code 2 and a message
# naming the key, before a step is taken (cell3d and twocell3d read the same cell keys).
foreach(_app cell3d twocell3d)
  set(_run $<TARGET_FILE:${_app}> ${_decks}/${_app}/demo.xml --output ${CMAKE_CURRENT_BINARY_DIR}/out/never)

  capsula_add_reliability_test(reliability_bending_${_app}_negative_modulus EXIT_CODE 2
    MATCHES "'Cells/Cell 0/Bending modulus' = -0\\.01 is invalid: it must be a finite real number >= 0"
    COMMAND ${_run} --set "Cells/Cell 0/Bending modulus=-0.01")

  capsula_add_reliability_test(reliability_bending_${_app}_spontaneous_curvature_without_modulus EXIT_CODE 2
    MATCHES "'Cells/Cell 0/Spontaneous curvature' = 2 has no effect without bending: set 'Cells/Cell 0/Bending modulus' > 0"
    COMMAND ${_run} --set "Cells/Cell 0/Spontaneous curvature=2")

  capsula_add_reliability_test(reliability_bending_${_app}_with_the_contour_integral_load EXIT_CODE 2
    MATCHES "'Cells/Cell 0/Bending modulus' > 0 needs 'Cells/Cell 0/Membrane forces' = 'Virtual work'"
    COMMAND ${_run} --set "Cells/Cell 0/Bending modulus=0.01" --set "Cells/Cell 0/Membrane forces=Contour integral")

  capsula_add_reliability_test(reliability_bending_${_app}_two_reference_curvatures EXIT_CODE 2
    MATCHES "'Cells/Cell 0/Spontaneous curvature' = 1 and 'Cells/Cell 0/Bending reference' = 'Initial shape' both set"
    COMMAND ${_run} --set "Cells/Cell 0/Bending modulus=0.01" --set "Cells/Cell 0/Spontaneous curvature=1"
            --set "Cells/Cell 0/Bending reference=Initial shape")
endforeach()
