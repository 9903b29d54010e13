#!/usr/bin/python3
"""The stability diagnostics over time of the 3D cases of the `stability` test label
(tests/regression/stability.cmake, docs/stability.md), from their run directories.

  stability_diagnostics.png   a) smallest element angle, b) most compressive principal
                              tension, c) lowest node's height over the local element size
                              (cases with a wall), d) |volume drift|, e) step size dt,
                              f) edge ratio, against time; one line per case (two cells:
                              both cells, dashed for Cell 1). Dotted: the bounds the tests
                              assert where they are the same for every case.

Usage: stability_diagnostics.py --out FIGDIR STABILITY_DIR
  STABILITY_DIR: <build>/tests/regression/stability after `ctest -L stability`.
"""
import argparse
import os
import sys

import numpy as np

import capsula_outputs as co

# (directory, legend, has a wall)
CASES = [
    ("sphere_near_wall", "sphere h/a = 1.05, Ca 0.9, C 0.5", True),
    ("chapter5_most_deformable", "Ch5 Ca 0.9, C 0.5, held at h/a = 1.25", True),
    ("neohookean_low_ca_buckling", "neo-Hookean Ca 0.05, no prestress", False),
    ("neohookean_low_ca_prestressed", "neo-Hookean Ca 0.05, 5% prestress", False),
    ("skalak_c10", "Skalak C = 10, Ca 0.9", False),
    ("free_shear_ca1.8", "Ca 1.8 free shear", False),
    ("two_cells_in_line", "two cells in line, dx/a 2.65, h/a 1.25", True),
]


def columns(table, name):
    """The one-cell column, or the per-cell columns NAME_0, NAME_1 of a two-cell table."""
    if name in table:
        return [table[name]]
    return [table[f"{name}_{c}"] for c in range(2) if f"{name}_{c}" in table]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", required=True)
    parser.add_argument("stability_dir")
    args = parser.parse_args()
    plt = co.use_agg()
    fig, axes = plt.subplots(2, 3, figsize=(12, 6.5))
    panels = [("min_angle_deg", "a) smallest element angle (degrees)", False),
              ("min_tension", "b) most compressive tension / G", False),
              ("wall_gap_per_h", "c) lowest node height / local element size", True),
              ("volume_change", "d) |V / V(0) - 1|", False),
              ("dt", "e) step size dt (last accepted)", False),
              ("max_edge_ratio", "f) largest edge ratio", False)]
    found = 0
    for k, (directory, label, wall) in enumerate(CASES):
        path = os.path.join(args.stability_dir, directory, "metrics.csv")
        if not os.path.exists(path):
            print(f"skipping {directory}: no {path}", file=sys.stderr)
            continue
        found += 1
        table = co.read_table(path)
        t = table["time"]
        colour = f"C{k}"
        for ax, (name, title, wallOnly) in zip(axes.flat, panels):
            if wallOnly and not wall:
                continue
            for c, values in enumerate(columns(table, name)):
                y = np.abs(values) if name == "volume_change" else values
                keep = t > 0 if name in ("dt", "volume_change") else np.ones_like(t, dtype=bool)
                ax.plot(t[keep], y[keep], color=colour, linestyle="-" if c == 0 else "--", marker="o",
                        markersize=2.5, label=label if (c == 0 and ax is axes.flat[0]) else None)
            ax.set_title(title)
            ax.set_xlabel("k t")
    if found == 0:
        print("no stability run found under " + args.stability_dir, file=sys.stderr)
        return 1
    axes.flat[0].axhline(25, color="k", linestyle=":", linewidth=0.8)
    axes.flat[1].axhline(0, color="k", linestyle=":", linewidth=0.8)
    axes.flat[2].axhline(0.05, color="k", linestyle=":", linewidth=0.8)
    axes.flat[3].axhline(0.003, color="k", linestyle=":", linewidth=0.8)
    axes.flat[3].set_yscale("log")
    axes.flat[4].set_yscale("log")
    fig.legend(loc="lower center", ncol=4, bbox_to_anchor=(0.5, -0.08))
    co.save_figure(fig, args.out, "stability_diagnostics.png")
    return 0


if __name__ == "__main__":
    sys.exit(main())
