#!/usr/bin/python3
"""The adhesion study (docs/cell3d-adhesion-results.md): the regime of each cell3d run of a cell
on a ligand-coated wall, the state diagram of a near-rigid cell in the plane of unstressed
off-rate and reactive compliance, and rolling against membrane stiffness.

Every cell3d run under the folders given is read (metrics.csv, deck.xml, summary.json). A run
with adhesion is compared with the run without adhesion ('Adhesion/Enabled' false) at the same
Ca, mesh level, start and contact strength: both velocities are the centroid's mean velocity along the flow over
the outputs after --late (default: the second half of the run),

    V = (x_c(t_end) - x_c(t_late)) / (t_end - t_late),

and the regime follows from r = V / V_free (classify()):
    firm adhesion   r < 0.02  (the cell creeps less than 2% as fast as a free one; a bonded
                               cell's springs let it creep while it holds)
    rolling         0.02 <= r < 0.5, with bonds at the end
    no adhesion     r >= 0.5, or no bond at the end

The state diagram's axes are k_off0 / k (on top: k_off0 in 1/s at k = 100/s) and gamma / a;
the table gives each run's Bell force k_B T / gamma in units of mu k a^2, the scale of the
hydrodynamic force on the cell (a rigid sphere held at the wall feels 32 mu k a^2, Goldman,
Cox & Brenner 1967).

Writes into --out:
  cell3d_adhesion_state_diagram.png   the regimes over (k_off0, gamma) for the stiffest cells
  cell3d_adhesion_rolling.png         x_c(t) and V, contact area against Ca for one molecule
  with --table FILE: the numbers of every run as Markdown

Usage: cell3d_adhesion.py --out FIGDIR [--table FILE] [--late T] [--check-trends] RUNDIR_OR_PARENT...
       cell3d_adhesion.py --self-test   (the criterion on synthetic velocities)
"""
import argparse
import math
import os
import sys

import numpy as np

import capsula_outputs as co

FIRM_RATIO = 0.02
ROLLING_RATIO = 0.5
REGIMES = {"firm adhesion": ("s", "tab:red"), "rolling": ("o", "tab:green"), "no adhesion": ("^", "tab:blue")}

SHEAR_RATE = 100.0   # 1 / s, for the top axis of the state diagram

# Published molecules that mediate rolling, placed on the diagram by their measured Bell
# constants (unstressed off-rate k_r0 in 1/s, reactive compliance r_0 in m):
#   E-selectin - sialyl Lewis x, Tees, Waugh & Hammer (Biophys J 80:668, 2001), values they
#     find "in the range required for rolling" by Adhesive Dynamics;
#   L-selectin - PSGL-1 / sialyl Lewis x, Evans, Leung, Hammer & Simon (PNAS 98:3784, 2001),
#     the outer of its two barriers, which governs below ~40 pN (the inner one, 0.06 nm and
#     100/s, only above: a bond here carries ~1 pN).
# At SHEAR_RATE, for a cell of radius RADIUS in a medium of viscosity MU, a molecule sits at
# k_off0 / k = k_r0 / SHEAR_RATE and at the gamma / a whose Bell force, with the runs' k_B T,
# equals the molecule's k_B T / r_0 in units of mu k a^2.
PUBLISHED_MOLECULES = [
    dict(label="E-selectin (Tees et al. 2001)", off_rate=0.82, r0=0.034e-9, marker="*", size=260),
    dict(label="L-selectin (Evans et al. 2001)", off_rate=3.0, r0=0.4e-9, marker="D", size=110),
]
RADIUS = 4e-6        # m, a leukocyte
MU = 1e-3            # Pa s
THERMAL_ENERGY = 4.1e-21   # J, k_B T at room temperature


def published_point(molecule, thermal_flow_units):
    """(k_off0 / k, gamma / a) of `molecule` for runs whose k_B T is `thermal_flow_units`
    mu k a^3."""
    force_scale = MU * SHEAR_RATE * RADIUS ** 2
    bell_force = THERMAL_ENERGY / molecule["r0"] / force_scale
    return molecule["off_rate"] / SHEAR_RATE, thermal_flow_units / bell_force


def classify(velocity, free_velocity, bonds_at_end):
    """The regime of a run from its late velocity, the free cell's, and its bonds at the end."""
    if not free_velocity > 0.0:
        raise ValueError(f"the free cell's velocity must be positive, got {free_velocity}")
    ratio = velocity / free_velocity
    if ratio >= ROLLING_RATIO or bonds_at_end <= 0.0:
        return "no adhesion"
    return "firm adhesion" if ratio < FIRM_RATIO else "rolling"


