#!/usr/bin/python3
"""Deformation and velocity of a capsule near a wall against its height and against C and Ca
(thesis Figs. 5.3-5.22), from cell3d run directories (metrics.csv, summary.json).

Against the height h/a (runs released from several heights, thesis Section 5.1): every
output after the transient (t >= --transient) of every run gives one point (h/a = y_c / a of
that output), so each run draws a short curve and the runs released at different heights
together cover the range, as in the thesis (Fig. 5.2). Panels: a) C = 2.5, prestress 5%,
one colour per Ca; b) Ca = 0.9, no prestress, one colour per C.
  fig5.3 reduced volume, fig5.7 footprint A_xz / pi a^2, fig5.10 slip velocity (with the
  rigid sphere, Goldman et al. 1967 far field 5/16 (a/h)^2), fig5.13 migration velocity,
  fig5.15 increase of the mean membrane shear stress, fig5.19 / fig5.21 wall area with shear
  stress 5% above ambient downstream / upstream (when the runs mapped the wall stress).

Against C and Ca (centroid held at a fixed height, prestress 5%; the steady value, or the last
output if the run stopped before steady state): a) against C, one line per Ca; b) against
Ca, one line per C.
  fig5.4 reduced volume, fig5.8 footprint, fig5.11 slip velocity (rigid sphere at the same
  height dotted), fig5.14 migration velocity (u_lift: the rise rate the fixed-height
  constraint removes), fig5.16 stress increase, fig5.20 / fig5.22 wall areas.

Usage: cell3d_trends.py --out FIGDIR [--transient T] RUNDIR_OR_PARENT...
"""
import argparse
import sys

import numpy as np

import capsula_outputs as co
import cell3d_runs as c3

# column, axis label, figure against h/a, figure against C and Ca, file stem, scale by 1/(pi a^2)
QUANTITIES = [
    ("reduced_volume", "reduced volume nu", 3, 4, "reduced_volume", False),
    ("footprint_xz", "A_xz / pi a^2", 7, 8, "footprint", True),
    ("u_slip", "U_slip / k a", 10, 11, "slip_velocity", False),
    ("u_migr", "U_migr / k a", 13, None, "migration_velocity", False),
    # Fig. 5.14: at a fixed height the migration velocity is the rise rate the constraint
    # removes (u_lift); released cells are drawn by Fig. 5.13 instead.
    ("u_lift", "U_migr / k a (removed by the fixed height)", None, 14, "migration_velocity", False),
    ("mean_shear_stress_increase", "increase of mean |sigma_SS| a / G", 15, 16, "membrane_stress_increase", False),
    ("wall_area_downstream", "wall area downstream / pi a^2", 19, 20, "wall_area_downstream", True),
    ("wall_area_upstream", "wall area upstream / pi a^2", 21, 22, "wall_area_upstream", True),
]


def scale_of(run, per_area):
    return 1.0 / (np.pi * run.radius ** 2) if per_area else 1.0


def against_height(runs, column, label, number, stem, per_area, transient, out, plt):
    name = f"cell3d_fig5.{number}_{stem}_vs_height.png"
    families = [("a) C = 2.5, prestress 5%", c3.family_a(c3.released(runs)), "ca", "Ca"),
                ("b) Ca = 0.9, no prestress", c3.family_b(c3.released(runs)), "c", "C")]
    if not any(f[1] for f in families) or not any(column in r.run.table() for f in families for r in f[1]):
        print(f"{name}: no released runs with '{column}'; skipped", file=sys.stderr)
        return None
    fig, axes = plt.subplots(1, 2, figsize=(9.0, 3.4))
    heights = []
    for ax, (title, group, key, key_label) in zip(axes, families):
        values = sorted({getattr(r, key) for r in group})
        colours = plt.cm.viridis(np.linspace(0.0, 0.9, max(len(values), 1)))
        for value, colour in zip(values, colours):
            first = True
            for run in sorted((r for r in group if getattr(r, key) == value), key=lambda r: r.height0):
                m = run.metrics()
                if column not in m or len(m["time"]) == 0:
                    continue
                keep = m["time"] >= transient
                if not keep.any():
                    keep = m["time"] == m["time"][-1]
                h = m["y_c"][keep] / run.radius
                heights.extend(h)
                ax.plot(h, m[column][keep] * scale_of(run, per_area), color=colour, marker=".", ms=3,
                        label=f"{key_label} = {co.label_number(value)}" if first else None)
                first = False
        if column == "u_slip" and heights:
            h = np.linspace(max(1.0, 0.95 * min(heights)), 1.05 * max(heights), 200)
            ax.plot(h, c3.rigid_sphere_slip(h), "k:", label="rigid sphere, 5/16 (a/h)^2")
        ax.set_xlabel("h / a")
        ax.set_ylabel(label)
        ax.set_title(title)
        if values:
            ax.legend()
    fig.suptitle(f"outputs after t = {transient:g} of runs released at several heights")
    return co.save_figure(fig, out, name)


