#!/usr/bin/python3
"""The tethered 3D cell against the tethered 2D cell (docs/cell3d-tether-results.md): tether
force histories, the pivoting of the cell about its anchor, and a table of the key numbers.

Both forces are made dimensionless with the viscous scale of their own problem, which takes
the membrane modulus out:
  3D (cell3d, 'Tether'):  F / (mu k a^2) = (F / G a) / Ca,   a the cell radius
  2D (tether2d):          F / (mu k L)   = (F / E) / Ca,     L = sqrt(ab), F per unit length
Times: k t since the tether holds (3D: from t = 0; 2D: tau = k (t - t_tether) / lambda after the
preparation stage, lambda = 1 here). The pivot angle is the centroid's angle about the anchor
in the shear plane, atan2(y_c - y_A, x_c - x_A) (90: straight above it).

The reference for a rigid sphere (Goldman, Cox & Brenner, Chem Eng Sci 22:653, 1967): a
sphere of radius a held fixed with its centre at h above the wall in the shear flow k y feels
the drag F_x = 6 pi mu a k h f(h/a) along the flow, f -> 1.7005 as it touches the wall
(h/a -> 1); so F_x / (mu k a^2) = 32.05 h / a near contact. The table compares the 3D tether
force's flow component with it at the 3D cell's centroid height.

Usage: cell3d_tether.py --out FIGDIR [--table FILE] RUNDIR_OR_PARENT...
Finds the tethered cell3d runs and the tethered tether2d runs under the given folders and
writes FIGDIR/cell3d_tether_force.png, FIGDIR/cell3d_tether_shapes.png (the finest 3D run
with snapshots: its cut through the shear plane and its tether at a few times, beside the 2D
contours) and with --table the numbers as Markdown.
"""
import argparse
import math
import os
import sys

import numpy as np
from matplotlib.collections import LineCollection

import capsula_outputs as co
import cell3d_runs as c3

GCB_TOUCHING = 1.7005  # Goldman, Cox & Brenner (1967): the drag factor of a fixed sphere at contact


def label3d(run):
    return f"3D, level {run.value('Cells/Cell 0/Mesh level')}"


def label2d(run):
    return f"2D, {run.value('Cell/Number of points')} points"


def history3d(run):
    """k t, F / (mu k a^2), F_x / (mu k a^2), pivot angle, tether angle, centroid height."""
    t = run.table()
    ca = run.value("Flow/Capillary number")
    return dict(time=t["time"], force=t["tether_force"] / ca, force_x=-t["tether_force_x"] / ca,
                pivot=t["pivot_angle_deg"], angle=t["tether_angle_deg"], height=t["y_c"])


def history2d(run):
    """tau after tethering, F / (mu k L), F_x / (mu k L), pivot angle about the anchor."""
    t = run.table()
    ca = run.value("Flow/Capillary number")
    anchor = run.value("Tether/Anchor height")
    pivot = np.degrees(np.arctan2(t["centroid_y"] - anchor, t["centroid_x"]))
    return dict(time=t["time"], force=t["tether_force"] / ca, force_x=t["tether_force_x"] / ca, pivot=pivot,
                height=t["centroid_y"])


def peak(h):
    """The first maximum of the force: the largest value before the force first falls 1% below
    the largest so far (the whole history's maximum if it never does), and its time."""
    force, time = h["force"], h["time"]
    best = 0
    for k in range(len(force)):
        if force[k] > force[best]:
            best = k
        elif force[k] < 0.99 * force[best]:
            break
    return float(force[best]), float(time[best])


def figure(runs3d, runs2d, plt, out):
    fig, axes = plt.subplots(1, 3, figsize=(13.0, 3.4), squeeze=False)
    a, b, c = axes[0]
    for run in runs3d:
        h = history3d(run)
        line, = a.plot(h["time"], h["force"], label=f"{label3d(run)}: F / (mu k a^2)")
        a.plot(h["time"], h["force_x"], ":", color=line.get_color(), label=f"{label3d(run)}: -F_x / (mu k a^2)")
        f, t = peak(h)
        b.plot(h["time"] / t, h["force"] / f, color=line.get_color(), label=label3d(run))
        c.plot(h["time"], h["pivot"], color=line.get_color(), label=label3d(run))
        gcb = 6.0 * math.pi * GCB_TOUCHING * h["height"]
        a.plot(h["time"], gcb, "--", color="grey", linewidth=0.8,
               label="rigid sphere held at the centroid height (GCB 1967)" if run is runs3d[0] else None)
    for run in runs2d:
        h = history2d(run)
        a.plot(h["time"], h["force"], color="k", label=f"{label2d(run)}: F / (mu k L)")
        a.plot(h["time"], h["force_x"], ":", color="k", label=f"{label2d(run)}: F_x / (mu k L)")
        f, t = peak(h)
        b.plot(h["time"] / t, h["force"] / f, color="k", label=label2d(run))
        c.plot(h["time"], h["pivot"], color="k", label=label2d(run))
    end = max([float(history3d(r)["time"][-1]) for r in runs3d] + [1.0])
    a.set_xlim(0.0, end)
    c.set_xlim(0.0, end)
    a.set_xlabel("k t since tethering")
    a.set_ylabel("tether force / viscous scale")
    a.set_title("a) tether force (3D: mu k a^2; 2D: mu k L per unit length)")
    b.set_xlim(0.0, 5.0)
    b.set_xlabel("t / t_peak")
    b.set_ylabel("F / F_max")
    b.set_title("b) the histories' shapes (t_peak, F_max: the first maximum)")
    c.set_xlabel("k t since tethering")
    c.set_ylabel("pivot angle of the centroid (degrees)")
    c.set_title("c) pivoting about the anchor")
    a.legend(fontsize=7, loc="upper left", bbox_to_anchor=(0.0, -0.2), ncol=2)
    b.legend()
    c.legend()
    return co.save_figure(fig, out, "cell3d_tether_force.png")


