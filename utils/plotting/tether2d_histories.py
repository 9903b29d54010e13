#!/usr/bin/python3
"""Time histories and their maxima for the 2D tethered cell (thesis Figs. 4.7-4.21) from
tether2d run directories (metrics.csv of the tethered stage, summary.json maxima).

For each quantity, as in the thesis:
  quantity             over Ca        over lambda    over a/b      maximum against Ca
  A/A0                 fig4.7         fig4.8         fig4.9        fig4.10
  L_cell/L             fig4.11        fig4.12        fig4.13       fig4.14
  F/E (tether force)   fig4.15        fig4.16        fig4.17       fig4.18
  lambda U_cell/k a    fig4.19        fig4.20        fig4.21       -
"over Ca": a/b = 1, one panel per lambda (the smallest and the largest present); "over
lambda": a/b = 1, one panel per Ca (smallest, largest); "over a/b": lambda = 1, one panel per
Ca; "maximum": one panel per a/b, one line per lambda (the maxima are over every accepted
step, not only the output rows). A figure whose varied parameter has a single value among
the runs is not drawn (the script says so and exits non-zero).

Usage: tether2d_histories.py --out FIGDIR RUNDIR_OR_PARENT...
"""
import argparse
import sys

import numpy as np

import capsula_outputs as co

AB, LAMBDA, CA = 0, 1, 2
NAMES = {AB: "a/b", LAMBDA: "lambda", CA: "Ca"}

QUANTITIES = [
    # column, axis label, file stem, thesis figure numbers (over Ca, lambda, a/b, max), summary max key
    ("contour_length_ratio", "A / A0", "contour_length", (7, 8, 9, 10), "contour_length_ratio"),
    ("cell_length", "L_cell / L", "cell_length", (11, 12, 13, 14), "cell_length"),
    # The force's maximum after the tethering transient (Tether/Force transient): the spike
    # of the first ~0.01 tau depends on the resolution (docs/tether2d-results.md).
    ("tether_force", "F / E", "tether_force", (15, 16, 17, 18), "tether_force_after_transient"),
    ("leading_edge_velocity", "lambda U_cell / k a", "cell_velocity", (19, 20, 21, None), None),
]


def parameters(run):
    return (run.value("Cell/Aspect ratio"), run.value("Flow/Viscosity ratio"), run.value("Flow/Capillary number"))


def values_of(runs, index):
    return sorted({parameters(r)[index] for r in runs})


def ends(values):
    """The smallest and the largest value (one if they are the same)."""
    return values[:1] if len(values) < 2 else [values[0], values[-1]]


def history_figure(runs, plt, out, column, label, figure_number, stem, fixed, panel_index, line_index):
    """One figure: one panel per value of `panel_index`, one line per value of `line_index`,
    among the runs whose parameters match `fixed` ({index: value})."""
    selected = [r for r in runs if all(parameters(r)[i] == v for i, v in fixed.items())]
    line_values = values_of(selected, line_index)
    varied = NAMES[line_index].replace("/", "")
    name = f"tether2d_fig4.{figure_number}_{stem}_over_{varied}.png"
    if len(line_values) < 2:
        print(f"{name}: needs runs at two or more {NAMES[line_index]} with "
              + ", ".join(f"{NAMES[i]} = {co.label_number(v)}" for i, v in fixed.items()) + "; skipped",
              file=sys.stderr)
        return None
    panels = ends(values_of(selected, panel_index))
    fig, axes = plt.subplots(1, len(panels), figsize=(4.3 * len(panels), 3.2), squeeze=False)
    colours = plt.cm.viridis(np.linspace(0.0, 0.9, len(line_values)))
    for ax, panel_value, letter in zip(axes[0], panels, "ab"):
        for line_value, colour in zip(line_values, colours):
            for run in selected:
                p = parameters(run)
                if p[panel_index] == panel_value and p[line_index] == line_value:
                    table = run.table()
                    ax.plot(table["time"], table[column], color=colour,
                            label=f"{NAMES[line_index]} = {co.label_number(line_value)}")
        ax.set_xlabel("k (t - t0) / lambda")
        ax.set_ylabel(label)
        title = ", ".join([f"{NAMES[i]} = {co.label_number(v)}" for i, v in fixed.items()]
                          + [f"{NAMES[panel_index]} = {co.label_number(panel_value)}"])
        ax.set_title(f"{letter}) {title}")
        ax.legend()
    return co.save_figure(fig, out, name)


def maximum_figure(runs, plt, out, max_key, label, figure_number, stem):
    name = f"tether2d_fig4.{figure_number}_max_{stem}_vs_Ca.png"
    ratios = values_of(runs, AB)
    if len(values_of(runs, CA)) < 2:
        print(f"{name}: needs runs at two or more Ca; skipped", file=sys.stderr)
        return None
    fig, axes = plt.subplots(1, len(ratios), figsize=(4.3 * len(ratios), 3.2), squeeze=False)
    lambdas = values_of(runs, LAMBDA)
    markers = "osD^v"
    for ax, ratio, letter in zip(axes[0], ratios, "abcd"):
        for lam, marker in zip(lambdas, markers):
            group = sorted((r for r in runs if parameters(r)[AB] == ratio and parameters(r)[LAMBDA] == lam),
                           key=lambda r: parameters(r)[CA])
            if group:
                # Runs made before max.tether_force_after_transient existed have the plain maximum.
                ax.plot([parameters(r)[CA] for r in group],
                        [r.summary["max"].get(max_key, r.summary["max"].get(max_key.replace("_after_transient", "")))
                         for r in group],
                        marker=marker, label=f"lambda = {co.label_number(lam)}")
        co.log_axis_at(ax, [parameters(r)[CA] for r in runs])
        ax.set_xlabel("Ca")
        ax.set_ylabel(f"max {label}")
        ax.set_title(f"{letter}) a/b = {co.label_number(ratio)}")
        ax.legend()
    return co.save_figure(fig, out, name)


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
    lambdas = values_of(runs, LAMBDA)
    cas = values_of(runs, CA)
    written = []
    for column, label, stem, (over_ca, over_lambda, over_ab, maximum), max_key in QUANTITIES:
        written.append(history_figure(runs, plt, args.out, column, label, over_ca, stem, {AB: 1.0}, LAMBDA, CA))
        written.append(history_figure(runs, plt, args.out, column, label, over_lambda, stem, {AB: 1.0}, CA, LAMBDA))
        written.append(history_figure(runs, plt, args.out, column, label, over_ab, stem, {LAMBDA: 1.0}, CA, AB))
        if maximum is not None:
            written.append(maximum_figure(runs, plt, args.out, max_key, label, maximum, stem))
    print(f"{sum(w is not None for w in written)} of {len(written)} figures from {len(runs)} runs "
          f"(lambda in {lambdas}, Ca in {cas})")
    return 0 if all(written) else 1


if __name__ == "__main__":
    sys.exit(main())