def late_velocity(time, x, late):
    chosen = time >= late - 1e-12
    if chosen.sum() < 2:
        raise ValueError(f"fewer than two outputs after t = {late}")
    t, xs = time[chosen], x[chosen]
    return (xs[-1] - xs[0]) / (t[-1] - t[0])


def read_run(run, late):
    table = run.table()
    rows = table["cell"] == 0 if "cell" in table else slice(None)
    time, x = table["time"][rows], table["x_c"][rows]
    start = late if late is not None else 0.5 * time[-1]
    chosen = time >= start - 1e-12
    adhesion = bool(run.value("Adhesion/Enabled"))
    ca = run.value("Flow/Capillary number")
    row = dict(run=run, name=os.path.relpath(run.directory, os.path.dirname(os.path.dirname(run.directory))),
               ca=ca, level=run.value("Cells/Cell 0/Mesh level"), adhesion=adhesion,
               centre=tuple(run.value("Cells/Cell 0/Center")), strength=run.value("Contact/Strength"),
               end=float(time[-1]), late=start,
               status=run.summary.get("status", "?"), velocity=late_velocity(time, x, start),
               time=time, x=x, y=table["y_c"][rows], d12=float(np.max(table["D12"][rows][chosen])),
               volume_drift=float(np.max(np.abs(table["volume_change"][rows]))))
    if adhesion:
        row.update(off_rate=run.value("Adhesion/Off-rate"), compliance=run.value("Adhesion/Reactive compliance"),
                   thermal=run.value("Adhesion/Thermal energy"), spring=run.value("Adhesion/Spring constant"),
                   on_rate=run.value("Adhesion/On-rate"), bonds=table["bonds"][rows],
                   bonds_end=float(table["bonds"][rows][-1]), bonds_late=float(np.mean(table["bonds"][rows][chosen])),
                   contact=float(np.mean(table["contact_area"][rows][chosen])),
                   gap=float(np.min(table["min_gap"][rows])))
        motion = (run.summary.get("cells") or [{}])[0].get("adhesion", {})
        row["pause_fraction"] = motion.get("pause fraction", float("nan"))
        row["bell_force"] = row["thermal"] / row["compliance"] / ca
    return row


def pair_with_free(rows):
    """Sets each adhesion run's free velocity and regime from the free run of its Ca, level,
    start and contact strength."""
    key = (lambda r: (r["ca"], r["level"], r["centre"], r["strength"]))
    free = {key(r): r for r in rows if not r["adhesion"]}
    for r in rows:
        if not r["adhesion"]:
            continue
        partner = free.get(key(r))
        if partner is None:
            r["regime"] = None
            continue
        r["free_velocity"] = partner["velocity"]
        r["ratio"] = r["velocity"] / partner["velocity"]
        r["regime"] = classify(r["velocity"], partner["velocity"], r["bonds_end"])


def state_grid(rows):
    """The runs of the state diagram: at the stiffest Ca, those sharing the molecules' other
    constants (spring, k_B T, on-rate, repulsion) that most of them share."""
    stiffest = min(r["ca"] for r in rows)
    groups = {}
    for r in rows:
        if r["ca"] == stiffest and r.get("regime"):
            key = (significant(r["spring"]), significant(r["thermal"]), significant(r["on_rate"]), r["strength"])
            groups.setdefault(key, []).append(r)
    return max(groups.values(), key=len, default=[]), stiffest


def state_diagram(rows, out, plt):
    grid, stiffest = state_grid(rows)
    fig, ax = plt.subplots(figsize=(5.2, 3.8))
    for regime, (marker, colour) in REGIMES.items():
        chosen = [r for r in grid if r["regime"] == regime]
        if chosen:
            ax.scatter([r["off_rate"] for r in chosen], [r["compliance"] for r in chosen], marker=marker, s=90,
                       color=colour, label=regime)
    for r in grid:
        ax.annotate(f"{r['ratio']:.3f}", (r["off_rate"], r["compliance"]), textcoords="offset points",
                    xytext=(7, 5), fontsize=7)
    for molecule in PUBLISHED_MOLECULES if grid else []:
        off_rate, compliance = published_point(molecule, grid[0]["thermal"] / stiffest)
        ax.scatter([off_rate], [compliance], marker=molecule["marker"], s=molecule["size"], facecolors="none",
                   edgecolors="black", label=molecule["label"].replace(" (", "\n("))
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("unstressed off-rate k_off0 / k")
    ax.set_ylabel("reactive compliance gamma / a")
    top = ax.secondary_xaxis("top", functions=(lambda k: k * SHEAR_RATE, lambda k: k / SHEAR_RATE))
    top.set_xlabel("k_off0 (1/s) at k = 100/s")
    ax.set_title(f"near-rigid cell (Ca = {stiffest:g}, level {grid[0]['level'] if grid else '?'}); "
                 "V / V_free beside each run;\nhollow: rolling molecules at k = 100/s, a = 4 um", fontsize=8)
    ax.margins(0.15)
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0))
    return co.save_figure(fig, out, "cell3d_adhesion_state_diagram.png")


