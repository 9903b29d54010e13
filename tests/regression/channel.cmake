# cell3d in the periodic channel (docs/domains.md; the kernel PeriodicChannel): the demo
# capsule at mesh level 1 in a channel 0 < y < 6, periodic in a box 6 x 6, RK4 steps of 0.02
# to t = 0.4.
#
# Plane Poiseuille flow is symmetric about the mid-plane y = 3, so the capsule started at
# y = 2 (1 rank) and the one started at y = 4 (2 ranks) are mirror images: y_c adds up to 6,
# u_migr to 0, and x_c, u_slip, D12 and the volume are the same. The fast sums reflect the
# upper half into the lower wall's frame, so the two runs differ by round-off and the ranks'
# order of sums only: measured 3.4e-13 (u_slip) on 1 rank each; 1e-8 is the 1 vs 2 rank
# margin of regression_periodic_crossing. The upper wall's kernel taken wrong (or the lower
# wall's used near the upper wall), a profile not symmetric about y = H / 2, or the upper
# wall's contact missing shows as 1e-4 or more.
set(_channel_out ${CMAKE_CURRENT_BINARY_DIR}/channel)
set(_channel_run ${PROJECT_SOURCE_DIR}/input/cell3d/demo.xml --set "Cells/Cell 0/Mesh level=1"
    --set "Domain/Periodic length x=6" --set "Domain/Periodic length z=6" --set "Wall/Channel height=6"
    --set "Output/Wall shear stress/Enabled=false" --set "Time integration/Method=RK4"
    --set "Time integration/Initial step=0.02" --set "Time integration/End time=0.4" --set "Output/Interval=0.04")
add_test(NAME regression_channel_poiseuille_lower
  COMMAND cell3d ${_channel_run} --set "Flow/Profile=Poiseuille" --output ${_channel_out}/lower
          --set "Cells/Cell 0/Center={1.5, 2, 0}")
set_tests_properties(regression_channel_poiseuille_lower PROPERTIES FIXTURES_SETUP channel_lower
  LABELS "mpi;regression")
capsula_add_mpi_command_test(regression_channel_poiseuille_upper
  COMMAND $<TARGET_FILE:cell3d> ${_channel_run} --set "Flow/Profile=Poiseuille" --output ${_channel_out}/upper
          --set "Cells/Cell 0/Center={1.5, 4, 0}"
  LABELS regression TIMEOUT 600)
set_tests_properties(regression_channel_poiseuille_upper PROPERTIES FIXTURES_SETUP channel_upper)
add_test(NAME regression_channel_poiseuille_upper_is_the_mirror
  COMMAND check_metrics mirrored ${_channel_out}/lower/metrics.csv ${_channel_out}/upper/metrics.csv
          y_c=6:1e-8 u_migr=0:1e-8 z_c=0:1e-8)
add_test(NAME regression_channel_poiseuille_upper_moves_alike
  COMMAND check_metrics shifted ${_channel_out}/lower/metrics.csv ${_channel_out}/upper/metrics.csv
          x_c=0:1e-8 u_slip=0:1e-8 D12=0:1e-8 volume=0:1e-8)
set_tests_properties(regression_channel_poiseuille_upper_is_the_mirror regression_channel_poiseuille_upper_moves_alike
  PROPERTIES FIXTURES_REQUIRED "channel_lower;channel_upper" LABELS "mpi;regression")
# Plane Couette flow (the upper wall sliding at k H = 6) maps onto itself under the point
# reflection (x, y) -> (-x, H - y) about the channel's centre, in the frame moving with the
# centre-plane at 3: the capsule started on the centre-plane stays there (u_migr = 0), and its
# centroid moves with the centre-plane (u_slip = 0). The fast sums at 1e-10 (not a symmetry of
# their grid) leave 5e-11 (measured, u_migr and u_slip); 1e-8 is the margin. A channel kernel
# that is not symmetric between its walls (the lower wall's kernel serving the upper half: node
# velocities off by 8.5e-5 in test_periodic_channel) moves the capsule off the plane.
add_test(NAME regression_channel_couette_centre
  COMMAND cell3d ${_channel_run} --output ${_channel_out}/couette --set "Cells/Cell 0/Center={1.5, 3, 0}"
          --set "Operator/PeriodicChannel/Tolerance=1e-10")
set_tests_properties(regression_channel_couette_centre PROPERTIES FIXTURES_SETUP channel_couette
  LABELS regression)
