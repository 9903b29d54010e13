"""The study decks under input/, as deck_writer.py writes them (`deck_writer.py studies`).

Each function yields (path under the repository, comment, [(key path, value), ...]); values are
the text the deck holds. Only the keys a study sets are written; the rest keep the defaults.
"""
import os


def g(x):
    """A number as awk's print writes it (%.6g, no negative zero)."""
    return f"{x + 0.0:.6g}"


# --- cell3d: thesis Chapter 5 and Section 3.12 ---------------------------------------------
#   demo.xml       the default demo (about a minute on 2 cores)
#   heights/       released at (h/a)_0 in {1.2, 1.6, 2, 3, 5, 7.5, 10}: C = 2.5, prestress 5%,
#                  Ca in {0.01, 0.1, 0.3, 0.6, 0.9} (Figs 5.3a, 5.7a, 5.10a, 5.13a, 5.15a, 5.19a,
#                  5.21a), and Ca = 0.9, prestress 0, C in {0.5, 1, 1.5, 2, 2.5} (the b panels)
#   fixed-height/  h/a = 1.25 held fixed (Section 5.1): prestress 5%, every Ca x C (Figs 5.4,
#                  5.8, 5.11, 5.14, 5.16, 5.20, 5.22), and Ca = 0.9, prestress 0, every C (Fig 5.5)
#   unbounded/     the same cells in unbounded shear (top rows of Figs 5.5, 5.6, 5.9)
#   validation/    free shear against Lac et al. (2004) and Lac & Barthes-Biesel (2005); a nearly
#                  rigid capsule against Goldman, Cox & Brenner (1967)
#   adhesion/      a level-1 capsule released 0.03 a above a ligand-coated wall, stochastic bonds
#   channel/       the demo's capsule at viscosity ratio 5 in a periodic Poiseuille channel
#   tether/        a capsule tethered at its lowest point 0.05 a above the wall (the 3D
#                  counterpart of the thesis's Chapter 4 a/b = 1, lambda = 1, Ca = 0.1 case)
# The thesis used mesh level 3 (1280 elements), N_Q = 7 and RKF45; its eps = 1e-10 is replaced
# by 1e-6 (positions in cell radii: a millionth of a radius per step, far below the mesh error).
# Runs end at t = 15, where the thesis reports mesh degradation, or at steady shape.

def cell3d_deck(path, comment, *, ca, height, wall="true", law="Skalak", c="2.5", prestress="0.0",
                fixed="false", level="3", end="15", tolerance="1e-6", steady="0", interval="0.1",
                wall_stress="true", stride="10", near_singular="1", directory=None, spacing="0.25",
                lam="1.0", method="RKF45", shape=(), extra=()):
    directory = directory or f"out/cell3d/{os.path.basename(os.path.dirname(path))}/" \
                             f"{os.path.splitext(os.path.basename(path))[0]}"
    cell = "Cells/Cell 0/"
    wss = "Output/Wall shear stress/"
    return (path, comment + "\n     (written by %WRITER%)", [
        ("Flow/Capillary number", ca), ("Flow/Viscosity ratio", lam),
        ("Wall/Enabled", wall),
        *(shape or [(cell + "Shape", "Sphere"), (cell + "Radius", "1.0")]),
        (cell + "Center", f"{{0.0, {height}, 0.0}}"),
        (cell + "Mesh level", level), (cell + "Membrane law", law), (cell + "Area dilation C", c),
        (cell + "Prestress", prestress), (cell + "Fixed height", fixed),
        ("Time integration/End time", end), ("Time integration/Method", method),
        ("Time integration/Tolerance", tolerance), ("Time integration/Initial step", "1e-3"),
        ("Time integration/Steady tolerance", steady),
        ("Discretisation/Quadrature points", "7"), ("Discretisation/Singular quadrature points", "6"),
        ("Discretisation/Near-singular distance", near_singular),
        ("Output/Directory", directory), ("Output/Interval", interval), ("Output/Snapshot stride", stride),
        (wss + "Enabled", wall_stress), (wss + "Upstream extent", "6.0"), (wss + "Downstream extent", "6.0"),
        (wss + "Half width", "4.0"), (wss + "Spacing", spacing), (wss + "Threshold", "1.05"),
        *extra,
    ])


