#!/usr/bin/python3
"""Contour figures of the 2D tethered cell (thesis Chapter 4) from tether2d run directories.

  tether2d_fig4.3_contours_over_time.png      contours at several tau, a/b = 1, lambda = 1,
                                              the lowest and the highest Ca run (Fig. 4.3)
  tether2d_fig4.4_final_contours_over_Ca.png  the last contour of every Ca, lambda = 1, one
                                              panel per a/b (Fig. 4.4: equilibrium contours;
                                              the legend says which runs reached it)
  tether2d_fig4.22_stress_along_s.png         principal stress sigma L / E against s / s_max
                                              at four times, and the contours (Fig. 4.22)

Usage: tether2d_contours.py --out FIGDIR RUNDIR_OR_PARENT...
The runs are grouped by a/b, lambda and Ca read from each run's deck.xml.
"""
import argparse
import sys

import numpy as np

import capsula_outputs as co


def parameters(run):
    return (run.value("Cell/Aspect ratio"), run.value("Flow/Viscosity ratio"), run.value("Flow/Capillary number"))


def closed(points):
    return np.vstack([points, points[:1]])


def contour_of(snapshot):
    block = snapshot.blocks["cell"]
    return block.positions[:, :2], block.node_fields


PAD = 0.15  # around the contours, in L; also the depth of the grey wall band


def limits(contours):
    xs = np.concatenate([c[:, 0] for c in contours])
    ys = np.concatenate([c[:, 1] for c in contours])
    return (xs.min() - PAD, xs.max() + PAD), (-PAD, ys.max() + PAD)


def frame(ax, contours, xlim=None):
    """Wall, tether marker, equal axes around the contours (x range `xlim` if given)."""
    own_xlim, ylim = limits(contours)
    xlim = xlim or own_xlim
    ax.axhline(0.0, color="0.3", lw=1.0)
    ax.fill_between(xlim, -PAD, 0.0, color="0.85", lw=0)
    ax.set_xlim(*xlim)
    ax.set_ylim(*ylim)
    ax.set_aspect("equal")
    ax.set_xlabel("x / L")
    ax.set_ylabel("y / L")
    ax.plot([0.0], [min(c[:, 1].min() for c in contours)], marker="^", color="k", ms=4, ls="none")


def stacked_panels(plt, panels, title, name, out):
    """panels: [(title, [(xy, colour, label)])], drawn one above the other, each panel as
    tall as its contours need at equal scales (no empty bands)."""
    panels = [p for p in panels if p[1]]
    shapes = [[xy for xy, _, _ in curves] for _, curves in panels]
    # one x range for all panels, so that equal scales make no empty bands
    xlim = (min(limits(c)[0][0] for c in shapes), max(limits(c)[0][1] for c in shapes))
    heights = [(limits(c)[1][1] - limits(c)[1][0]) / (xlim[1] - xlim[0]) for c in shapes]
    width = 4.8  # inches of plot; the legends take the rest
    fig, axes = plt.subplots(len(panels), 1, squeeze=False, gridspec_kw={"height_ratios": heights},
                             figsize=(width + 2.2, width * sum(heights) + 0.6 * len(panels) + 0.4))
    for ax, (panel_title, curves), contours in zip(axes[:, 0], panels, shapes):
        for xy, colour, label in curves:
            c = closed(xy)
            ax.plot(c[:, 0], c[:, 1], color=colour, label=label)
        frame(ax, contours, xlim)
        ax.set_title(panel_title)
        ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0))
    fig.suptitle(title)
    return co.save_figure(fig, out, name)


def pick_times(snapshots, count):
    """Up to `count` snapshots spread evenly over the run, always the first and the last."""
    if len(snapshots) <= count:
        return snapshots
    indices = np.unique(np.round(np.linspace(0, len(snapshots) - 1, count)).astype(int))
    return [snapshots[i] for i in indices]


