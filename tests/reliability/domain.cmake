# The domain's keys (walls, channel, periodic box, flow profile; docs/domains.md): a domain
# that cannot hold the cells, a profile the walls cannot carry, a kernel that cannot serve the
# domain are refused at start-up with exit 2, the key named, and no output directory made.
#
# domain_refusal(<name> <regex> <app> <deck> [--set ...]...)
function(domain_refusal name matches app deck)
  capsula_add_reliability_test(reliability_domain_${name} EXIT_CODE 2 MATCHES "${matches}"
    NOT_MATCHES "output directory .* was written"
    COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/refused_without_output.sh ${_out}/domain_${name}
            $<TARGET_FILE:${app}> ${deck} ${ARGN})
endfunction()

set(_twocell3d_demo ${_decks}/twocell3d/demo.xml)

domain_refusal(poiseuille_without_a_channel
  "'Flow/Profile' = 'Poiseuille' is the pressure-driven flow of a channel, but 'Wall/Channel height' is 0"
  cell3d ${_cell3d_demo} --set "Flow/Profile=Poiseuille")
domain_refusal(channel_without_its_lower_wall
  "'Wall/Channel height' = 6 asks for a channel, but 'Wall/Enabled' = false removes its lower wall"
  cell3d ${_cell3d_demo} --set "Wall/Enabled=false" --set "Wall/Channel height=6")
# The demo's unit sphere at height 1.6 reaches y = 2.6.
domain_refusal(cell_through_the_upper_wall
  "'Cells/Cell 0' crosses the upper wall: its highest node \\([0-9]+\\) lies at y = 2\\.6, not more than 'Wall/Minimum gap' = 0\\.025 from it"
  cell3d ${_cell3d_demo} --set "Wall/Channel height=2.55")
domain_refusal(cell_too_close_to_the_upper_wall
  "'Cells/Cell 0' starts too close to the upper wall: .* by more than 0\\.015, lower 'Wall/Minimum gap' or raise 'Wall/Channel height'"
  cell3d ${_cell3d_demo} --set "Wall/Channel height=2.61")
domain_refusal(channel_no_taller_than_the_cell
  "'Wall/Channel height' = 2\\.04 leaves no room for 'Cells/Cell 0', which is 2 tall"
  cell3d ${_cell3d_demo} --set "Wall/Channel height=2.04")
domain_refusal(cell_longer_than_the_periodic_box
  "'Domain/Periodic length x' = 2 is too short for 'Cells/Cell 0', which is 2 long along x.*its own periodic image"
  cell3d ${_cell3d_demo} --set "Domain/Periodic length x=2")
# The demo's cells at z = +-1.25: with L_z = 4.4 the image of Cell 1 reaches into Cell 0.
domain_refusal(cells_overlapping_across_the_periodic_boundary
  "'Cells/Cell 0' and 'Cells/Cell 1' overlap at the start: a node of one lies inside the other \\(across the periodic boundary"
  twocell3d ${_twocell3d_demo} --set "Domain/Periodic length z=4.4")
domain_refusal(no_kernel_serves_a_periodic_box
  "No registered Green's function serves the fluid above the wall y = 0, periodic along x \\(L_x = 8\\) \\('Wall/Enabled' = true, 'Domain/Periodic length x' = 8\\)"
  cell3d ${_cell3d_demo} --set "Domain/Periodic length x=8")
domain_refusal(wall_kernel_named_for_a_channel
  "'Operator/Kernel' = Wall is for the fluid above the wall y = 0 without periodic directions but the deck \\('Wall/Enabled' = true, 'Wall/Channel height' = 6\\) describes a channel 0 < y < 6"
  cell3d ${_cell3d_demo} --set "Operator/Kernel=Wall" --set "Wall/Channel height=6")
# Folding the snapshots into the box needs a box.
domain_refusal(fold_into_box_without_a_period
  "'Output/Fold into box' = true, but the fluid above the wall y = 0 has no periodic direction: set 'Domain/Periodic length x' or 'z'"
  cell3d ${_cell3d_demo} --set "Output/Fold into box=true")