def cell3d():
    root = "input/cell3d"
    # The demo: level 2, two shear times, with the wall shear stress map: ~10 s on 2 cores.
    yield cell3d_deck(
        f"{root}/demo.xml",
        "Demo: a Skalak capsule (C = 2.5) released at h/a = 1.6 above the wall at Ca = 0.3 (thesis\n"
        "     Chapter 5): it deforms, tilts, tank-treads and starts to lift off the wall.",
        ca="0.3", height="1.6", level="2", end="2.0", tolerance="1e-5", stride="2",
        directory="out/cell3d-demo", spacing="0.5")
    heights = ["1.2", "1.6", "2", "3", "5", "7.5", "10"]
    cas = ["0.01", "0.1", "0.3", "0.6", "0.9"]
    cs = ["0.5", "1", "1.5", "2", "2.5"]
    for h in heights:
        for ca in cas:
            yield cell3d_deck(
                f"{root}/heights/Ca{ca}-C2.5-prestress5-h{h}.xml",
                f"Thesis Figs 5.3a-5.21a: Skalak C = 2.5, prestress 5%, Ca = {ca}, released at (h/a)_0 = {h}.",
                ca=ca, height=h, prestress="0.05")
        for c in cs:
            yield cell3d_deck(
                f"{root}/heights/Ca0.9-C{c}-prestress0-h{h}.xml",
                f"Thesis Figs 5.3b-5.21b: Skalak C = {c}, no prestress, Ca = 0.9, released at (h/a)_0 = {h}.",
                ca="0.9", height=h, c=c)
    held = dict(height="1.25", fixed="true", steady="1e-3")
    for ca in cas:
        for c in cs:
            yield cell3d_deck(
                f"{root}/fixed-height/Ca{ca}-C{c}-prestress5.xml",
                f"Thesis Section 5.1, Figs 5.4-5.22: Skalak C = {c}, prestress 5%, Ca = {ca}, "
                "centroid held at h/a = 1.25.",
                ca=ca, c=c, prestress="0.05", **held)
    free = dict(wall="false", height="0.0", steady="1e-3", wall_stress="false")
    for c in cs:
        yield cell3d_deck(
            f"{root}/fixed-height/Ca0.9-C{c}-prestress0.xml",
            f"Thesis Fig 5.5 (bottom row): Skalak C = {c}, no prestress, Ca = 0.9, centroid held at h/a = 1.25.",
            ca="0.9", c=c, **held)
        yield cell3d_deck(
            f"{root}/unbounded/Ca0.9-C{c}-prestress0.xml",
            f"Thesis Fig 5.5 (top row): Skalak C = {c}, no prestress, Ca = 0.9, unbounded shear.",
            ca="0.9", c=c, **free)
    for ca in cas:
        yield cell3d_deck(
            f"{root}/unbounded/Ca{ca}-C0.5-prestress5.xml",
            f"Thesis Figs 5.6, 5.9 (top rows): Skalak C = 0.5, prestress 5%, Ca = {ca}, unbounded shear.",
            ca=ca, c="0.5", prestress="0.05", **free)

    # Validation (Section 3.12.2). Free shear, lambda = 1, level 3; utils/studies/validate-cell3d.sh
    # runs them at levels 1-3 (docs/validation-cell3d.md). As in the thesis, no adaptive
    # near-singular integration (distance 0): in free shear it moves D12 by ~1e-5 relative and
    # costs 10-20 times the single layer.
    shear = dict(wall="false", height="0.0", end="20", steady="1e-3", wall_stress="false", stride="20",
                 near_singular="0")
    yield cell3d_deck(
        f"{root}/validation/lac2005-skalak-Ca1.8-prestress2.5.xml",
        "Lac & Barthes-Biesel (2005): Skalak capsule (C = 1) prestressed 2.5% at Ca = 1.8 in unbounded\n"
        "     shear, steady D12 = 0.547 (the thesis, Table 3.3: 0.538).",
        ca="1.8", c="1.0", prestress="0.025", **shear)
    for ca in ["0.3", "0.6", "0.9", "1.2"]:
        yield cell3d_deck(
            f"{root}/validation/lac2004-neohookean-Ca{ca}.xml",
            f"Lac et al. (2004), thesis Fig 3.9: neo-Hookean capsule, no prestress, Ca = {ca}, unbounded shear.",
            ca=ca, law="NeoHookean", c="1.0", **shear)
    # Goldman, Cox & Brenner (1967) tabulate the sphere at heights h/a = cosh(alpha), alpha = 0.5,
    # 1, 1.5, 2, 3. A capsule at Ca = 0.01 deforms by D12 = 25/12 Ca ~ 0.02 (Barthes-Biesel &
    # Rallison 1981): nearly rigid, and validate-cell3d.sh extrapolates Ca -> 0 from Ca = 0.01 and
    # 0.005. Its height is held fixed (a rigid sphere does not migrate); the elastic transient is
    # over by t ~ 30 Ca.
    for h in ["1.1276", "1.5431", "2.3524", "3.7622", "10.0677"]:
        yield cell3d_deck(
            f"{root}/validation/goldman-rigid-h{h}.xml",
            f"Goldman, Cox & Brenner (1967): a nearly rigid capsule (Ca = 0.01) held at h/a = {h}; its slip\n"
            "     velocity and rotation rate approach those of a freely suspended rigid sphere.",
            ca="0.01", height=h, law="NeoHookean", c="1.0", fixed="true", level="2", end="0.3",
            interval="0.05", wall_stress="false")
    # Small deformation (Barthes-Biesel & Rallison 1981): D12 = 5/4 (2 + nu)/(1 + nu) Ca with the
    # surface Poisson ratio nu = 1/2 (neo-Hookean), C/(1 + C) (Skalak).
    yield cell3d_deck(
        f"{root}/validation/small-deformation-neohookean-Ca0.01.xml",
        "Small-deformation limit: neo-Hookean capsule at Ca = 0.01 in unbounded shear, D12 -> 25/12 Ca.",
        ca="0.01", wall="false", height="0.0", law="NeoHookean", c="1.0", end="0.3", interval="0.05",
        wall_stress="false", near_singular="0")

    # Pulsatile shear (docs/cell3d-pulsatile-results.md): the demo's capsule (Skalak C = 2.5,
    # Ca = 0.3, released at h/a = 1.6, free height) under k(t) = 1 + 0.5 sin(2 pi t / T) at
    # T = 0.5 and T = 5, against the steady flow of the same mean shear. The membrane relaxes
    # in about one shear time at Ca = 0.3 (the steady run's start-up: tau ~ 0.5-1), so
    # omega tau is ~10 at T = 0.5 (faster than the membrane) and ~1 at T = 5 (close to quasi-
    # static). Level 2, RKF45 at 1e-5 as the demo, to t = 15 (3 and 30 periods); 20 outputs per
    # period (T/20 is also the largest step), no wall stress map.
    pulsatile = dict(ca="0.3", height="1.6", level="2", end="15", tolerance="1e-5", stride="20",
                     wall_stress="false")
    yield cell3d_deck(
        f"{root}/pulsatile/steady.xml",
        "Pulsatile study reference: the demo's capsule (Skalak C = 2.5, Ca = 0.3, released at h/a = 1.6)\n"
        "     in the steady shear of the same mean rate.",
        interval="0.25", **pulsatile)
    for period, interval in [("0.5", "0.025"), ("5", "0.25")]:
        path, comment, assignments = cell3d_deck(
            f"{root}/pulsatile/T{period}-A0.5.xml",
            f"Pulsatile study: the demo's capsule (Skalak C = 2.5, Ca = 0.3, released at h/a = 1.6) under\n"
            f"     k(t) = 1 + 0.5 sin(2 pi t / T), T = {period}.",
            interval=interval, **pulsatile)
        yield path, comment, assignments[:2] + [
            ("Flow/Shear rate/Form", "Pulsatile"), ("Flow/Shear rate/Amplitude", "0.5"),
            ("Flow/Shear rate/Period", period)] + assignments[2:]

    # Viscosity ratio (docs/cell3d-viscosity-ratio-results.md). An initially spherical capsule
    # has no preferred material orientation, so it tank-treads at every lambda; tumbling and
    # swinging need a non-spherical unstressed shape. The cell is an oblate spheroid of aspect
    # ratio 0.8 with the volume of the unit sphere (semi-axes 1.0772, 1.0772, 0.86177: Ca
    # refers to the equal-volume radius, as in Walter et al. 2011 and Dupont et al. 2016),
    # its symmetry axis along the velocity gradient y, so that it turns in the shear plane.
    # Its largest semi-axis stays below 1.25, so it can tumble at h/a = 1.25 without touching
    # the wall. The height is held fixed (Section 5.1), so each run's regime belongs to one
    # height; u_lift is the migration velocity the constraint removes. lambda in {0.2, 1, 2,
    # 5, 10} x Ca in {0.03, 0.05, 0.1, 0.3, 0.9} x {Skalak C = 2.5, neo-Hookean}, at h/a =
    # 1.25 and 2 and in unbounded shear (Ca = 0.03 and 0.05 reach the tumbling side of the
    # transition, which lies below Ca = 0.1 for this shape); a spherical control at lambda =
    # 10, Ca = 0.1. Level 2, Auto at
    # 1e-4 (ROS34PW2 takes over where the membrane holds RKF45's step), to t = 30 (two
    # tumbling periods of a rigid spheroid of this shape, 4 pi (r + 1/r) / 2 ~ 13), outputs
    # every 0.1, a wall stress map at spacing 0.5.
    cell = "Cells/Cell 0/"
    oblate = [(cell + "Shape", "Spheroid"), (cell + "Semi-axes", "{1.0772, 1.0772, 0.86177}"),
              (cell + "Orientation axis", "{1.0, 0.0, 0.0}"), (cell + "Orientation angle", "90")]
    study = dict(level="2", end="30", tolerance="1e-4", method="Auto", stride="50", spacing="0.5")
    laws = [("Skalak", "2.5", "Skalak C = 2.5"), ("NeoHookean", "1.0", "neo-Hookean")]
    for setting, where, placement in [
            ("wall-h1.25", "centroid held at h/a = 1.25", dict(height="1.25", fixed="true")),
            ("wall-h2", "centroid held at h/a = 2", dict(height="2", fixed="true")),
            ("unbounded", "unbounded shear", dict(height="0.0", wall="false", wall_stress="false"))]:
        for law, c, law_name in laws:
            for ca in ["0.03", "0.05", "0.1", "0.3", "0.9"]:
                for lam in ["0.2", "1", "2", "5", "10"]:
                    yield cell3d_deck(
                        f"{root}/viscosity-ratio/{setting}/{law}-Ca{ca}-lambda{lam}.xml",
                        f"Viscosity-ratio study: oblate capsule (aspect ratio 0.8), {law_name}, Ca = {ca},\n"
                        f"     lambda = {lam}, {where}.",
                        ca=ca, lam=lam, law=law, c=c, shape=oblate, **placement, **study)
    for setting, placement in [("wall-h1.25", dict(height="1.25", fixed="true")),
                               ("unbounded", dict(height="0.0", wall="false", wall_stress="false"))]:
        yield cell3d_deck(
            f"{root}/viscosity-ratio/{setting}/sphere-Skalak-Ca0.1-lambda10.xml",
            "Viscosity-ratio study, control: a spherical capsule, Skalak C = 2.5, Ca = 0.1, lambda = 10,\n"
            f"     {'centroid held at h/a = 1.25' if setting != 'unbounded' else 'unbounded shear'}: "
            "it tank-treads.",
            ca="0.1", lam="10", **placement, **study)


    # Red cells (docs/cell3d-red-cell-results.md): the Evans-Fung biconcave cell with the
    # volume of the unit sphere (disc radius R0 = 1.38577 a, a the equal-volume radius Ca
    # refers to), Skalak C = 10 (a nearly area-preserving membrane), bending modulus E_b =
    # k_b / (G a^2) = 0.01 with the initial shape free of bending moments, its symmetry axis
    # along the velocity gradient y so that it turns in the shear plane. Free shear: Ca in
    # {0.05, 0.1, 0.2, 0.4, 0.8} x lambda in {1, 5} (5: the viscosity of haemoglobin over
    # plasma's); near the wall: released at h/a = 2 (free height), Ca in {0.1, 0.4} x lambda
    # in {1, 5}. Level 2, Auto at 1e-4 (ROS34PW2 takes the stiff steps bending and C = 10
    # need), to t = 30, outputs every 0.1.
    red = [(cell + "Shape", "Biconcave"), (cell + "Radius", "1.38577"),
           (cell + "Orientation axis", "{1.0, 0.0, 0.0}"), (cell + "Orientation angle", "90"),
           (cell + "Bending modulus", "0.01"), (cell + "Bending reference", "Initial shape")]
    for setting, where, placement, grid in [
            ("unbounded", "unbounded shear", dict(height="0.0", wall="false", wall_stress="false"),
             [(ca, lam) for lam in ["1", "5"] for ca in ["0.05", "0.1", "0.2", "0.4", "0.8"]]),
            ("wall-h2", "released at h/a = 2 above the wall", dict(height="2"),
             [(ca, lam) for lam in ["1", "5"] for ca in ["0.1", "0.4"]])]:
        for ca, lam in grid:
            yield cell3d_deck(
                f"{root}/red-cell/{setting}/Ca{ca}-lambda{lam}.xml",
                f"Red cell: biconcave (Evans-Fung), Skalak C = 10, bending E_b = 0.01, Ca = {ca},\n"
                f"     lambda = {lam}, {where}.",
                ca=ca, lam=lam, c="10", shape=red, directory=f"out/cell3d/red-cell/{setting}/Ca{ca}-lambda{lam}",
                **placement, **study)


    # Adhesion (docs/cell3d.md, "Adhesion"): a level-1 sphere released 0.03 a above a wall
    # coated with ligands everywhere, Ca = 0.3, Skalak C = 2.5; stochastic Bell slip bonds,
    # 200 receptors per a^2, k_on0 n_L = 100 k, k_off0 = k, k_B T = 4e-3 G a^2 (a bond formed
    # 0.02 a stretched keeps exp(-0.5) of the on-rate), gamma = 0.01 a (a bond stretched by
    # 0.1 a breaks 12 times faster); the contact repulsion within 0.03 a. A short run to t = 2,
    # outputs every 0.1, no wall stress map. The contact load 'Nodal area', as the results of
    # docs/cell3d.md were computed.
    adhesion = "Adhesion/"
    yield cell3d_deck(
        f"{root}/adhesion/sphere-ligand-wall.xml",
        "Adhesion: a Skalak capsule (C = 2.5, Ca = 0.3, level 1) released 0.03 a above a ligand-coated\n"
        "     wall; stochastic Bell slip bonds form within 0.05 a of the wall, slow it down and break.",
        ca="0.3", height="1.03", level="1", end="2", tolerance="1e-4", wall_stress="false", stride="5",
        extra=[("Contact/Enabled", "true"), ("Contact/Range", "0.03"), ("Contact/Load", "Nodal area"),
               (adhesion + "Enabled", "true"),
               (adhesion + "Receptor density", "200"), (adhesion + "On-rate", "1.0"),
               (adhesion + "Off-rate", "1.0"), (adhesion + "Reactive compliance", "1e-2"),
               (adhesion + "Thermal energy", "4e-3"), (adhesion + "Kinetics", "Stochastic"),
               (adhesion + "Seed", "1")])


    # The periodic channel (docs/domains.md): the demo's capsule at viscosity ratio 5 in plane
    # Poiseuille flow between walls 12 apart, in a box periodic along x and z (L = 12), started
    # at y = 4 towards the centre-plane; the wall stress map on both walls. The regression
    # tests run it on the centre-plane for one step (Faxen's law of a drop).
    yield cell3d_deck(
        f"{root}/channel/poiseuille-lambda5.xml",
        "A Skalak capsule (C = 2.5, Ca = 0.3) at viscosity ratio 5 in plane Poiseuille flow between two\n"
        "     walls, 0 < y < 12, periodic along x and z (L = 12; kernel PeriodicChannel): started at\n"
        "     y = 4, it deforms and migrates towards the centre-plane; wall stress maps on both walls.",
        ca="0.3", height="4.0", level="2", end="2.0", tolerance="1e-5", stride="2", lam="5.0",
        directory="out/cell3d-channel", spacing="0.5",
        extra=[("Flow/Profile", "Poiseuille"), ("Wall/Channel height", "12.0"),
               ("Domain/Periodic length x", "12.0"), ("Domain/Periodic length z", "12.0")])

    # Tether (docs/cell3d.md, "Tether"; docs/cell3d-tether-results.md): a sphere released with
    # its lowest point 0.05 a above the wall, tethered there from t = 0 by a spring of rest
    # length 0.05 a (its length at t = 0) and 100 G to the point of the wall below it; the
    # tether's foot a patch of radius 0.17 a (a 2 um wide membrane tether on a 6 um leukocyte
    # radius, thesis Chapter 4). The 2D study's a/b = 1, lambda = 1, Ca = 0.1 case in 3D:
    # Skalak C = 2.5 (the thesis's 3D membrane), no prestress; the contact repulsion within
    # 0.03 a keeps the membrane off the wall as the cell pivots down to it. Level 2, RKF45 at
    # 1e-5, to t = 20, outputs every 0.1, no wall stress map. The contact load 'Nodal area', as
    # docs/cell3d-tether-results.md was computed.
    yield cell3d_deck(
        f"{root}/tether/sphere-Ca0.1.xml",
        "Tether: a Skalak capsule (C = 2.5, Ca = 0.1, level 2) tethered at its lowest point, 0.05 a above\n"
        "     the wall, to the wall below it (thesis Chapter 4's a/b = 1, lambda = 1, Ca = 0.1 case in 3D).",
        ca="0.1", height="1.05", level="2", end="20", tolerance="1e-5", wall_stress="false", stride="10",
        extra=[("Contact/Enabled", "true"), ("Contact/Range", "0.03"), ("Contact/Load", "Nodal area"),
               ("Tether/Enabled", "true"),
               ("Tether/Patch radius", "0.17"), ("Tether/Spring constant", "100")])


