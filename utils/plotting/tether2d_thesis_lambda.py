#!/usr/bin/python3
"""The thesis's lambda trend against this code's (docs/tether2d.md, "Why the thesis finds the
opposite trend"): tether force, A/A0 and L_cell over k (t - t_tether) for tethered a/b = 1
runs of one Ca, on the thesis's time axis k (t - t_tether) / Lambda with Lambda the thesis's
viscosity ratio. A run with lambda < 1 is drawn as the thesis's Lambda = 1/lambda: its eq
A.35 with the inward normal of eqs A.26-A.27 is this code's 1/lambda run Lambda times slower,
so its time is this run's k t. A run with lambda >= 1 is this code's own, Lambda = lambda, at
its tau = k t / lambda. At most the first 40 units are drawn (the maxima come within 12).

Usage: tether2d_thesis_lambda.py --out FIGDIR RUNDIR_OR_PARENT...
Writes FIGDIR/tether2d_thesis_lambda_ca<Ca>.png, one per Ca among the runs.
"""
import argparse
import sys

import numpy as np

import capsula_outputs as co

PANELS = [("tether_force", "F / E"), ("contour_length_ratio", "A / A0"), ("cell_length", "L_cell / L")]


def label(lam):
    if lam < 1.0:
        return f"thesis's lambda = {1.0 / lam:g} (lambda = {lam:g} here)"
    return f"lambda = {lam:g}" + ("" if lam == 1.0 else " (this code)")


def figure(runs, plt, out, ca):
    runs = sorted(runs, key=lambda r: r.value("Flow/Viscosity ratio"))
    fig, axes = plt.subplots(1, len(PANELS), figsize=(4.3 * len(PANELS), 3.2), squeeze=False)
    end = 0.0
    for run in runs:
        lam = run.value("Flow/Viscosity ratio")
        table = run.table()
        # this code's tau = k t / lambda; the thesis's time is k t / Lambda
        scale = lam if lam < 1.0 else 1.0
        time = (np.asarray(table["time"]) - run.summary["preparation time"]) * scale
        end = max(end, float(time[-1]))
        style = "-" if lam <= 1.0 else "--"
        for ax, (column, _) in zip(axes[0], PANELS):
            ax.plot(time, table[column], style, label=label(lam))
    for ax, (_, name), letter in zip(axes[0], PANELS, "abc"):
        ax.set_xlabel("k (t - t_tether) / Lambda  (Lambda: the thesis's lambda)")
        ax.set_xlim(-0.5, min(end, 40.0))
        ax.set_ylabel(name)
        ax.set_title(f"{letter}) a/b = 1, Ca = {ca:g}")
    axes[0][0].legend()
    return co.save_figure(fig, out, f"tether2d_thesis_lambda_ca{ca:g}.png")


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", required=True, help="folder for the PNG files")
    parser.add_argument("runs", nargs="+", help="tether2d run directories or folders holding them")
    args = parser.parse_args(argv)
    runs = [r for r in co.find_runs(args.runs, "tether2d")
            if r.value("Tether/Enabled") and r.value("Cell/Aspect ratio") == 1.0]
    if not runs:
        print(f"no tethered a/b = 1 tether2d runs under {' '.join(args.runs)}", file=sys.stderr)
        return 1
    plt = co.use_agg()
    for ca in sorted({r.value("Flow/Capillary number") for r in runs}):
        figure([r for r in runs if r.value("Flow/Capillary number") == ca], plt, args.out, ca)
    return 0


if __name__ == "__main__":
    sys.exit(main())
