#!/usr/bin/python3
"""Runs a list of twocell3d (or cell3d) decks and gathers the per-cell results into one table.

    utils/studies/twocell3d_sweep.py [--build build] [--ranks 2] [--out out/twocell3d-sweep]
                                     [--set "List/Key=value"]... [--skip-done] [--gather-only]
                                     [--isolated RUN_DIR] [--table FILE] DECK...

Each deck runs into OUT/<folder>/<name> (its folder and file name, e.g.
out/twocell3d-sweep/in-line/h1.25-dx1-fixed), with the --set overrides passed on; a run that
stops with an error is reported and the sweep goes on (its outputs up to the failure are
gathered). --skip-done leaves runs whose summary.json says finished, steady or too close;
--gather-only runs nothing. --isolated RUN_DIR takes the smallest and largest wall stress of
an isolated cell's run (its summary.json, final or steady) and passes them as
'Output/Wall shear stress/Isolated range', so each run reports the wall areas below and
above the isolated cell's range (thesis Figs 6.6, 6.12).

The table (default OUT/table.csv) has one row per cell per deck, from the run's
summary.json: the steady values where the run reached a steady shape, else the final ones
("values" column), and for two or more cells the metrics of the pair (0, 1) on every row of
the deck. Columns:
  deck, status, time, values, cell, h0, dx0, dy0, dz0, gap0   (the start: centre of cell 0
      height, centre differences cell 0 - cell 1, and the gap between the undeformed spheres
      |x0 - x1| - r0 - r1, which is the thesis's Delta x0/a or Delta z0/a)
  x_c, y_c, z_c, u_slip, u_migr, u_slip_spline, u_migr_spline, D12, inclination_deg,
  reduced_volume, mean_shear_stress, max_shear_stress, volume_change   (the cell)
  distance, dx, dy, dz, du, dv, dw, dslip, gap   (the pair (0, 1); empty for one cell)
  wall_stress_min, wall_stress_max, wall_area_below_isolated, wall_area_above_isolated
      (the last wall stress map, where the run made one)
Standard library only (Debian's python3).
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys
import xml.etree.ElementTree as ElementTree

CELL_KEYS = [
    ("x_c", lambda v: v["centroid"][0]),
    ("y_c", lambda v: v["centroid"][1]),
    ("z_c", lambda v: v["centroid"][2]),
    ("u_slip", lambda v: v["u_slip"]),
    ("u_migr", lambda v: v["u_migr"]),
    ("u_slip_spline", lambda v: v["u_slip (spline of outputs)"]),
    ("u_migr_spline", lambda v: v["u_migr (spline of outputs)"]),
    ("D12", lambda v: v["D12"]),
    ("inclination_deg", lambda v: v["inclination (degrees)"]),
    ("reduced_volume", lambda v: v["reduced volume"]),
    ("mean_shear_stress", lambda v: v["mean shear stress"]),
    ("max_shear_stress", lambda v: v["max shear stress"]),
    ("volume_change", lambda v: v["volume change"]),
]
PAIR_KEYS = [
    ("distance", lambda v: v["distance"]),
    ("dx", lambda v: v["separation"][0]),
    ("dy", lambda v: v["separation"][1]),
    ("dz", lambda v: v["separation"][2]),
    ("du", lambda v: v["relative velocity"][0]),
    ("dv", lambda v: v["relative velocity"][1]),
    ("dw", lambda v: v["relative velocity"][2]),
    ("dslip", lambda v: v["relative u_slip"]),
    ("gap", lambda v: v["gap"]),
]
WALL_KEYS = [
    ("wall_stress_min", "minimum"),
    ("wall_stress_max", "maximum"),
    ("wall_area_below_isolated", "area below the isolated cell's minimum"),
    ("wall_area_above_isolated", "area above the isolated cell's maximum"),
]
DONE = ("finished", "steady", "too close")


def run_directory(out, deck):
    folder = os.path.basename(os.path.dirname(os.path.abspath(deck)))
    return os.path.join(out, folder, os.path.splitext(os.path.basename(deck))[0])


def read_summary(directory):
    path = os.path.join(directory, "summary.json")
    if not os.path.exists(path):
        return None
    with open(path) as f:
        return json.load(f)


def parameter(cell, name, default):
    for p in cell.findall("Parameter"):
        if p.get("name") == name:
            return p.get("value")
    return default


def start_geometry(deck):
    """h0, dx0, dy0, dz0, gap0 from the deck's cells (spheres: Radius, Center)."""
    root = ElementTree.parse(deck).getroot()
    cells = None
    for sub in root.findall("ParameterList"):
        if sub.get("name") == "Cells":
            cells = sub
    centres, radii = [], []
    for k in range(2):
        for cell in (cells.findall("ParameterList") if cells is not None else []):
            if cell.get("name") == "Cell %d" % k:
                text = parameter(cell, "Center", "{0, 0, 0}").strip("{} ")
                centres.append([float(x) for x in text.split(",")])
                radii.append(float(parameter(cell, "Radius", "1")))
    if not centres:
        return ["", "", "", "", ""]
    if len(centres) < 2:
        return [centres[0][1], "", "", "", ""]
    d = [centres[0][i] - centres[1][i] for i in range(3)]
    gap = math.sqrt(sum(x * x for x in d)) - radii[0] - radii[1]
    return [centres[0][1]] + d + [gap]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("decks", nargs="+")
    parser.add_argument("--build", default="build")
    parser.add_argument("--app", default="twocell3d", help="twocell3d (default) or cell3d")
    parser.add_argument("--ranks", type=int, default=2)
    parser.add_argument("--out", default="out/twocell3d-sweep")
    parser.add_argument("--set", action="append", default=[], dest="overrides")
    parser.add_argument("--skip-done", action="store_true")
    parser.add_argument("--gather-only", action="store_true")
    parser.add_argument("--table")
    parser.add_argument("--isolated", help="run directory of the isolated cell (its wall stress range)")
    args = parser.parse_args()

    if args.isolated:
        reference = read_summary(args.isolated)
        if not reference or "wall shear stress" not in reference:
            sys.exit("--isolated %s: no summary.json with a wall shear stress map" % args.isolated)
        wall = reference["wall shear stress"]
        args.overrides.append("Output/Wall shear stress/Isolated range={%r, %r}" % (wall["minimum"], wall["maximum"]))

    app = os.path.join(args.build, "apps", args.app, args.app)
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    if not args.gather_only:
        for deck in args.decks:
            directory = run_directory(args.out, deck)
            summary = read_summary(directory)
            if args.skip_done and summary and summary.get("status") in DONE:
                print("== %s: %s, skipped" % (deck, summary["status"]), file=sys.stderr)
                continue
            os.makedirs(directory, exist_ok=True)
            command = [app, deck, "--output", directory]
            for override in args.overrides:
                command += ["--set", override]
            if args.ranks > 1:
                command = ["mpiexec", "-n", str(args.ranks), "--oversubscribe"] + command
            print("== %s" % deck, file=sys.stderr)
            with open(directory + ".log", "w") as log:
                code = subprocess.call(command, stdout=log, stderr=subprocess.STDOUT, env=env)
            if code != 0:
                print("   stopped with exit code %d (see %s.log)" % (code, directory), file=sys.stderr)

    table = args.table or os.path.join(args.out, "table.csv")
    os.makedirs(os.path.dirname(os.path.abspath(table)), exist_ok=True)
    columns = (["deck", "status", "time", "values", "cell", "h0", "dx0", "dy0", "dz0", "gap0"]
               + [k for k, _ in CELL_KEYS] + [k for k, _ in PAIR_KEYS] + [k for k, _ in WALL_KEYS])
    rows = 0
    with open(table + ".tmp", "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(columns)
        for deck in args.decks:
            summary = read_summary(run_directory(args.out, deck))
            if summary is None:
                print("   no summary.json for %s" % deck, file=sys.stderr)
                continue
            start = start_geometry(deck)
            wall = summary.get("wall shear stress", {})
            wall_values = [wall.get(key, "") for _, key in WALL_KEYS]
            pair_values = [""] * len(PAIR_KEYS)
            pairs = summary.get("pairs", [])
            if pairs:
                which = "steady" if "steady" in pairs[0] else "final"
                pair_values = [f(pairs[0][which]) for _, f in PAIR_KEYS]
            for index, cell in enumerate(summary.get("cells", [])):
                which = "steady" if "steady" in cell else "final"
                writer.writerow([deck, summary["status"], summary["time"], which, index] + start
                                + [f(cell[which]) for _, f in CELL_KEYS] + pair_values + wall_values)
                rows += 1
    os.replace(table + ".tmp", table)
    print("wrote %s (%d rows)" % (table, rows), file=sys.stderr)


if __name__ == "__main__":
    main()
