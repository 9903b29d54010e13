#!/usr/bin/python3
"""Two capsules near a wall (thesis Chapter 6) from twocell3d run directories: velocities
against the separation and wall shear stress maps.

The thesis places cell (1) at (dx/2a, h/a, dz/2a) and cell (2) at (-dx/2a, h/a, -dz/2a);
twocell3d's Cell 0 is cell (1) and Cell 1 cell (2) (input/twocell3d/, docs/twocell3d.md),
and metrics.csv has one column per cell (u_slip_0, u_slip_1, ...) and per pair (dx_0_1 =
x_c_0 - x_c_1, dw_0_1, dslip_0_1, ...). Side by side: the decks with cells at the same x;
in line: at the same z. Every output after the transient (t >= --transient) of every run
gives one point at the separation of that output (|dz| or |dx|, centre to centre, over a),
so each run draws a short curve, as in the thesis; one colour per height h/a (of the deck).

  twocell3d_fig6.3_velocities_side_by_side.png    a) U_slip / k a, b) U_migr / k a of both
                                                  cells against dz / a
  twocell3d_fig6.4_relative_spanwise_velocity.png (w_1 - w_2) / k a against dz / a
  twocell3d_fig6.9_velocities_in_line.png         a) U_slip, b) U_migr of the upstream and
                                                  the downstream cell against dx / a
  twocell3d_fig6.10_relative_slip_in_line.png     (U_slip(1) - U_slip(2)) / k a against dx / a
  twocell3d_fig6.6_wall_stress_side_by_side.png   wall shear stress maps at the separations
  twocell3d_fig6.12_wall_stress_in_line.png       run (the last snapshot of each run), the
                                                  5%-above-ambient line in black, the cells'
                                                  shadows dashed. Flow bottom to top (6.6)
                                                  and left to right (6.12), as in the thesis.
Migration velocities come from runs whose heights are free (a held height has none); the
other velocities from held heights when there are such runs, else from free ones.

Usage: twocell3d_figures.py --out FIGDIR [--transient T] RUNDIR_OR_PARENT...
"""
import argparse
import sys

import numpy as np
from matplotlib.ticker import MaxNLocator

import capsula_outputs as co
import cell3d_runs as c3


class PairRun:
    def __init__(self, run):
        self.run = run
        c0 = run.value("Cells/Cell 0/Center")
        c1 = run.value("Cells/Cell 1/Center")
        self.height = c0[1]
        self.fixed = bool(run.value("Cells/Cell 0/Fixed height"))
        self.layout = "side-by-side" if abs(c0[0] - c1[0]) < 1e-12 else "in-line" if abs(c0[2] - c1[2]) < 1e-12 else None
        self.threshold = run.value("Output/Wall shear stress/Threshold", 1.05)

    def after(self, transient):
        m = self.run.table()
        keep = m["time"] >= transient
        if not keep.any() and len(m["time"]):
            keep = m["time"] == m["time"][-1]
        return co.select_rows(m, keep)


def pair_runs(roots):
    runs = []
    for run in co.find_runs(roots, "twocell3d"):
        cells = [k for k in run.value("Cells", {}) if k.startswith("Cell ")]
        if cells == ["Cell 0", "Cell 1"]:
            pair = PairRun(run)
            if pair.layout is not None:
                runs.append(pair)
    return runs


def velocity_source(runs, free_only):
    """Free-height runs for the migration; else held ones if any."""
    if free_only:
        return [r for r in runs if not r.fixed]
    held = [r for r in runs if r.fixed]
    return held or runs


def scatter_runs(ax, runs, transient, separation, value, colours, label_of, **style):
    labelled = set()
    for run in sorted(runs, key=lambda r: (r.height, abs(separation(r.run.table())[0]))):
        m = run.after(transient)
        if len(m["time"]) == 0:
            continue
        label = label_of(run)
        ax.plot(np.abs(separation(m)), value(m), color=colours[run.height],
                label=None if label in labelled else label, **style)
        labelled.add(label)


def height_colours(plt, runs):
    heights = sorted({r.height for r in runs})
    return {h: c for h, c in zip(heights, plt.cm.viridis(np.linspace(0.0, 0.8, max(len(heights), 1))))}


