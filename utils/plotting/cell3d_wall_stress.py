#!/usr/bin/python3
"""Wall shear stress under a capsule held near the wall (thesis Figs. 5.17 and 5.18), from the
wall grid of the last snapshot of cell3d runs that mapped it (Output/Wall shear stress).

  cell3d_fig5.17_wall_stress_maps.png   sigma / mu k on the wall around the cell, one column
                                        per Ca (C = 2.5, prestress 5%, fixed height); black
                                        line: the deck's threshold (5% above ambient); bottom
                                        row: the same with the outline of the cell's shadow
                                        (white, dashed). Flow bottom to top.
  cell3d_fig5.18_wall_stress_line.png   sigma / mu k along the flow direction on the wall line
                                        under the centroid: a) C = 2.5, prestress 5%, over Ca;
                                        b) Ca = 0.9, no prestress, over C.
The stress is scaled by the ambient wall stress mu k (1 far from the cell); the thesis scales
by E / a, so only the shape of its curves compares directly.

Usage: cell3d_wall_stress.py --out FIGDIR RUNDIR_OR_PARENT...
"""
import argparse
import sys

import numpy as np
from matplotlib.ticker import MaxNLocator

import capsula_outputs as co
import cell3d_runs as c3


def wall_of(run):
    """(snapshot, x grid, z grid, sigma grid) of the last snapshot that has the wall, or None."""
    for snapshot in reversed(run.snapshots()):
        if "wall" in snapshot.blocks:
            block = snapshot.blocks["wall"]
            shape = block.grid_shape  # (nz, nx), x fastest
            p = block.positions.reshape(shape[0], shape[1], 3)
            sigma = block.node_fields["shear_stress"].reshape(shape)
            return snapshot, p[:, :, 0], p[:, :, 2], sigma
    return None


def mapped(runs):
    return [r for r in c3.fixed_height(runs) if r.run.value("Output/Wall shear stress/Enabled")]


def maps_figure(runs, out, plt):
    name = "cell3d_fig5.17_wall_stress_maps.png"
    group = sorted((r for r in c3.family_a(mapped(runs))), key=lambda r: r.ca)
    walls = [(r, wall_of(r)) for r in group]
    walls = [(r, w) for r, w in walls if w is not None]
    if not walls:
        print(f"{name}: no fixed-height run with C = 2.5, prestress 5% and a wall map; skipped", file=sys.stderr)
        return None
    low = min(w[3].min() for _, w in walls)
    high = max(w[3].max() for _, w in walls)
    levels = MaxNLocator(nbins=20).tick_values(low, high)
    fig, axes = plt.subplots(2, len(walls), figsize=(2.0 * len(walls) + 1.2, 6.4), squeeze=False)
    image = None
    for col, (run, (snapshot, x, z, sigma)) in enumerate(walls):
        centre = c3.centroid(snapshot.blocks["cell0"])
        for row in range(2):
            ax = axes[row, col]
            # flow (x) upwards, spanwise z across, both relative to the centroid
            image = ax.contourf(z - centre[2], x - centre[0], sigma, levels=levels, cmap="viridis")
            ax.contour(z - centre[2], x - centre[0], sigma, levels=[run.threshold], colors="k", linewidths=1.0)
            if row == 1:
                nodes = snapshot.blocks["cell0"].positions - centre
                outline = c3.convex_outline(nodes[:, [2, 0]])
                ax.plot(outline[:, 0], outline[:, 1], color="w", lw=1.2, ls="--")
            ax.set_aspect("equal")
            ax.set_xlabel("z / a")
            if col == 0:
                ax.set_ylabel("x / a (flow upwards)")
            if row == 0:
                ax.set_title(f"Ca = {co.label_number(run.ca)}\nt = {snapshot.time:.3g}")
    fig.colorbar(image, ax=axes, shrink=0.8, label="wall shear stress sigma / mu k")
    fig.suptitle(f"C = 2.5, prestress 5%, h/a = {walls[0][0].height0:g}; black: sigma = {walls[0][0].threshold:g}")
    return co.save_figure(fig, out, name)


def line_figure(runs, out, plt):
    name = "cell3d_fig5.18_wall_stress_line.png"
    families = [("a) C = 2.5, prestress 5%", c3.family_a(mapped(runs)), "ca", "Ca"),
                ("b) Ca = 0.9, no prestress", c3.family_b(mapped(runs)), "c", "C")]
    if not any(f[1] for f in families):
        print(f"{name}: no fixed-height runs with a wall map; skipped", file=sys.stderr)
        return None
    fig, axes = plt.subplots(1, 2, figsize=(9.0, 3.4))
    for ax, (title, group, key, label) in zip(axes, families):
        group = sorted(group, key=lambda r: getattr(r, key))
        colours = plt.cm.viridis(np.linspace(0.0, 0.9, max(len(group), 1)))
        for run, colour in zip(group, colours):
            wall = wall_of(run)
            if wall is None:
                continue
            snapshot, x, z, sigma = wall
            centre = c3.centroid(snapshot.blocks["cell0"])
            row = np.argmin(np.abs(z[:, 0] - centre[2]))  # the grid line under the centroid
            ax.plot(x[row] - centre[0], sigma[row], color=colour, label=f"{label} = {co.label_number(getattr(run, key))}")
        ax.axhline(1.0, color="0.6", lw=0.8, ls="--")
        ax.set_xlabel("(x - x_c) / a")
        ax.set_ylabel("wall shear stress sigma / mu k")
        ax.set_title(title)
        if group:
            ax.legend()
        else:
            ax.text(0.5, 0.5, "no runs", ha="center", transform=ax.transAxes, color="0.5")
    fig.suptitle("wall shear stress on the line under the centroid (flow left to right)")
    return co.save_figure(fig, out, name)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", required=True, help="folder for the PNG files")
    parser.add_argument("runs", nargs="+", help="cell3d run directories or folders holding them")
    args = parser.parse_args(argv)
    runs = c3.cell_runs(args.runs)
    plt = co.use_agg()
    written = [maps_figure(runs, args.out, plt), line_figure(runs, args.out, plt)]
    return 0 if all(written) else 1


if __name__ == "__main__":
    sys.exit(main())