def contours_over_time(runs, out, plt):
    chosen = sorted((r for r in runs if parameters(r)[0] == 1.0 and parameters(r)[1] == 1.0),
                    key=lambda r: parameters(r)[2])
    if not chosen:
        print("fig 4.3: no run with a/b = 1 and lambda = 1; skipped", file=sys.stderr)
        return None
    panels = []
    for run, letter in zip([chosen[0]] if len(chosen) == 1 else [chosen[0], chosen[-1]], "ab"):
        snapshots = pick_times(run.snapshots("contour"), 6)
        colours = plt.cm.viridis(np.linspace(0.0, 0.9, len(snapshots)))
        curves = [(contour_of(snap)[0], colour, f"tau = {snap.time:.3g}") for snap, colour in zip(snapshots, colours)]
        panels.append((f"{letter}) a/b = 1, lambda = 1, Ca = {co.label_number(parameters(run)[2])}", curves))
    return stacked_panels(plt, panels, "Cell contours over time after tethering (flow left to right)",
                          "tether2d_fig4.3_contours_over_time.png", out)


def final_contours_over_ca(runs, out, plt):
    chosen = [r for r in runs if parameters(r)[1] == 1.0]
    ratios = sorted({parameters(r)[0] for r in chosen}, reverse=True)
    if not ratios:
        print("fig 4.4: no run with lambda = 1; skipped", file=sys.stderr)
        return None
    panels = []
    for ratio, letter in zip(ratios, "abcd"):
        group = sorted((r for r in chosen if parameters(r)[0] == ratio), key=lambda r: parameters(r)[2])
        colours = plt.cm.plasma(np.linspace(0.0, 0.85, len(group)))
        curves = []
        for run, colour in zip(group, colours):
            last = run.last_snapshot("contour")
            if last is None:
                continue
            state = "equilibrium" if run.summary.get("status") == "steady" else f"tau = {last.time:.3g}"
            curves.append((contour_of(last)[0], colour, f"Ca = {co.label_number(parameters(run)[2])} ({state})"))
        panels.append((f"{letter}) a/b = {co.label_number(ratio)}, lambda = 1", curves))
    return stacked_panels(plt, panels, "Final tethered contours over Ca (flow left to right)",
                          "tether2d_fig4.4_final_contours_over_Ca.png", out)


def stress_along_s(runs, out, plt):
    chosen = sorted((r for r in runs if parameters(r)[0] == 1.0 and parameters(r)[1] == 1.0),
                    key=lambda r: parameters(r)[2])
    if not chosen:
        print("fig 4.22: no run with a/b = 1 and lambda = 1; skipped", file=sys.stderr)
        return None
    run = chosen[0]  # the thesis shows the lowest Ca (0.01)
    snapshots = pick_times(run.snapshots("contour"), 4)
    fig, (left, right) = plt.subplots(1, 2, figsize=(9.0, 3.2), gridspec_kw={"width_ratios": [1.1, 1.0]})
    colours = plt.cm.viridis(np.linspace(0.0, 0.9, len(snapshots)))
    shapes = []
    for snap, colour in zip(snapshots, colours):
        xy, fields = contour_of(snap)
        s = fields["s_over_smax"]
        tension = fields["tension"]
        # s runs from 0 at the tether (node 0) anticlockwise; close the curve at s = 1,
        # where the contour is back at the tether.
        left.plot(np.append(s, 1.0), np.append(tension, tension[0]), color=colour, label=f"tau = {snap.time:.3g}")
        shapes.append(xy)
        c = closed(xy)
        right.plot(c[:, 0], c[:, 1], color=colour)
    left.set_xlabel("s / s_max")
    left.set_ylabel("principal stress sigma L / E")
    left.set_xlim(0.0, 1.0)
    left.legend()
    left.set_title(f"a) membrane stress, a/b = 1, lambda = 1, Ca = {co.label_number(parameters(run)[2])}")
    frame(right, shapes)
    right.set_title("b) the contours (s = 0 at the tether, anticlockwise)")
    return co.save_figure(fig, out, "tether2d_fig4.22_stress_along_s.png")


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", required=True, help="folder for the PNG files")
    parser.add_argument("runs", nargs="+", help="tether2d run directories or folders holding them")
    args = parser.parse_args(argv)
    runs = [r for r in co.find_runs(args.runs, "tether2d") if r.value("Tether/Enabled")]
    if not runs:
        print(f"no tethered tether2d runs under {' '.join(args.runs)}", file=sys.stderr)
        return 1
    plt = co.use_agg()
    written = [contours_over_time(runs, args.out, plt), final_contours_over_ca(runs, args.out, plt),
               stress_along_s(runs, args.out, plt)]
    return 0 if all(written) else 1


if __name__ == "__main__":
    sys.exit(main())
