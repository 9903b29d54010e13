# The suspension's outputs ('Output/Suspension', docs/suspensions.md): a box the deck leaves
# open or one the domain fixes already is refused at start-up with exit 2, the key named, and
# no output directory made.
#
# suspension_refusal(<name> <regex> [--set ...]...) on the twocell3d demo (two cells above the
# wall, not periodic).
function(suspension_refusal name matches)
  capsula_add_reliability_test(reliability_suspension_${name} EXIT_CODE 2 MATCHES "${matches}"
    NOT_MATCHES "output directory .* was written"
    COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/refused_without_output.sh ${_out}/suspension_${name}
            $<TARGET_FILE:twocell3d> ${_decks}/twocell3d/demo.xml --set "Output/Suspension/Enabled=true" ${ARGN})
endfunction()

suspension_refusal(height_left_open
  "'Output/Suspension/Height' = 0, but 'Wall/Channel height' does not bound the domain: give the box's height over which the hematocrit is taken"
  --set "Output/Suspension/Box length x=8" --set "Output/Suspension/Box length z=8")
suspension_refusal(box_length_z_left_open
  "'Output/Suspension/Box length z' = 0, but 'Domain/Periodic length z' does not bound the domain: give the box's length along z"
  --set "Output/Suspension/Height=4" --set "Output/Suspension/Box length x=8")
suspension_refusal(height_given_in_a_channel
  "'Output/Suspension/Height' = 4 is given, but 'Wall/Channel height' = 8 is the box's length there; leave it at 0"
  --set "Wall/Channel height=8" --set "Output/Suspension/Height=4" --set "Output/Suspension/Box length x=8"
  --set "Output/Suspension/Box length z=8")