def velocities_figure(runs, plt, out, transient, layout, number):
    name = f"twocell3d_fig6.{number}_velocities_{layout.replace('-', '_')}.png"
    group = [r for r in runs if r.layout == layout]
    if not group:
        print(f"{name}: no {layout} runs; skipped", file=sys.stderr)
        return None
    colours = height_colours(plt, group)
    key = "dz_0_1" if layout == "side-by-side" else "dx_0_1"
    separation = lambda m: m[key]  # noqa: E731 (centre to centre, over a = 1)
    fig, axes = plt.subplots(1, 2, figsize=(9.0, 3.4))
    for ax, (column, label, free_only) in zip(axes, [("u_slip", "U_slip / k a", False),
                                                      ("u_migr", "U_migr / k a", True)]):
        source = velocity_source(group, free_only)
        if layout == "side-by-side":
            for cell, marker in ((0, "o"), (1, "x")):
                scatter_runs(ax, source, transient, separation, lambda m, c=cell: m[f"{column}_{c}"], colours,
                             lambda r, c=cell: f"h/a = {r.height:g}, cell ({c + 1})", marker=marker, ms=3, lw=0.8)
        else:
            # cell (1), Cell 0, starts downstream (x > 0); pick by position at each output
            down = lambda m: np.where(m["x_c_0"] >= m["x_c_1"], m[f"{column}_0"], m[f"{column}_1"])  # noqa: E731
            up = lambda m: np.where(m["x_c_0"] >= m["x_c_1"], m[f"{column}_1"], m[f"{column}_0"])  # noqa: E731
            scatter_runs(ax, source, transient, separation, down, colours,
                         lambda r: f"h/a = {r.height:g}, downstream", marker="o", ms=3, lw=0.8)
            scatter_runs(ax, source, transient, separation, up, colours,
                         lambda r: f"h/a = {r.height:g}, upstream", marker="x", ms=3, lw=0.8, ls="--")
        ax.set_xlabel("dz / a" if layout == "side-by-side" else "dx / a")
        ax.set_ylabel(label)
        held = "held" if source and source[0].fixed else "free"
        ax.set_title(f"{'ab'[column == 'u_migr']}) {label} ({held} heights)")
        if source:
            ax.legend()
        else:
            ax.text(0.5, 0.5, "needs runs with free heights", ha="center", transform=ax.transAxes, color="0.5")
    fig.suptitle(f"two cells {layout}: outputs after t = {transient:g}")
    return co.save_figure(fig, out, name)


def relative_figure(runs, plt, out, transient, layout, number):
    side = layout == "side-by-side"
    name = (f"twocell3d_fig6.{number}_relative_spanwise_velocity.png" if side
            else f"twocell3d_fig6.{number}_relative_slip_in_line.png")
    group = velocity_source([r for r in runs if r.layout == layout], False)
    if not group:
        print(f"{name}: no {layout} runs; skipped", file=sys.stderr)
        return None
    colours = height_colours(plt, group)
    fig, ax = plt.subplots(figsize=(5.0, 3.4))
    key, column, label = (("dz_0_1", "dw_0_1", "(w(1) - w(2)) / k a") if side
                          else ("dx_0_1", "dslip_0_1", "(U_slip(1) - U_slip(2)) / k a"))
    scatter_runs(ax, group, transient, lambda m: m[key], lambda m: m[column], colours,
                 lambda r: f"h/a = {r.height:g}", marker="o", ms=3, lw=0.8)
    ax.axhline(0.0, color="0.6", lw=0.8, ls="--")
    ax.set_xlabel("dz / a" if side else "dx / a")
    ax.set_ylabel(label)
    ax.set_title(f"two cells {layout} ({'held' if group[0].fixed else 'free'} heights), t >= {transient:g}")
    ax.legend()
    return co.save_figure(fig, out, name)


