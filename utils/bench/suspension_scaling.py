#!/usr/bin/python3
"""The cost of a suspension3d time step against the number of cells at a fixed hematocrit, as a
markdown table and a log-log figure.

  suspension_scaling.py --build BUILD [--cells 8,16,32,64] [--level 1] [--hematocrit 0.2]
                        [--lambda 5] [--steps 2] [--runs DIR] [--out DIR]

Each run is suspension3d on one rank with the demo deck's cells (input/suspension3d/demo.xml:
biconcave red cells with bending at viscosity ratio --lambda, mesh level --level, and platelets,
one per eight red cells, at viscosity ratio 1) in the periodic Poiseuille channel of height 6.
N red cells fill the hematocrit: the box is square, L_x = L_z = sqrt(N V / (hematocrit H)) with V
the red cell's own (faceted) volume, which the app reports when asked for a hematocrit it
cannot meet. The platelets' shear modulus is 2 (so RK4 steps of 0.0025 are stable at level 1 and
2), the gaps kept at placement those of the margination deck (0.05 between cells, 0.1 from the
walls: random sequential addition jams at hematocrit 0.2 with the demo's 0.2), the steps are RK4
of 0.0025 (fixed: every N takes the same steps), GMRES at 1e-6, the Ewald sums at their default
tolerance, outputs at the start and the end only.

Per run: the seconds of one step (the wall time of the run less its outputs, over the steps),
the double-layer applications (GMRES iterations) per right-hand side, the single-layer and
double-layer seconds, the peak resident memory (summary.json), and the growth exponent between
successive N (log of the step-time ratio over log of the N ratio). A cost growing like n ln n in
the nodes n gives slightly more than 1 (the table states it); the step count is fixed, so that is
the bound the table is read against. It names this generator and the code version (git describe --always --dirty).
Writes suspension_scaling_table.md and suspension_scaling.png (python3-matplotlib) to --out;
exits 1 if a run fails. Debian's /usr/bin/python3.
"""
import argparse
import json
import math
import os
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
import accuracy_cost_report as report_helpers  # noqa: E402 (git_sha, cpu_model)

DECK = os.path.join(ROOT, "input", "suspension3d", "demo.xml")
HEIGHT = 6.0
STEP = 0.0025
CELL_VOLUME = re.compile(r"one cell of volume ([0-9.eE+-]+)")
TIMER = re.compile(r"Capsula: Double-layer application\s+\S+\s+\((\d+)\)")


def deck_settings(args, box):
    settings = {"Domain/Periodic length x": box, "Domain/Periodic length z": box,
                "Suspension/Hematocrit": args.hematocrit,
                "Suspension/Cell types/red_cell/Mesh level": args.level,
                "Suspension/Cell types/red_cell/Viscosity ratio": args.viscosity_ratio,
                "Suspension/Cell types/platelet/Mesh level": args.level,
                "Suspension/Cell types/platelet/Shear modulus": 2,
                "Time integration/Method": "RK4", "Time integration/Initial step": STEP,
                "Time integration/End time": STEP * args.steps, "Output/Interval": STEP * args.steps,
                "Output/Snapshots": "false", "Solver/Tolerance": 1e-6,
                "Cells/Minimum gap": 0.05, "Wall/Minimum gap": 0.1}
    return [item for key, value in settings.items() for item in ("--set", f"{key}={value}")]


def red_cell_volume(app, args, runs):
    """The red cell's faceted volume, from the refusal of a hematocrit one cell overshoots."""
    probe = subprocess.run([app, DECK] + deck_settings(args, 3.0) +
                           ["--set", "Suspension/Hematocrit=0.001", "--output", os.path.join(runs, "probe")],
                           capture_output=True, text=True)
    match = CELL_VOLUME.search(probe.stdout + probe.stderr)
    if probe.returncode == 0 or not match:
        sys.exit(f"suspension_scaling: the probe did not report the red cell's volume:\n{probe.stdout}{probe.stderr}")
    return float(match.group(1))