# --- twocell3d: thesis Chapter 6, Section 6.1 ------------------------------------------------
#   demo.xml        two cells side by side at h/a = 1.25, level 2, to t = 1
#   side-by-side/   Delta x = 0, Delta z0/a in {0.5, 1, 2, 3, 4, 5, 7.5, 10}
#   in-line/        Delta z = 0, Delta x0/a in {1, 2, 3, 4, 5, 7.5, 10, 20}
#   isolated/       the single cell at the same heights and settings (the thesis's reference)
# each at h/a = 2.5 and 1.25, with the heights held fixed (*-fixed.xml, as in the thesis after
# Uijttewaal et al. 1993) and free (*-free.xml). Ca = 0.3, Skalak C = 2.5, no prestress,
# lambda = 1. Delta x0/a and Delta z0/a are the gaps between the two spheres' surfaces at the
# start, centre distance 2a + Delta0 (docs/twocell3d.md). Cell 0 is the thesis's cell (1) at
# (+Delta x/2, h, +Delta z/2), Cell 1 its cell (2) at the opposite point. Settings as cell3d's:
# level 3, N_Q = 7, N_GL = 6, RKF45 at 1e-6, to t = 15 or steady shape (fixed height), a wall
# shear stress map around both cells (spacing 0.5), 'Cells/Minimum gap' 0.05.

