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

# suspension3d's own input ('Suspension', docs/suspension3d.md), refused at start-up with
# exit 2, the key named, before an output directory is made: a hematocrit that no whole number
# of cells meets within 1%, counts that do not fit the box, a key a cell type does not have,
# one the placement sets, cells of the deck's own, and a box that is not a periodic channel.
function(suspension3d_refusal name matches deck)
  capsula_add_reliability_test(reliability_suspension3d_${name} EXIT_CODE 2 MATCHES "${matches}"
    NOT_MATCHES "output directory .* was written"
    COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/refused_without_output.sh ${_out}/suspension3d_${name}
            $<TARGET_FILE:suspension3d> ${deck} ${ARGN})
endfunction()
set(_suspension3d_demo ${_decks}/suspension3d/demo.xml)

suspension3d_refusal(hematocrit_out_of_reach
  "'Suspension/Hematocrit' = 0.075 cannot be met within 1% in a box of volume 403.2" ${_suspension3d_demo}
  --set "Suspension/Hematocrit=0.075")
suspension3d_refusal(counts_that_do_not_fit
  "The suspension jams: cell 1 of the 2 of type 'platelet' found no place in 100 random tries" ${_suspension3d_demo}
  --set "Suspension/Attempts=100" --set "Suspension/Cell types/platelet/Semi-axes={5, 5, 1.25}")
suspension3d_refusal(unknown_key_in_a_type
  "'Suspension/Cell types/red_cell/Radios' is not a parameter of this app. Did you mean 'Suspension/Cell types/red_cell/Radius'" ${_suspension3d_demo}
  --set "Suspension/Cell types/red_cell/Radios=1.3")
suspension3d_refusal(placed_key_in_a_type
  "'Suspension/Cell types/platelet/Center' is not a parameter of this app" ${_suspension3d_demo}
  --set "Suspension/Cell types/platelet/Center={1, 2, 3}")
suspension3d_refusal(two_types_fill_the_hematocrit
  "'Suspension/Cell types/red_cell/Count' and 'platelet/Count' are both 0" ${_suspension3d_demo}
  --set "Suspension/Cell types/platelet/Count=0")
suspension3d_refusal(cells_of_its_own
  "'Cells/Cell 0' is given, but the cells of a suspension are placed from 'Suspension/Cell types'"
  ${_bad_decks}/suspension3d-with-a-cell.xml)
suspension3d_refusal(not_a_periodic_channel
  "A suspension fills a channel periodic along x and z" ${_suspension3d_demo}
  --set "Domain/Periodic length z=0")