def against_parameters(runs, column, label, number, stem, per_area, out, plt):
    name = f"cell3d_fig5.{number}_{stem}_vs_C_and_Ca.png"
    group = [r for r in c3.fixed_height(runs) if abs(r.prestress - 0.05) < 1e-12]
    if not group or not any(column in r.run.table() for r in group):
        print(f"{name}: no fixed-height runs with prestress 5% and '{column}'; skipped", file=sys.stderr)
        return None
    fig, axes = plt.subplots(1, 2, figsize=(9.0, 3.4))
    heights = sorted({r.height0 for r in group})
    for ax, (x_key, x_label, line_key, line_label), letter in zip(
            axes, [("c", "C", "ca", "Ca"), ("ca", "Ca", "c", "C")], "ab"):
        lines = sorted({getattr(r, line_key) for r in group})
        colours = plt.cm.viridis(np.linspace(0.0, 0.9, max(len(lines), 1)))
        for value, colour in zip(lines, colours):
            members = sorted((r for r in group if getattr(r, line_key) == value), key=lambda r: getattr(r, x_key))
            xs = [getattr(r, x_key) for r in members]
            ys = [r.steady_or_final(column) * scale_of(r, per_area) for r in members]
            ax.plot(xs, ys, marker="o", ms=4, color=colour, label=f"{line_label} = {co.label_number(value)}")
        if column == "u_slip":
            for h in heights:
                ax.axhline(c3.rigid_sphere_slip(h / group[0].radius), color="k", ls=":",
                           label=f"rigid sphere at h/a = {h:g}")
        if x_key == "ca":
            co.log_axis_at(ax, [r.ca for r in group])
        ax.set_xlabel(x_label)
        ax.set_ylabel(label)
        ax.set_title(f"{letter}) against {x_label}")
        ax.legend()
    fig.suptitle("centroid held at h/a = " + ", ".join(f"{h:g}" for h in heights) + ", prestress 5%")
    return co.save_figure(fig, out, name)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", required=True, help="folder for the PNG files")
    parser.add_argument("--transient", type=float, default=1.0,
                        help="time k t after which outputs of released runs count (default 1)")
    parser.add_argument("runs", nargs="+", help="cell3d run directories or folders holding them")
    args = parser.parse_args(argv)
    runs = c3.cell_runs(args.runs)
    if not runs:
        print(f"no single-cell cell3d runs under {' '.join(args.runs)}", file=sys.stderr)
        return 1
    plt = co.use_agg()
    written = []
    for column, label, vs_height, vs_parameters, stem, per_area in QUANTITIES:
        if vs_height is not None:
            written.append(against_height(runs, column, label, vs_height, stem, per_area, args.transient, args.out, plt))
        if vs_parameters is not None:
            written.append(against_parameters(runs, column, label, vs_parameters, stem, per_area, args.out, plt))
    print(f"{sum(w is not None for w in written)} of {len(written)} figures from {len(runs)} runs")
    return 0 if all(written) else 1


if __name__ == "__main__":
    sys.exit(main())