def twocell3d_cell(name, center, level, fixed):
    cell = f"Cells/{name}/"
    return [(cell + "Shape", "Sphere"), (cell + "Radius", "1.0"), (cell + "Center", center),
            (cell + "Mesh level", level), (cell + "Membrane law", "Skalak"), (cell + "Area dilation C", "2.5"),
            (cell + "Prestress", "0.0"), (cell + "Fixed height", fixed)]


def twocell3d_deck(path, comment, *, h, dx=None, dz=None, level="3", fixed, end="15", steady, interval="0.1",
                   stride="10", directory=None):
    """DX, DZ: the centre distances (text); neither for one cell."""
    directory = directory or f"out/twocell3d/{os.path.basename(os.path.dirname(path))}/" \
                             f"{os.path.splitext(os.path.basename(path))[0]}"
    if dx is None:
        cells = twocell3d_cell("Cell 0", f"{{0.0, {h}, 0.0}}", level, fixed)
        upstream = downstream = "6"
        half_width = "4"
    else:
        x, z = float(dx), float(dz)
        cells = (twocell3d_cell("Cell 0", f"{{{g(x / 2)}, {h}, {g(z / 2)}}}", level, fixed)
                 + twocell3d_cell("Cell 1", f"{{{g(-x / 2)}, {h}, {g(-z / 2)}}}", level, fixed))
        upstream = downstream = g(6 + x / 2)
        half_width = g(4 + z / 2)
    wss = "Output/Wall shear stress/"
    return (path, comment + "\n     (written by %WRITER%)", [
        ("Flow/Capillary number", "0.3"), ("Flow/Viscosity ratio", "1.0"),
        ("Wall/Enabled", "true"),
        ("Cells/Minimum gap", "0.05")] + cells + [
        ("Time integration/End time", end), ("Time integration/Method", "RKF45"),
        ("Time integration/Tolerance", "1e-6"), ("Time integration/Initial step", "1e-3"),
        ("Time integration/Steady tolerance", steady),
        ("Discretisation/Quadrature points", "7"), ("Discretisation/Singular quadrature points", "6"),
        ("Discretisation/Near-singular distance", "1"),
        ("Output/Directory", directory), ("Output/Interval", interval), ("Output/Snapshot stride", stride),
        (wss + "Enabled", "true"), (wss + "Upstream extent", upstream), (wss + "Downstream extent", downstream),
        (wss + "Half width", half_width), (wss + "Spacing", "0.5"), (wss + "Threshold", "1.05"),
    ])