add_test(NAME regression_channel_couette_centre_stays
  COMMAND check_metrics within ${_channel_out}/couette/metrics.csv y_c=2.99999999:3.00000001
          u_migr=-1e-8:1e-8 u_slip=-1e-8:1e-8)
set_tests_properties(regression_channel_couette_centre_stays PROPERTIES FIXTURES_REQUIRED channel_couette
  LABELS regression)
# Viscosity ratio 5 (the channel's fast double layer, solved for by GMRES): the tension-free
# capsule at t = 0 is a drop, whose centroid moves in unbounded Poiseuille flow at
# k f(y_c) - lambda a^2 / (2 (3 lambda + 2)) |f''| (the Faxen law of a drop, Hetsroni & Haber
# 1970; Nadim & Stone 1991), so on the centre-plane u_slip = (5 / 17) a^2 / H for lambda = 5.
# The walls add O((a / H)^3): measured at level 2 in boxes L = H, +5.20% at H = 6, +0.682% at
# H = 12 and +0.091% at H = 24 (the excess falling 7.6 and 7.5 times per doubling; level 3
# moves H = 6 by 4e-5). The windows [+0.4%, +1.0%] at H = 12 and [+0.04%, +0.14%] at H = 24
# hold that law; lambda = 1 (no double layer) gives (1 / 5) a^2 / H, 32% lower, and a wrong
# sign of the double layer O(1). u_migr stays 0 on the centre-plane (measured 1e-10).
# H = 12 runs on 2 ranks.
# The deck is input/cell3d/channel/poiseuille-lambda5.xml (H = 12, box 12 x 12, level 2),
# its capsule moved to the centre-plane and run for one step of 1e-4.
set(_channel_drop ${PROJECT_SOURCE_DIR}/input/cell3d/channel/poiseuille-lambda5.xml
    --set "Output/Wall shear stress/Enabled=false" --set "Time integration/Method=RK4"
    --set "Time integration/Initial step=0.0001" --set "Time integration/End time=0.0001"
    --set "Output/Interval=0.0001")
capsula_add_mpi_command_test(regression_channel_drop_h12
  COMMAND $<TARGET_FILE:cell3d> ${_channel_drop} --set "Cells/Cell 0/Center={1.5, 6, 0}"
          --output ${_channel_out}/drop_h12
  LABELS regression TIMEOUT 600)
set_tests_properties(regression_channel_drop_h12 PROPERTIES FIXTURES_SETUP channel_drop_h12)
add_test(NAME regression_channel_drop_h24
  COMMAND cell3d ${_channel_drop} --set "Domain/Periodic length x=24" --set "Domain/Periodic length z=24"
          --set "Wall/Channel height=24" --set "Cells/Cell 0/Center={1.5, 12, 0}" --output ${_channel_out}/drop_h24)
set_tests_properties(regression_channel_drop_h24 PROPERTIES FIXTURES_SETUP channel_drop_h24 LABELS regression)
add_test(NAME regression_channel_drop_h12_slip_is_the_drops_faxen_law
  COMMAND check_metrics within ${_channel_out}/drop_h12/metrics.csv u_slip=0.0246078:0.0247549
          u_migr=-1e-8:1e-8)
set_tests_properties(regression_channel_drop_h12_slip_is_the_drops_faxen_law PROPERTIES
  FIXTURES_REQUIRED channel_drop_h12 LABELS "mpi;regression")
add_test(NAME regression_channel_drop_h24_slip_is_the_drops_faxen_law
  COMMAND check_metrics within ${_channel_out}/drop_h24/metrics.csv u_slip=0.0122598:0.0122721
          u_migr=-1e-8:1e-8)
set_tests_properties(regression_channel_drop_h24_slip_is_the_drops_faxen_law PROPERTIES
  FIXTURES_REQUIRED channel_drop_h24 LABELS regression)
# The same drop at H = 12 on 1 rank: 1 and 2 ranks agree (measured 3.7e-15, u_migr).
add_test(NAME regression_channel_drop_h12_one_rank
  COMMAND cell3d ${_channel_drop} --set "Cells/Cell 0/Center={1.5, 6, 0}"
          --output ${_channel_out}/drop_h12_one_rank)
set_tests_properties(regression_channel_drop_h12_one_rank PROPERTIES FIXTURES_SETUP channel_drop_h12_one_rank
  LABELS regression)
add_test(NAME regression_channel_drop_h12_one_and_two_ranks_agree
  COMMAND check_metrics shifted ${_channel_out}/drop_h12_one_rank/metrics.csv ${_channel_out}/drop_h12/metrics.csv
          x_c=0:1e-8 y_c=0:1e-8 u_slip=0:1e-8 u_migr=0:1e-8 D12=0:1e-8 volume=0:1e-8)
