# The periodic kernels (Periodic, PeriodicWall, PeriodicChannel; docs/domains.md): what they cannot serve is
# refused at start-up with exit 2, the keys named, and no output directory made.
#
# periodic_refusal(<name> <regex> <app> <deck> [--set ...]...)
function(periodic_refusal name matches app deck)
  capsula_add_reliability_test(reliability_periodic_${name} EXIT_CODE 2 MATCHES "${matches}"
    NOT_MATCHES "output directory .* was written"
    COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/refused_without_output.sh ${_out}/periodic_${name}
            $<TARGET_FILE:${app}> ${deck} ${ARGN})
endfunction()

# The treecode sums the free-space and Blake kernels only.
periodic_refusal(treecode_with_a_periodic_kernel
  "'Operator/Summation' = Treecode does not support the periodic lower wall kernel \\('Operator/Kernel'\\); use 'Operator/Summation' = Direct"
  cell3d ${_cell3d_demo} --set "Domain/Periodic length x=8" --set "Domain/Periodic length z=8"
  --set "Operator/Summation=Treecode")
# The Ewald sums are doubly periodic: a box periodic along x only has no periodic kernel.
periodic_refusal(periodic_kernel_named_for_one_period
  "'Operator/Kernel' = PeriodicWall is for the fluid above the wall y = 0, periodic along x and z but the deck \\('Wall/Enabled' = true, 'Domain/Periodic length x' = 8\\) describes"
  cell3d ${_cell3d_demo} --set "Domain/Periodic length x=8" --set "Operator/Kernel=PeriodicWall")