def twocell3d():
    root = "input/twocell3d"
    yield twocell3d_deck(
        f"{root}/demo.xml",
        "Demo: two Skalak capsules (C = 2.5, Ca = 0.3) side by side at h/a = 1.25, heights held fixed,\n"
        "     surfaces 0.5 a apart at the start (thesis Chapter 6): they deform, tank-treading, and\n"
        "     move apart across the flow.",
        h="1.25", dx="0", dz="2.5", level="2", fixed="true", end="1.0", steady="0", stride="2",
        directory="out/twocell3d-demo")
    for h in ["2.5", "1.25"]:
        for mode in ["fixed", "free"]:
            fixed = "true" if mode == "fixed" else "false"
            steady = "1e-3" if mode == "fixed" else "0"
            for d in ["0.5", "1", "2", "3", "4", "5", "7.5", "10"]:
                centres = g(2 + float(d))
                yield twocell3d_deck(
                    f"{root}/side-by-side/h{h}-dz{d}-{mode}.xml",
                    f"Thesis Section 6.2 (Figs 6.2-6.6): side by side (Delta x = 0) at h/a = {h} ({mode} height),\n"
                    f"     surfaces Delta z0/a = {d} apart at the start (centre distance {centres} a).",
                    h=h, dx="0", dz=centres, fixed=fixed, steady=steady)
            for d in ["1", "2", "3", "4", "5", "7.5", "10", "20"]:
                centres = g(2 + float(d))
                yield twocell3d_deck(
                    f"{root}/in-line/h{h}-dx{d}-{mode}.xml",
                    f"Thesis Section 6.3 (Figs 6.7-6.12): in line (Delta z = 0) at h/a = {h} ({mode} height),\n"
                    f"     surfaces Delta x0/a = {d} apart at the start (centre distance {centres} a).",
                    h=h, dx=centres, dz="0", fixed=fixed, steady=steady)
            yield twocell3d_deck(
                f"{root}/isolated/h{h}-{mode}.xml",
                f"Thesis Chapter 6 reference: the isolated cell at h/a = {h} ({mode} height), the same settings.",
                h=h, fixed=fixed, steady=steady)
    yield suspension(f"{root}/suspension/ten-cells-wall.xml")


