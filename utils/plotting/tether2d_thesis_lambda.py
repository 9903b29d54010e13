#!/usr/bin/python3
"""The thesis's lambda trend against this code's (docs/tether2d-results.md, "The thesis's lambda
read as 1/lambda"): tether force, A/A0 and L_cell over k (t - t_tether) for tethered a/b = 1
runs of one Ca, on the thesis's time axis k (t - t_tether) / Lambda with Lambda the thesis's
viscosity ratio. A run with lambda < 1 is drawn as the thesis's Lambda = 1/lambda: its eq
A.35 with the inward normal of eqs A.26-A.27 is this code's 1/lambda run Lambda times slower,
so its time is this run's k t. A run with lambda >= 1 is this code's own, Lambda = lambda, at
its tau = k t / lambda. At most the first 40 units are drawn (the maxima come within 12).

Usage: tether2d_thesis_lambda.py --out FIGDIR [--table FILE] RUNDIR_OR_PARENT...
Writes FIGDIR/tether2d_thesis_lambda_ca<Ca>.png, one per Ca among the runs, and with --table
the maxima of the runs with lambda <= 1 (the thesis's lambda = 1/lambda), times in k t.
"""
import argparse
import os
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


def table(runs, path):
    """The maxima of the runs with lambda <= 1, read as the thesis's lambda = 1/lambda."""
    lines = []
    for ca in sorted({r.value("Flow/Capillary number") for r in runs}):
        chosen = sorted((r for r in runs if r.value("Flow/Capillary number") == ca
                         and r.value("Flow/Viscosity ratio") <= 1.0),
                        key=lambda r: -r.value("Flow/Viscosity ratio"))
        if not chosen:
            continue
        lines += [f"a/b = 1, Ca = {ca:g}, {chosen[0].value('Cell/Number of points')} points; times in k t "
                  "(the thesis's tau for its lambda)",
                  "| thesis lambda | lambda run here | tethered at k t | F_max | k t of F_max after tethering "
                  "| A_max/A0 | L_cell max | max area drift |",
                  "|---|---|---|---|---|---|---|---|"]
        for run in chosen:
            lam = run.value("Flow/Viscosity ratio")
            s = run.summary
            tether = s["preparation time"] * lam          # tau = k t / lambda in this code
            peak = s["max"]["time_of_max_tether_force"] * lam
            lines.append(f"| {1.0 / lam:g} | {lam:.12g} | {tether:.3f} | {s['max']['tether_force']:.4f} "
                         f"| {peak - tether:.2f} | {s['max']['contour_length_ratio']:.4f} "
                         f"| {s['max']['cell_length']:.4f} | {100 * s['max']['abs_area_drift']:.3f}% |")
    with open(path + ".tmp", "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")
    os.replace(path + ".tmp", path)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", required=True, help="folder for the PNG files")
    parser.add_argument("--table", metavar="FILE", help="also write the maxima of the lambda <= 1 runs here")
    parser.add_argument("runs", nargs="+", help="tether2d run directories or folders holding them")
    args = parser.parse_args(argv)
    runs = [r for r in co.find_runs(args.runs, "tether2d")
            if r.value("Tether/Enabled") and r.value("Cell/Aspect ratio") == 1.0]
    if not runs:
        print(f"no tethered a/b = 1 tether2d runs under {' '.join(args.runs)}", file=sys.stderr)
        return 1
    if args.table:
        table(runs, args.table)
    plt = co.use_agg()
    for ca in sorted({r.value("Flow/Capillary number") for r in runs}):
        figure([r for r in runs if r.value("Flow/Capillary number") == ca], plt, args.out, ca)
    return 0


if __name__ == "__main__":
    sys.exit(main())