set_tests_properties(regression_channel_drop_h12_one_and_two_ranks_agree PROPERTIES
  FIXTURES_REQUIRED "channel_drop_h12;channel_drop_h12_one_rank" LABELS "mpi;regression")
# Ligands on the upper wall ('Adhesion/Ligand wall' = Upper) of the periodic Poiseuille channel
# (H = 6, box 6 x 6): the adhesion deck's capsule 0.03 below that wall, RK4 steps of 0.01 to
# t = 0.2. Bonds form to y = 6 and pull the membrane up (bond_force_y > 0), the capsule is
# held at the wall (y_c rises by 0.0012, as the lower wall's run falls by 0.0010), and the gaps
# are measured to the upper wall (min_gap 0.0257, the lower wall's run 0.0258). Goldens
# (measured): `bonds` exactly (the draws are per (seed, receptor, step)), the others to 1e-8.
# The receptors are material points of a mesh that is not the mirror image of the lower run's,
# so the two runs agree in kind, not number for number (31 bonds against 40); the exact mirror
# is BondKinetics.BondsToTheUpperWallAreTheMirrorOfBondsToTheLowerWall.
add_test(NAME regression_channel_adhesion_to_the_upper_wall
  COMMAND cell3d ${PROJECT_SOURCE_DIR}/input/cell3d/adhesion/sphere-ligand-wall.xml
          --set "Time integration/Method=RK4" --set "Time integration/Initial step=0.01"
          --set "Output/Interval=0.1" --set "Time integration/End time=0.2"
          --set "Domain/Periodic length x=6" --set "Domain/Periodic length z=6" --set "Wall/Channel height=6"
          --set "Flow/Profile=Poiseuille" --set "Output/Wall shear stress/Enabled=false"
          --set "Adhesion/Ligand wall=Upper" --set "Cells/Cell 0/Center={0.0, 4.97, 0.0}"
          --output ${_channel_out}/adhesion_upper)
set_tests_properties(regression_channel_adhesion_to_the_upper_wall PROPERTIES FIXTURES_SETUP channel_adhesion_upper
  LABELS regression)
add_test(NAME regression_channel_adhesion_to_the_upper_wall_holds
  COMMAND check_metrics expect ${_channel_out}/adhesion_upper/metrics.csv 0
          time=0.2:1e-12 bonds=31:0 bond_force_y=4.106208418075759:1e-8 y_c=4.971198201369437:1e-8
          min_gap=0.0256896981411405:1e-8)
set_tests_properties(regression_channel_adhesion_to_the_upper_wall_holds PROPERTIES
  FIXTURES_REQUIRED channel_adhesion_upper LABELS regression)

# The wall shear stress maps of the mirrored pair above (capsule at y = 2, 1 rank, and at
# y = 4, 2 ranks, in Poiseuille flow), on a small grid (spacing 0.5, 3 up- and downstream,
# half width 2: 13 x 9 nodes per wall) for two steps (about 4 s and 7 s). Each wall's map is
# sampled along its own normal into the fluid (WallShearStressMap.hpp), so the upper wall's
# map of the mirrored run is the lower wall's map of the first, node for node (du/dn, dw/dn
# and the magnitude), and so are their metrics columns: measured 9.1e-14 (fields) and
# 1.0e-13 (metrics), with the Ewald sums at 1e-10 (at their default 1e-6 they are not
# mirror-symmetric at the flow points to 1.3e-8 in du/dn, test_wall_shear_map); 1e-8 is the
# 1 vs 2 rank margin of the pair above. An upper map sampled near y = 0, or differentiated
# along +e_y, reads the far wall of the mirrored run instead: at t = 0.04 the near wall's map
# spans [0.9894, 1.0142], the far wall's [0.9964, 0.9999].
set(_channel_maps ${_channel_run} --set "Flow/Profile=Poiseuille" --set "Output/Wall shear stress/Enabled=true"
    --set "Output/Wall shear stress/Upstream extent=3" --set "Output/Wall shear stress/Downstream extent=3"
    --set "Output/Wall shear stress/Half width=2" --set "Output/Wall shear stress/Spacing=0.5"
    --set "Time integration/End time=0.04" --set "Output/Interval=0.02"
    --set "Operator/PeriodicChannel/Tolerance=1e-10")
