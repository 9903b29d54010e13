# A time-dependent shear rate ('Flow/Shear rate') with bad values or a bad waveform file: exit
# code 2 and a message naming the key (and the file and line, for what the file holds). Each
# run stops while the deck is read, before a step.
set(_waveforms ${CMAKE_CURRENT_BINARY_DIR}/waveforms)
file(WRITE ${_waveforms}/unsorted.dat "# time, shear rate\n0 1\n0.5 2\n0.4 1\n1 1\n")
file(WRITE ${_waveforms}/not_numeric.dat "0 1\n0.5 fast\n1 1\n")
file(WRITE ${_waveforms}/reversing.dat "0 1\n0.5 -0.5\n1 1\n")

set(_pulsatile --set "Flow/Shear rate/Form=Pulsatile")
set(_tabulated --set "Flow/Shear rate/Form=Tabulated")

foreach(_app cell3d tether2d)
  set(_deck ${_decks}/${_app}/demo.xml)
  set(_run $<TARGET_FILE:${_app}> ${_deck} --output ${CMAKE_CURRENT_BINARY_DIR}/out/never)

  capsula_add_reliability_test(reliability_pulsatile_${_app}_negative_period EXIT_CODE 2
    MATCHES "'Flow/Shear rate/Period'.*-2"
    COMMAND ${_run} ${_pulsatile} --set "Flow/Shear rate/Period=-2")

  capsula_add_reliability_test(reliability_pulsatile_${_app}_reversing_amplitude EXIT_CODE 2
    MATCHES "'Flow/Shear rate/Amplitude' = 1.5 > 1 reverses the flow.*'Flow/Shear rate/Allow reversal' = true"
    COMMAND ${_run} ${_pulsatile} --set "Flow/Shear rate/Amplitude=1.5")

  capsula_add_reliability_test(reliability_pulsatile_${_app}_missing_waveform EXIT_CODE 2
    MATCHES "'Flow/Shear rate/Waveform file' = '[^']*missing\\.dat': the file cannot be opened"
    COMMAND ${_run} ${_tabulated} --set "Flow/Shear rate/Waveform file=${_waveforms}/missing.dat")

  capsula_add_reliability_test(reliability_pulsatile_${_app}_unsorted_waveform EXIT_CODE 2
    MATCHES "'Flow/Shear rate/Waveform file' = '[^']*unsorted\\.dat', line 4: time 0\\.4 does not come after the 0\\.5 of line 3"
    COMMAND ${_run} ${_tabulated} --set "Flow/Shear rate/Waveform file=${_waveforms}/unsorted.dat")

  capsula_add_reliability_test(reliability_pulsatile_${_app}_non_numeric_waveform EXIT_CODE 2
    MATCHES "'Flow/Shear rate/Waveform file' = '[^']*not_numeric\\.dat', line 2: 'fast' \\(the shear rate\\) is not a finite number"
    COMMAND ${_run} ${_tabulated} --set "Flow/Shear rate/Waveform file=${_waveforms}/not_numeric.dat")

  capsula_add_reliability_test(reliability_pulsatile_${_app}_reversing_waveform EXIT_CODE 2
    MATCHES "'Flow/Shear rate/Waveform file' = '[^']*reversing\\.dat', line 2: shear rate -0\\.5 < 0 reverses the flow"
    COMMAND ${_run} ${_tabulated} --set "Flow/Shear rate/Waveform file=${_waveforms}/reversing.dat")
endforeach()

# Outputs that would fall at another phase every period.
capsula_add_reliability_test(reliability_pulsatile_cell3d_output_interval_not_dividing_the_period EXIT_CODE 2
  MATCHES "'Output/Interval' = 0\\.3 does not divide the shear rate's period 1 \\('Flow/Shear rate/Period'\\)"
  COMMAND $<TARGET_FILE:cell3d> ${_decks}/cell3d/demo.xml --output ${CMAKE_CURRENT_BINARY_DIR}/out/never ${_pulsatile}
          --set "Flow/Shear rate/Period=1" --set "Output/Interval=0.3")
capsula_add_reliability_test(reliability_pulsatile_tether2d_output_interval_not_dividing_the_period EXIT_CODE 2
  MATCHES "'Output/Interval' = 0\\.3 \\(times lambda = 2\\) does not divide the shear rate's period 1"
  COMMAND $<TARGET_FILE:tether2d> ${_decks}/tether2d/demo.xml --output ${CMAKE_CURRENT_BINARY_DIR}/out/never
          ${_pulsatile} --set "Flow/Viscosity ratio=2" --set "Flow/Shear rate/Period=1" --set "Output/Interval=0.3")

# A steady-state stop under a pulsating flow (the tether2d demo stops at steady state).
capsula_add_reliability_test(reliability_pulsatile_tether2d_steady_stop EXIT_CODE 2
  MATCHES "'Time integration/Steady tolerance' = 1e-07 stops a run when its state stops changing, which it never does under a periodic shear rate"
  COMMAND $<TARGET_FILE:tether2d> ${_decks}/tether2d/demo.xml --output ${CMAKE_CURRENT_BINARY_DIR}/out/never
          ${_pulsatile})