def wall_maps_figure(runs, plt, out, layout, number):
    name = f"twocell3d_fig6.{number}_wall_stress_{layout.replace('-', '_')}.png"
    group = [r for r in runs if r.layout == layout and r.run.value("Output/Wall shear stress/Enabled")]
    # one map per starting separation, at the lowest height, held heights first
    chosen = {}
    for r in sorted(group, key=lambda r: (r.height, not r.fixed)):
        key = round(abs(r.run.table()["dz_0_1" if layout == "side-by-side" else "dx_0_1"][0]), 6)
        chosen.setdefault(key, r)
    maps = []
    for key in sorted(chosen, reverse=True):
        run = chosen[key]
        for snapshot in reversed(run.run.snapshots(c3.SNAPSHOT_BASE)):
            if "wall" in snapshot.blocks:
                maps.append((run, snapshot))
                break
    if not maps:
        print(f"{name}: no {layout} runs with a wall map; skipped", file=sys.stderr)
        return None
    grids = []
    for run, snapshot in maps:
        block = snapshot.blocks["wall"]
        nz, nx = block.grid_shape
        p = block.positions.reshape(nz, nx, 3)
        grids.append((p[:, :, 0], p[:, :, 2], block.node_fields["shear_stress"].reshape(nz, nx)))
    levels = MaxNLocator(nbins=20).tick_values(min(g[2].min() for g in grids), max(g[2].max() for g in grids))
    side = layout == "side-by-side"
    fig, axes = plt.subplots(1 if side else len(maps), len(maps) if side else 1, squeeze=False,
                             figsize=(2.4 * len(maps) + 1.2, 5.0) if side else (7.0, 2.3 * len(maps) + 0.6))
    image = None
    for ax, (run, snapshot), (x, z, sigma) in zip(axes.flat, maps, grids):
        centre = np.mean([c3.centroid(snapshot.blocks[b]) for b in ("cell0", "cell1")], axis=0)
        # side by side: flow (x) upwards, z across (thesis Fig. 6.6); in line: x across (6.12)
        h_axis, v_axis = (z - centre[2], x - centre[0]) if side else (x - centre[0], z - centre[2])
        image = ax.contourf(h_axis, v_axis, sigma, levels=levels, cmap="viridis")
        ax.contour(h_axis, v_axis, sigma, levels=[run.threshold], colors="k", linewidths=1.0)
        for block in ("cell0", "cell1"):
            nodes = snapshot.blocks[block].positions - centre
            outline = c3.convex_outline(nodes[:, [2, 0]] if side else nodes[:, [0, 2]])
            ax.plot(outline[:, 0], outline[:, 1], color="w", lw=1.0, ls="--")
        m = run.run.table()
        sep = abs(m["dz_0_1" if side else "dx_0_1"][-1])
        ax.set_title(f"{'dz' if side else 'dx'}/a = {sep:.3g} at t = {snapshot.time:.3g}")
        ax.set_aspect("equal")
        ax.set_xlabel("z / a" if side else "x / a")
        ax.set_ylabel("x / a (flow upwards)" if side else "z / a")
    fig.colorbar(image, ax=axes, shrink=0.8, label="wall shear stress sigma / mu k")
    fig.suptitle(f"two cells {layout}, h/a = {maps[0][0].height:g}; black: sigma = {maps[0][0].threshold:g}")
    return co.save_figure(fig, out, name)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", required=True, help="folder for the PNG files")
    parser.add_argument("--transient", type=float, default=1.0,
                        help="time k t after which outputs count (default 1)")
    parser.add_argument("runs", nargs="+", help="twocell3d run directories or folders holding them")
    args = parser.parse_args(argv)
    runs = pair_runs(args.runs)
    if not runs:
        print(f"no two-cell twocell3d runs under {' '.join(args.runs)}", file=sys.stderr)
        return 1
    plt = co.use_agg()
    written = [
        velocities_figure(runs, plt, args.out, args.transient, "side-by-side", 3),
        relative_figure(runs, plt, args.out, args.transient, "side-by-side", 4),
        wall_maps_figure(runs, plt, args.out, "side-by-side", 6),
        velocities_figure(runs, plt, args.out, args.transient, "in-line", 9),
        relative_figure(runs, plt, args.out, args.transient, "in-line", 10),
        wall_maps_figure(runs, plt, args.out, "in-line", 12),
    ]
    return 0 if all(written) else 1


if __name__ == "__main__":
    sys.exit(main())