add_test(NAME regression_channel_wall_maps_lower
  COMMAND cell3d ${_channel_maps} --output ${_channel_out}/maps_lower --set "Cells/Cell 0/Center={1.5, 2, 0}")
set_tests_properties(regression_channel_wall_maps_lower PROPERTIES FIXTURES_SETUP channel_maps_lower
  LABELS regression)
capsula_add_mpi_command_test(regression_channel_wall_maps_upper
  COMMAND $<TARGET_FILE:cell3d> ${_channel_maps} --output ${_channel_out}/maps_upper
          --set "Cells/Cell 0/Center={1.5, 4, 0}"
  LABELS regression TIMEOUT 600)
set_tests_properties(regression_channel_wall_maps_upper PROPERTIES FIXTURES_SETUP channel_maps_upper)
add_test(NAME regression_channel_upper_wall_map_of_the_mirror_is_the_lower_wall_map
  COMMAND check_snapshots wall-maps ${_channel_out}/maps_lower/snapshots.h5 wall
          ${_channel_out}/maps_upper/snapshots.h5 upper_wall 1e-8)
add_test(NAME regression_channel_upper_wall_metrics_of_the_mirror_are_the_lower_walls
  COMMAND check_metrics shifted ${_channel_out}/maps_lower/metrics.csv ${_channel_out}/maps_upper/metrics.csv
          wall_stress_min/wall_stress_min_upper=0:1e-8 wall_stress_max/wall_stress_max_upper=0:1e-8
          wall_area_upstream/wall_area_upstream_upper=0:1e-8
          wall_area_downstream/wall_area_downstream_upper=0:1e-8
          wall_stress_min_upper/wall_stress_min=0:1e-8 wall_stress_max_upper/wall_stress_max=0:1e-8)
set_tests_properties(regression_channel_upper_wall_map_of_the_mirror_is_the_lower_wall_map
  regression_channel_upper_wall_metrics_of_the_mirror_are_the_lower_walls
  PROPERTIES FIXTURES_REQUIRED "channel_maps_lower;channel_maps_upper" LABELS "mpi;regression")
# The relative viscosity against Einstein's 1 + 5/2 phi: one stiff spherical capsule (radius 1,
# Skalak C = 2.5, Ca = 0.02, viscosity ratio 1, level 1) on the centre-plane of plane Couette
# flow between walls 8 apart, periodic in a box 8 x 8 (phi = 4.18879 / 512 = 0.0081812), to
# t = 0.4 with Auto. The unloaded membrane first moves with the fluid (1 at t = 0); as its
# tension builds, the capsule turns into a nearly rigid particle: 1.0205758 at t = 0.4
# (changing 7e-5 per 0.05; level 2 gives 1.0206000), 2.515 phi. The window [2.45, 2.60] phi
# holds Einstein's 2.5 with the walls' and images' few-percent increase; a load moment with the
# wrong factor of Ca or sign, or the Poiseuille weight in Couette flow, misses it by O(1). The
# golden's 1e-6 allows the adaptive steps' round-off between machines (1e-8 on one machine).
add_test(NAME regression_channel_relative_viscosity_einstein
  COMMAND cell3d ${PROJECT_SOURCE_DIR}/input/cell3d/channel/poiseuille-lambda5.xml --set "Flow/Profile=Shear"
          --set "Flow/Viscosity ratio=1" --set "Flow/Capillary number=0.02" --set "Wall/Channel height=8"
          --set "Cells/Cell 0/Center={0.0, 4.0, 0.0}" --set "Cells/Cell 0/Mesh level=1"
          --set "Domain/Periodic length x=8" --set "Domain/Periodic length z=8"
          --set "Output/Wall shear stress/Enabled=false" --set "Output/Suspension/Enabled=true"
          --set "Output/Snapshots=false" --set "Time integration/End time=0.4" --set "Time integration/Method=Auto"
          --set "Time integration/Tolerance=1e-4" --set "Output/Interval=0.05"
          --output ${_channel_out}/einstein)
set_tests_properties(regression_channel_relative_viscosity_einstein PROPERTIES FIXTURES_SETUP channel_einstein
  LABELS regression)
add_test(NAME regression_channel_relative_viscosity_is_einsteins
  COMMAND check_metrics expect ${_channel_out}/einstein/metrics.csv - time=0.4:1e-12
          relative_viscosity=1.0205758013384858:1e-6 relative_viscosity=1.0206577:6.14e-4)
set_tests_properties(regression_channel_relative_viscosity_is_einsteins PROPERTIES
  FIXTURES_REQUIRED channel_einstein LABELS regression)