def significant(value):
    """A key for values that the decks write to 10 digits: equal to 6 significant digits."""
    return f"{value:.6g}"


def largest_series(rows, key):
    """The adhesion runs sharing the key that most values of Ca share, in order of Ca."""
    groups = {}
    for r in rows:
        if r["adhesion"]:
            groups.setdefault(key(r), []).append(r)
    best = max(groups.values(), key=lambda g: (len({r["ca"] for r in g}), -min(r["ca"] for r in g)), default=[])
    return sorted(best, key=lambda r: r["ca"])


def stiffness_series(rows):
    """One molecule in flow units (k_off0 / k, gamma, and the G-based constants over Ca) on
    membranes of several stiffnesses."""
    return largest_series(rows, lambda r: (r["off_rate"], r["compliance"], significant(r["spring"] / r["ca"]),
                                           significant(r["thermal"] / r["ca"])))


def shear_series(rows):
    """One cell and molecule (the constants in units of G, k_off0 / G) at several shear rates:
    Ca and the rates in units of k change together, Ca * k_off0 / k stays."""
    return largest_series(rows, lambda r: (r["spring"], r["thermal"], r["compliance"], significant(r["off_rate"] * r["ca"])))


def rolling_figure(rows, out, plt):
    series = stiffness_series(rows)
    shear = shear_series(rows)
    fig, axes = plt.subplots(1, 4, figsize=(14.0, 3.2))
    colours = plt.cm.viridis(np.linspace(0.0, 0.85, max(len(series), 1)))
    for r, colour in zip(series, colours):
        axes[0].plot(r["time"], r["x"], color=colour, label=f"Ca = {r['ca']:g}")
    if series:
        axes[0].set_title(f"k_off0 = {series[0]['off_rate']:g} k, gamma = {series[0]['compliance']:g} a")
    axes[0].set_xlabel("k t")
    axes[0].set_ylabel("x_c / a")
    axes[0].legend()
    with_free = [r for r in series if r.get("regime")]
    cas = [r["ca"] for r in with_free]
    axes[1].plot(cas, [r["velocity"] for r in with_free], "o-", label="V, with bonds")
    axes[1].plot(cas, [r["free_velocity"] for r in with_free], "s--", label="V_free")
    axes[1].set_ylabel("late velocity / (a k)")
    axes[1].set_title("stiffness: the same molecules, softer membrane")
    axes[1].legend()
    axes[2].plot([r["ca"] for r in series], [r["contact"] for r in series], "o-")
    axes[2].set_ylabel("mean contact area / a^2 (late)")
    axes[2].set_title("contact area against stiffness")
    for ax in axes[1:3]:
        ax.set_xscale("log")
        ax.set_xlabel("Ca = mu k a / G")
    if shear:
        reference = shear[0]["ca"] * shear[0]["off_rate"]   # Ca k_off0 / k = mu a k_off0 / G
        rates = [r["ca"] for r in shear]
        # Velocities in units of a times a fixed rate (k_off0): V / (a k) * k / k_off0.
        axes[3].plot(rates, [r["velocity"] * r["ca"] / reference for r in shear], "o-", label="V, with bonds")
        axes[3].plot(rates, [r["free_velocity"] * r["ca"] / reference if r.get("regime") else np.nan for r in shear],
                     "s--", label="V_free")
        axes[3].set_xscale("log")
        axes[3].set_yscale("log")
        axes[3].set_xlabel("Ca (shear rate k at fixed G)")
        axes[3].set_ylabel("late velocity / (a k_off0)")
        axes[3].set_title("shear rate: one cell and molecule")
        axes[3].legend()
    return co.save_figure(fig, out, "cell3d_adhesion_rolling.png")