def pick(snapshots, times):
    """The snapshot nearest each of `times` (each once, in time order)."""
    chosen = []
    for t in times:
        if snapshots:
            best = min(snapshots, key=lambda s: abs(s.time - t))
            if best not in chosen:
                chosen.append(best)
    return sorted(chosen, key=lambda s: s.time)


def shapes_figure(run3d, run2d, plt, out):
    """The 3D cell's cut through the shear plane z = 0 with its tether, and the 2D contour, at
    a few times after tethering (flow left to right, the anchor at the origin)."""
    panels = [("a) " + label3d(run3d) + ": the cut z = 0 and the tether", run3d, "snapshots")]
    if run2d is not None:
        panels.append(("b) " + label2d(run2d) + ": the contour", run2d, "contour"))
    fig, axes = plt.subplots(1, len(panels), figsize=(6.0 * len(panels), 2.8), squeeze=False)
    for ax, (title, run, base) in zip(axes[0], panels):
        series = run.snapshots(base)
        end = series[-1].time if series else 0.0
        chosen = pick(series, [0.0, 1.0, 2.0, 4.0, 0.5 * end, end])
        colours = plt.cm.viridis(np.linspace(0.0, 0.9, max(len(chosen), 1)))
        for snapshot, colour in zip(chosen, colours):
            label = f"k t = {snapshot.time:.3g}"
            if base == "contour":
                xy = snapshot.blocks["cell"].positions[:, :2]
                xy = np.vstack([xy, xy[:1]])
                ax.plot(xy[:, 0], xy[:, 1], color=colour, label=label)
                continue
            cut = c3.plane_cut(c3.flat_triangles(snapshot.blocks["cell0"]), 2, 0.0)
            ax.add_collection(LineCollection(cut[:, :, :2], colors=[colour], linewidths=1.2, label=label))
            tether = snapshot.blocks.get("tether")
            if tether is not None:
                ax.plot(tether.positions[:, 0], tether.positions[:, 1], color=colour, linewidth=2.5)
        ax.axhspan(-0.15, 0.0, color="0.85")
        ax.set_aspect("equal")
        ax.autoscale_view()
        ax.set_ylim(-0.15, None)
        ax.set_xlabel("x / a (3D), x / L (2D)")
        ax.set_ylabel("y")
        ax.set_title(title)
        ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0))
    return co.save_figure(fig, out, "cell3d_tether_shapes.png")


def table(runs3d, runs2d, path):
    lines = ["| run | first maximum of F (k t) | largest F (k t) | F at the end | end k t | change rate at the end "
             "| -F_x at the end | GCB 32.05 h/a at the end | pivot angle at the end | centroid height at the end |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for run in runs3d:
        h = history3d(run)
        s = run.summary["tether"]
        ca = run.value("Flow/Capillary number")
        f, t = peak(h)
        gcb = 6.0 * math.pi * GCB_TOUCHING * h["height"][-1]
        rate = s.get("final force change rate", float("nan"))
        lines.append(f"| {label3d(run)}, Ca = {ca:g}, mu k a^2 | {f:.2f} ({t:.2f}) | {s['peak force'] / ca:.2f} "
                     f"({s['time of peak force']:.2f}) | {h['force'][-1]:.2f} | {h['time'][-1]:.1f} | {rate:.2g} | "
                     f"{h['force_x'][-1]:.2f} | {gcb:.2f} | {h['pivot'][-1]:.1f} | {h['height'][-1]:.3f} |")
    for run in runs2d:
        h = history2d(run)
        ca = run.value("Flow/Capillary number")
        f, t = peak(h)
        largest = run.summary["max"]
        rate = (h["force"][-1] - h["force"][-2]) / ((h["time"][-1] - h["time"][-2]) * h["force"][-1])
        lines.append(f"| {label2d(run)}, Ca = {ca:g}, mu k L | {f:.2f} ({t:.2f}) | {largest['tether_force'] / ca:.2f} "
                     f"({largest['time_of_max_tether_force']:.2f}) | "
                     f"{h['force'][-1]:.2f} | {h['time'][-1]:.1f} | {rate:.2g} | {h['force_x'][-1]:.2f} | | "
                     f"{h['pivot'][-1]:.1f} | {h['height'][-1]:.3f} |")
    co.write_markdown_table(path, lines, list(runs3d) + list(runs2d))
    print(f"wrote {path}")


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", required=True, help="folder for the PNG file")
    parser.add_argument("--table", metavar="FILE", help="also write the numbers as a Markdown table here")
    parser.add_argument("runs", nargs="+", help="run directories or folders holding them")
    args = parser.parse_args(argv)
    runs3d = [r for r in co.find_runs(args.runs, "cell3d") if r.value("Tether/Enabled") and "tether" in r.summary]
    runs2d = [r for r in co.find_runs(args.runs, "tether2d") if r.value("Tether/Enabled") and r.summary.get("tethered")]
    if not runs3d:
        print(f"no tethered cell3d runs under {' '.join(args.runs)}", file=sys.stderr)
        return 1
    runs3d.sort(key=lambda r: r.value("Cells/Cell 0/Mesh level"))
    plt = co.use_agg()
    figure(runs3d, runs2d, plt, args.out)
    with_snapshots = [r for r in runs3d if r.snapshots("snapshots")]
    if with_snapshots:
        shapes_figure(with_snapshots[-1], runs2d[0] if runs2d else None, plt, args.out)
    if args.table:
        table(runs3d, runs2d, args.table)
    return 0


if __name__ == "__main__":
    sys.exit(main())