# --- twocell3d suspensions: N cells at random above the wall (utils/decks/random_suspension.py)
#   suspension/ten-cells-wall.xml  ten free level-3 cells of the isolated h/a = 1.25 deck's
#                  settings in a 16 x 5 x 10 box, gaps >= 0.25 a, Treecode far field, to t = 1
#                  with ROS34PW2 (tolerance 1e-3, 40 kept products), a wall shear stress map

def suspension(path):
    import random_suspension
    template = "input/twocell3d/isolated/h1.25-free.xml"
    box = random_suspension.Box(16.0, 10.0, 5.0)
    overrides = ["Operator/Summation=Treecode", "Time integration/End time=1",
                 "Time integration/Method=ROS34PW2", "Time integration/Tolerance=1e-3",
                 "Solver/Stiff/Recycled products=40",
                 "Output/Directory=out/twocell3d/suspension/ten-cells-wall",
                 "Output/Wall shear stress/Upstream extent=12", "Output/Wall shear stress/Downstream extent=12",
                 "Output/Wall shear stress/Half width=9"]
    settings = dict(cells=10, seed=7, gap=0.25, box=box, level=3)
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    command = random_suspension.command_line(template, settings["cells"], settings["seed"], settings["gap"], box,
                                             settings["level"], None, 10000, overrides, path)
    return (path, random_suspension.describe(settings["cells"], settings["seed"], settings["gap"], box, command),
            random_suspension.assignments(os.path.join(root, template), overrides=overrides, **settings))