def measure(app, args, runs, cells, volume):
    """One run of `cells` red cells: a dict of its figures."""
    box = math.sqrt(cells * volume / (args.hematocrit * HEIGHT))
    out = os.path.join(runs, f"cells{cells}")
    shutil.rmtree(out, ignore_errors=True)
    command = [app, DECK] + deck_settings(args, f"{box:.10g}") + [
        "--set", f"Suspension/Cell types/platelet/Count={max(1, cells // 8)}", "--output", out]
    proc = subprocess.run(command, capture_output=True, text=True)
    if proc.returncode != 0:
        sys.exit(f"suspension_scaling: {' '.join(command)} failed ({proc.returncode}):\n{proc.stdout[-3000:]}"
                 f"{proc.stderr[-3000:]}")
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    timings = summary["timings"]
    steps = summary["steps"]["accepted"]
    rhs = summary["steps"]["rhs evaluations"]
    placed = re.search(r"Placed (\d+) red_cell, (\d+) platelet", proc.stdout)
    applications = TIMER.search(proc.stdout)
    return {"cells": cells, "red": int(placed.group(1)), "platelets": int(placed.group(2)), "box": box,
            "step": (timings["wall seconds (this process)"] - timings.get("Outputs", 0.0)) / steps,
            "applications per rhs": int(applications.group(1)) / rhs if applications else 0.0,
            "single": timings.get("Single layer", 0.0), "double": timings.get("Double-layer application", 0.0),
            "memory": max(summary["peak memory (MiB) per rank"])}


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", required=True, help="the build folder (holds apps/suspension3d)")
    parser.add_argument("--cells", default="8,16,32,64", help="the numbers of red cells, comma-separated")
    parser.add_argument("--level", type=int, default=1, help="the cells' mesh level")
    parser.add_argument("--hematocrit", type=float, default=0.2)
    parser.add_argument("--lambda", dest="viscosity_ratio", type=float, default=5.0,
                        help="the red cells' viscosity ratio")
    parser.add_argument("--steps", type=int, default=2, help="RK4 steps per run")
    parser.add_argument("--runs", default="suspension-scaling-runs", help="where the runs write")
    parser.add_argument("--out", default=os.path.join(ROOT, "docs", "figures"), help="where to write")
    args = parser.parse_args()
    app = os.path.join(args.build, "apps", "suspension3d", "suspension3d")
    os.makedirs(args.runs, exist_ok=True)
    volume = red_cell_volume(app, args, args.runs)
    rows = [measure(app, args, args.runs, int(n), volume) for n in args.cells.split(",")]

    command = "/usr/bin/python3 utils/bench/suspension_scaling.py --build build"
    extra = [f"--{name}={value}" for name, value, default in
             [("cells", args.cells, "8,16,32,64"), ("level", args.level, 1), ("hematocrit", args.hematocrit, 0.2),
              ("lambda", args.viscosity_ratio, 5.0), ("steps", args.steps, 2)] if value != default]
    version = report_helpers.git_sha()
    lines = [f"Generated by `{' '.join([command] + extra)}` with the code at git {version}; one rank on "
             f"{report_helpers.cpu_model()} (one run per row: read the growth, not the seconds, across machines).",
             "", f"Red cells at viscosity ratio {args.viscosity_ratio:g}, mesh level {args.level}, hematocrit "
             f"{args.hematocrit:g} (faceted red-cell volume {volume:.5f}), channel height {HEIGHT:g}, "
             f"RK4 steps of {STEP:g}.", "",
             "| red cells | platelets | box L | s per step | growth | DL applications per rhs | single layer s | "
             "double layer s | peak MiB |", "|---|---|---|---|---|---|---|---|---|"]
    for k, row in enumerate(rows):
        growth = ""
        if k > 0:
            before = rows[k - 1]
            growth = f"{math.log(row['step'] / before['step']) / math.log(row['red'] / before['red']):.2f}"
        lines.append(f"| {row['red']} | {row['platelets']} | {row['box']:.3f} | {row['step']:.2f} | {growth} | "
                     f"{row['applications per rhs']:.1f} | {row['single']:.1f} | {row['double']:.1f} | "
                     f"{row['memory']:.0f} |")
    counts = [r["red"] for r in rows]
    per_cell = 10 * 4 ** (args.level + 1) + 2  # nodes of a level-L mesh of 6-node triangles (162 at 1)
    nlogn = [f"{1 + math.log(math.log(per_cell * n) / math.log(per_cell * m)) / math.log(n / m):.2f}"
             for m, n in zip(counts, counts[1:])]
    lines += ["", "growth: ln(step_N / step_M) / ln(N / M) between successive rows; the steps are fixed, so a "
              f"cost growing like n ln n in the nodes n = {per_cell} N gives " + ", ".join(nlogn) +
              " (a cost linear in N gives 1)."]
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, "suspension_scaling_table.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    figure, axes = plt.subplots(figsize=(5.5, 4.0))
    axes.loglog(counts, [r["step"] for r in rows], "o-", label="seconds per step")
    first = rows[0]
    axes.loglog(counts, [first["step"] * n * math.log(per_cell * n) / (counts[0] * math.log(per_cell * counts[0]))
                         for n in counts], "k--", linewidth=0.8, label="n ln n (n nodes) from the first point")
    axes.set_xlabel(f"red cells N (hematocrit {args.hematocrit:g})")
    axes.set_ylabel("wall seconds per RK4 step, one rank")
    axes.set_title(f"suspension3d, level {args.level}, red cells at lambda {args.viscosity_ratio:g} ({version})",
                   fontsize=9)
    axes.legend(fontsize=8)
    figure.tight_layout()
    figure.savefig(os.path.join(args.out, "suspension_scaling.png"), dpi=120)


if __name__ == "__main__":
    main()
