#!/usr/bin/python3
"""The red-cell study (docs/cell3d-red-cell-results.md): the regime of each cell3d run of the
biconcave cell with bending (tank-treading, swinging or tumbling, by the criterion of
cell3d_viscosity_ratio.py: tumbling when the inclination of the profile's long axis in the
shear plane passes through +-90 deg, swinging when it oscillates by at least --swing-threshold
degrees peak to peak, tank-treading otherwise), its mean inclination, D12 and membrane rotation,
against Ca and lambda.

Every cell3d run found under the folders given is read (metrics.csv, deck.xml, summary.json).
Only the outputs after --transient count.

Writes into --out, NAME being --name (default cell3d_red_cell)
  NAME_table.md, NAME_table.csv   one row per run
  NAME_regimes.png     regime against Ca and lambda, per setting (unbounded, height)
  NAME_histories.png   inclination (unwrapped) and D12 against time, one line per run

Usage: cell3d_red_cell.py --out FIGDIR [--name NAME] [--transient T] RUNDIR_OR_PARENT...
"""
import argparse
import os
import sys

import numpy as np

import cell3d_viscosity_ratio as vr

COLUMNS = ["setting", "ca", "lam", "regime", "mean_theta", "swing", "ratio", "D12", "omega_z", "u_lift",
           "steps", "stiff_steps", "seconds", "volume_drift", "level", "status", "time"]


def write_tables(rows, folder, name, co, runs):
    os.makedirs(folder, exist_ok=True)
    cell = (lambda row, c: vr.text(row[c] if c != "setting" else vr.setting_of(row)))
    with open(os.path.join(folder, f"{name}_table.csv"), "w", encoding="utf-8") as f:
        f.write(",".join(COLUMNS) + "\n")
        for row in rows:
            f.write(",".join(cell(row, c) for c in COLUMNS) + "\n")
    path = os.path.join(folder, f"{name}_table.md")
    co.write_markdown_table(path, ["| " + " | ".join(COLUMNS) + " |", "|" + "---|" * len(COLUMNS)]
                            + ["| " + " | ".join(cell(row, c) for c in COLUMNS) + " |" for row in rows], runs)
    print(f"wrote {path}")


def regimes_figure(rows, folder, name, plt, co):
    settings = vr.settings_in(rows)
    fig, axes = plt.subplots(1, len(settings), figsize=(3.4 * len(settings), 3.0), squeeze=False, sharey=True)
    cas = sorted({r["ca"] for r in rows})
    for j, (setting, height) in enumerate(settings):
        ax = axes[0][j]
        for regime, (marker, colour) in vr.MARKERS.items():
            chosen = [r for r in rows if r["height"] == height and r["regime"] == regime]
            if chosen:
                ax.scatter([r["lam"] for r in chosen], [r["ca"] for r in chosen], marker=marker, s=60, color=colour,
                           label=regime)
        co.log_axis_at(ax, [r["lam"] for r in rows])
        ax.set_yscale("log")
        ax.set_yticks(cas, [f"{c:g}" for c in cas])
        ax.minorticks_off()
        ax.set_title(f"red cell, {setting}")
        ax.set_xlabel("viscosity ratio lambda")
        if j == 0:
            ax.set_ylabel("Ca")
    axes[0][0].legend(fontsize=7)
    co.save_figure(fig, folder, f"{name}_regimes.png")


def histories_figure(rows, folder, name, plt, co):
    settings = vr.settings_in(rows)
    fig, axes = plt.subplots(2, len(settings), figsize=(3.6 * len(settings), 5.2), squeeze=False, sharex=True)
    cmap = plt.get_cmap("viridis")
    cas = sorted({r["ca"] for r in rows})
    styles = {lam: style for lam, style in zip(sorted({r["lam"] for r in rows}), ["-", "--", ":", "-."])}
    for j, (setting, height) in enumerate(settings):
        for r in rows:
            if r["height"] != height:
                continue
            t, theta = r["history"]
            colour = cmap(cas.index(r["ca"]) / max(1, len(cas) - 1))
            label = f"Ca {r['ca']:g}, lambda {r['lam']:g}"
            axes[0][j].plot(t, vr.unwrapped_inclination(theta), color=colour, ls=styles[r["lam"]], label=label)
            axes[1][j].plot(t, r["D12_history"], color=colour, ls=styles[r["lam"]], label=label)
        axes[0][j].set_title(f"red cell, {setting}")
        axes[1][j].set_xlabel("time (1/k)")
    axes[0][0].set_ylabel("inclination, unwrapped (deg)")
    axes[1][0].set_ylabel("D12")
    axes[0][0].legend(fontsize=6)
    co.save_figure(fig, folder, f"{name}_histories.png")


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", required=True, help="folder for the tables and PNG files")
    parser.add_argument("--name", default="cell3d_red_cell",
                        help="start of the names of the files written (default cell3d_red_cell)")
    parser.add_argument("--transient", type=float, default=5.0,
                        help="judge the regime on the outputs after this time (default 5)")
    parser.add_argument("--swing-threshold", type=float, default=1.0,
                        help="peak-to-peak inclination (degrees) from which a run swings (default 1)")
    parser.add_argument("runs", nargs="+", help="cell3d run directories or folders holding them")
    args = parser.parse_args(argv)
    if not args.name or "/" in args.name or args.name in (".", ".."):
        parser.error(f"--name: '{args.name}' is not a file-name prefix (no '/', not empty)")
    import capsula_outputs as co
    rows = []
    runs = co.find_runs(args.runs, "cell3d")
    for run in runs:
        row = vr.describe(run, args.transient, args.swing_threshold)
        row["D12_history"] = np.asarray(run.table()["D12"], dtype=float)
        rows.append(row)
    if not rows:
        print("cell3d_red_cell: no cell3d runs found", file=sys.stderr)
        return 1
    rows.sort(key=lambda r: (-r["height"], r["lam"], r["ca"]))
    write_tables(rows, args.out, args.name, co, runs)
    plt = co.use_agg()
    regimes_figure(rows, args.out, args.name, plt, co)
    histories_figure(rows, args.out, args.name, plt, co)
    counts = {regime: sum(r["regime"] == regime for r in rows) for regime in vr.MARKERS}
    print("cell3d_red_cell: regimes: " + ", ".join(f"{k} {v}" for k, v in counts.items()))
    for r in rows:
        if r["regime"] == vr.STOPPED:
            print(f"cell3d_red_cell: {r['directory']} stopped at t = {r['time']:g} ({r['status']})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