# --- tether2d: thesis Chapter 4 ----------------------------------------------------------------
# a/b in {0.25, 0.5, 1} x lambda in {1, 5, 10} x Ca in {0.01, 0.025, 0.05, 0.1, 0.25}, 256 points,
# N_GL = 6, RKF45 with eps = 1e-6 (thesis App. A.8), equilibrium at an L2 change of the positions
# below 1e-7 per step (Fig. 4.4). The tethered stage runs to tau = k (t - t0) / lambda of 50
# (Ca <= 0.025), 100 (Ca = 0.05) or 200 (Ca >= 0.1): the thesis's plots end at 10 and 200.

def tether2d():
    for ab in ["0.25", "0.5", "1"]:
        for lam in ["1", "5", "10"]:
            for ca in ["0.01", "0.025", "0.05", "0.1", "0.25"]:
                end = {"0.01": "50", "0.025": "50", "0.05": "100"}.get(ca, "200")
                yield (f"input/tether2d/study/ab{ab}_lambda{lam}_ca{ca}.xml",
                       f"Thesis Chapter 4: a/b = {ab}, lambda = {lam}, Ca = {ca} (written by %WRITER%).", [
                           ("Flow/Capillary number", ca), ("Flow/Viscosity ratio", lam),
                           ("Wall/Enabled", "true"),
                           ("Cell/Aspect ratio", ab), ("Cell/Number of points", "256"),
                           ("Cell/Lowest point height", "0.005"),
                           ("Tether/Enabled", "true"), ("Tether/Anchor height", "0.005"),
                           ("Tether/Preparation tolerance", "1e-3"), ("Tether/Minimum preparation time", "0.5"),
                           ("Tether/Maximum preparation time", "50"),
                           ("Discretisation/Gauss-Legendre points", "6"), ("Discretisation/Log-weighted points", "6"),
                           ("Discretisation/Near-singular distance", "2"),
                           ("Time integration/End time", end), ("Time integration/Method", "RKF45"),
                           ("Time integration/Tolerance", "1e-6"), ("Time integration/Initial step", "1e-3"),
                           ("Time integration/Steady criterion", "L2Change"),
                           ("Time integration/Steady tolerance", "1e-7"),
                           ("Output/Interval", "0.5"), ("Output/Snapshot every", "20"),
                           ("Output/Checkpoint every", "20"),
                       ])


DECKS = {"cell3d": cell3d, "twocell3d": twocell3d, "tether2d": tether2d}
