#!/usr/bin/python3
"""Cell profiles of thesis Chapter 5 from cell3d run directories (the last snapshot of each run).

  cell3d_fig5.5_xy_profiles_over_C.png    Ca = 0.9, no prestress, one column per C
  cell3d_fig5.6_xy_profiles_over_Ca.png   C = 0.5, prestress 5%, one column per Ca
  cell3d_fig5.9_xz_profiles_over_Ca.png   the same cells seen from above the wall
Top row: the cell in unbounded shear; bottom row: held at a fixed height above the wall
(the thesis's h/a = 1.25). Each profile is the cell's shadow on the plane (filled, the
footprint A_xz in the xz view) and its cut through the centroid (line). Flow left to right.

Usage: cell3d_profiles.py --out FIGDIR RUNDIR_OR_PARENT...
"""
import argparse
import sys

import numpy as np
from matplotlib.collections import LineCollection, PolyCollection

import capsula_outputs as co
import cell3d_runs as c3


def draw_profile(ax, run, plane, colour):
    """Shadow and centroid cut of the cell of `run` on the xy or xz plane; x is centred on the
    centroid, y stays measured from the wall (unbounded runs: from the centroid)."""
    snapshot = run.last_snapshot()
    if snapshot is None:
        return None
    block = snapshot.blocks["cell0"]
    tri = c3.flat_triangles(block)
    centre = c3.centroid(block)
    second = 1 if plane == "xy" else 2
    cut_axis = 2 if plane == "xy" else 1
    shift = np.array([centre[0], centre[1] if (plane == "xz" or not run.wall) else 0.0, centre[2]])
    flat = tri - shift
    polygons = flat[:, :, [0, second]]
    # opaque (overlapping translucent triangles would show the mesh)
    ax.add_collection(PolyCollection(polygons, facecolors=colour, edgecolors=colour, linewidths=0.3))
    cut = c3.plane_cut(flat, cut_axis, 0.0)  # through the centroid (z = z_c or y = y_c)
    ax.add_collection(LineCollection(cut[:, :, [0, second]], colors="k", linewidths=0.9))
    return snapshot.time, polygons


def profile_figure(columns, plane, title, name, out, plt):
    """columns: [(label, unbounded run or None, wall run or None)]."""
    columns = [c for c in columns if c[1] is not None or c[2] is not None]
    if not columns:
        print(f"{name}: no runs; skipped", file=sys.stderr)
        return None
    rows = ["unbounded", "near the wall"]
    fig, axes = plt.subplots(2, len(columns), figsize=(1.9 * len(columns) + 0.8, 4.6), squeeze=False)
    colour = "#f2a7a0"
    width, low, high = 1.0, -1.0, 1.0
    wall_row_top = 2.0
    for col, (label, free, bounded) in enumerate(columns):
        for row, run in enumerate((free, bounded)):
            ax = axes[row, col]
            ax.set_aspect("equal")
            ax.set_xticks([])
            ax.set_yticks([])
            for spine in ax.spines.values():
                spine.set_visible(False)
            if row == 0:
                ax.set_title(label)
            if col == 0:
                ax.text(-0.08, 0.5, rows[row], rotation=90, ha="right", va="center", transform=ax.transAxes)
            drawn = draw_profile(ax, run, plane, colour) if run is not None else None
            if drawn is None:
                ax.text(0.5, 0.5, "no run" if run is None else "no snapshot", ha="center", va="center",
                        transform=ax.transAxes, color="0.5")
                continue
            time, polygons = drawn
            width = max(width, np.abs(polygons[:, :, 0]).max())
            note = f"t = {time:.3g}"
            if run.wall and plane == "xy":
                ax.axhline(0.0, color="0.3", lw=1.0)
                wall_row_top = max(wall_row_top, polygons[:, :, 1].max())
                note += f", h/a = {run.steady_or_final('y_c'):.3g}"
            else:
                low = min(low, polygons[:, :, 1].min())
                high = max(high, polygons[:, :, 1].max())
            ax.text(0.5, -0.02, note, transform=ax.transAxes, fontsize=7, ha="center", va="top", color="0.3")
    pad = 0.08
    for col in range(len(columns)):
        for row, run in enumerate(columns[col][1:]):
            ax = axes[row, col]
            ax.set_xlim(-width - pad, width + pad)
            if run is not None and run.wall and plane == "xy":
                ax.set_ylim(-pad, wall_row_top + pad)
            else:
                ax.set_ylim(low - pad, high + pad)
    fig.suptitle(f"{title}\nflow left to right; filled: the cell's shadow on the plane, line: its cut "
                 f"through the centroid", fontsize=9)
    return co.save_figure(fig, out, name)


def columns_over(runs, key, label):
    values = sorted({getattr(r, key) for r in runs})
    columns = []
    for v in values:
        free = [r for r in c3.unbounded(runs) if getattr(r, key) == v]
        bounded = [r for r in c3.fixed_height(runs) if getattr(r, key) == v]
        columns.append((f"{label} = {co.label_number(v)}", free[0] if free else None, bounded[0] if bounded else None))
    return columns


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", required=True, help="folder for the PNG files")
    parser.add_argument("runs", nargs="+", help="cell3d run directories or folders holding them")
    args = parser.parse_args(argv)
    runs = c3.cell_runs(args.runs)
    plt = co.use_agg()
    over_c = [r for r in c3.family_b(runs) if not r.wall or r.fixed]
    over_ca = [r for r in runs if r.c == 0.5 and abs(r.prestress - 0.05) < 1e-12 and (not r.wall or r.fixed)]
    written = [
        profile_figure(columns_over(over_c, "c", "C"), "xy", "xy profiles, Ca = 0.9, no prestress",
                       "cell3d_fig5.5_xy_profiles_over_C.png", args.out, plt),
        profile_figure(columns_over(over_ca, "ca", "Ca"), "xy", "xy profiles, C = 0.5, prestress 5%",
                       "cell3d_fig5.6_xy_profiles_over_Ca.png", args.out, plt),
        profile_figure(columns_over(over_ca, "ca", "Ca"), "xz", "xz profiles, C = 0.5, prestress 5%",
                       "cell3d_fig5.9_xz_profiles_over_Ca.png", args.out, plt),
    ]
    return 0 if all(written) else 1


if __name__ == "__main__":
    sys.exit(main())