def write_table(rows, path, runs):
    lines = ["| run | Ca | k_off0 / k | gamma / a | Bell force / (mu k a^2) | t_end | status | V / (a k) "
             "| V / V_free | regime | pause fraction | bonds (late mean, end) | contact area / a^2 | lowest gap / a | y_c / a at the end "
             "| largest D12 | largest volume change |",
             "|" + "---|" * 17]
    for r in sorted(rows, key=lambda r: (not r["adhesion"], r["ca"], r.get("off_rate", 0), r.get("compliance", 0))):
        if r["adhesion"]:
            ratio = f"{r['ratio']:.3f}" if r.get("regime") else ""
            lines.append(f"| {r['name']} | {r['ca']:g} | {r['off_rate']:g} | {r['compliance']:g} | {r['bell_force']:.3g} "
                         f"| {r['end']:g} | {r['status']} | {r['velocity']:.4f} | {ratio} "
                         f"| {r.get('regime') or ''} | {r['pause_fraction']:.2f} | {r['bonds_late']:.1f}, {r['bonds_end']:.0f} | {r['contact']:.3f} "
                         f"| {r['gap']:.4f} | {r['y'][-1]:.4f} | {r['d12']:.4f} | {r['volume_drift']:.2g} |")
        else:
            lines.append(f"| {r['name']} | {r['ca']:g} | | | | {r['end']:g} | {r['status']} | {r['velocity']:.4f} "
                         f"| 1 | (no adhesion) | | | | | {r['y'][-1]:.4f} | {r['d12']:.4f} | {r['volume_drift']:.2g} |")
    co.write_markdown_table(path, lines, runs)
    print(f"wrote {path}")


def check_trends(rows):
    """Longer-lived bonds hold a cell back more: along each row of the grid (one gamma, the
    stiffest Ca), V / V_free must not fall as k_off0 rises by more than 0.05: another seed moved
    the ratios of three reduced-study runs by up to 0.044, so a smaller fall may be noise.
    Prints the count; returns its success."""
    grid, _ = state_grid(rows)
    counts = {}
    for r in grid:
        counts.setdefault(r["compliance"], []).append(r)
    counts = {compliance: row for compliance, row in counts.items() if len(row) > 1}   # rows, not single runs
    passed = 0
    for compliance, row in sorted(counts.items()):
        ratios = [r["ratio"] for r in sorted(row, key=lambda r: r["off_rate"])]
        if all(b >= a - 0.05 for a, b in zip(ratios, ratios[1:])):
            passed += 1
        else:
            print(f"V / V_free at gamma = {compliance:g} against k_off0: {', '.join(f'{q:.3f}' for q in ratios)}")
    tally = {regime: sum(r["regime"] == regime for r in grid) for regime in REGIMES}
    print("state diagram: " + ", ".join(f"{regime} {n}" for regime, n in tally.items()))
    print(f"V / V_free rises with k_off0 in {passed} of {len(counts)} rows")
    return passed == len(counts)


def self_test():
    failures = []
    cases = [((0.0, 0.5, 40), "firm adhesion"), ((0.009, 0.5, 40), "firm adhesion"),
             ((0.011, 0.5, 40), "rolling"), ((0.2, 0.5, 3), "rolling"), ((0.249, 0.5, 1), "rolling"),
             ((0.25, 0.5, 1), "no adhesion"), ((0.1, 0.5, 0), "no adhesion"), ((0.6, 0.5, 10), "no adhesion")]
    for args, expected in cases:
        got = classify(*args)
        if got != expected:
            failures.append(f"classify{args} = {got}, expected {expected}")
    try:
        classify(0.1, 0.0, 5)
        failures.append("a zero free velocity was accepted")
    except ValueError:
        pass
    for failure in failures:
        print("FAIL:", failure)
    print(f"cell3d_adhesion self-test: {len(failures)} failures")
    return 1 if failures else 0


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", help="folder for the PNG files")
    parser.add_argument("--table", metavar="FILE", help="also write the numbers as a Markdown table here")
    parser.add_argument("--late", type=float, help="start of the window of the late velocity (default: half the run)")
    parser.add_argument("--self-test", action="store_true", help="check the criterion on synthetic velocities")
    parser.add_argument("--check-trends", action="store_true",
                        help="exit 1 unless V / V_free rises with k_off0 along each row of the grid")
    parser.add_argument("runs", nargs="*", help="run directories or folders holding them")
    args = parser.parse_args(argv)
    if args.self_test:
        return self_test()
    if not args.out or not args.runs:
        parser.error("give --out FIGDIR and at least one run folder (or --self-test)")
    runs = [r for r in co.find_runs(args.runs, "cell3d") if r.value("Adhesion") is not None]
    rows = []
    for run in runs:
        try:
            rows.append(read_run(run, args.late))
        except ValueError as error:   # a run that has just started
            print(f"skipped {run.directory}: {error}")
    if not any(r["adhesion"] for r in rows):
        print(f"no cell3d runs with adhesion under {' '.join(args.runs)}", file=sys.stderr)
        return 1
    pair_with_free(rows)
    plt = co.use_agg()
    state_diagram([r for r in rows if r["adhesion"]], args.out, plt)
    rolling_figure(rows, args.out, plt)
    if args.table:
        write_table(rows, args.table, runs)
    trends = check_trends([r for r in rows if r["adhesion"]])
    return 0 if trends or not args.check_trends else 1


if __name__ == "__main__":
    sys.exit(main())
