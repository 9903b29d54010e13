#!/usr/bin/python3
"""A many-cell twocell3d run with a fast far-field summation against the same run with the
direct sum: the metrics of every cell at every output, the cost and the memory per rank.

  suspension_agreement.py --build BUILD [--deck DECK] [--ranks N] [--runs DIR] [--summation NAME]
                          [--tolerance T] [--set "List/Key=value"]... [--report FILE] [--quick]
  suspension_agreement.py --compare DIRECT_DIR FAST_DIR [--tolerance T] [--report FILE]

The deck (default input/twocell3d/suspension/ten-cells-wall.xml: ten level-3 cells near the
wall to t = 1) runs twice on N ranks (default 2): with 'Operator/Summation' = NAME (default
Treecode) and = Direct, every other key the same. Finished runs in RUNS are reused (delete a
run's folder for fresh numbers); --compare reads two finished output folders instead.
--quick (a pipeline check, under a minute) runs every cell at mesh level 1 to t = 0.02.

Compared at every output time both tables hold, for every cell: D12, D13, D23, inclination,
centroid (x_c, y_c, z_c), u_slip, u_migr, omega_z, volume and area change, mean and largest
shear stress on the membrane. A column passes when its largest |fast - direct| over cells and
times is at most T times max(1, its largest |value|) (default T = 1e-4; lengths in a,
velocities in k a, stresses in mu k, angles in degrees).
Cost: operator applications (right-hand sides, GMRES iterations, linearisations), wall and CPU
seconds of each run, their ratios, and the peak resident memory of each rank (summary.json).
Exits 1 when a column fails or a run did not finish. Debian's /usr/bin/python3, standard
library only.
"""
import argparse
import csv
import json
import os
import sys
import xml.etree.ElementTree as ElementTree

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
import accuracy_cost as ac  # noqa: E402 (run_app: one app run with its wall and CPU time)
import accuracy_cost_report as report_helpers  # noqa: E402 (git_sha)

DECK = "input/twocell3d/suspension/ten-cells-wall.xml"
COLUMNS = ["D12", "D13", "D23", "inclination_deg", "x_c", "y_c", "z_c", "u_slip", "u_migr", "omega_z",
           "volume_change", "area_change", "mean_shear_stress", "max_shear_stress"]
QUIET = {"Output/Snapshots": "false", "Output/Progress steps": "100000"}
TIMEOUT = 6 * 3600.0  # the direct ten-cell level-3 run takes about half an hour on 2 ranks


def run(build, runs, name, deck, ranks, sets):
    """Runs twocell3d once (or reuses a finished run); returns its output folder and times."""
    out = os.path.join(runs, name)
    record_file = out + ".json"
    if os.path.exists(record_file):
        with open(record_file) as f:
            return json.load(f)
    app = os.path.join(build, "apps/twocell3d/twocell3d")
    code, wall, _, before, after, cpu = ac.run_app(app, deck, {}, sets, ranks, out, TIMEOUT)
    record = {"folder": out, "code": code, "wall": wall, "cpu": cpu, "load": [before, after]}
    with open(record_file, "w") as f:
        json.dump(record, f, indent=1)
    return record


def quick_settings(deck):
    """Level 1 for every cell of DECK and a short end time."""
    cells = ElementTree.parse(deck).getroot().find("ParameterList[@name='Cells']")
    names = [c.get("name") for c in cells.findall("ParameterList") if c.get("name", "").startswith("Cell ")]
    settings = {f"Cells/{name}/Mesh level": "1" for name in names}
    settings.update({"Time integration/End time": "0.02", "Output/Interval": "0.01"})
    return settings


def finished(record, name):
    """An error message when the run did not write a finished summary, else None."""
    try:
        with open(os.path.join(record["folder"], "summary.json")) as f:
            status = json.load(f)["status"]
    except (OSError, KeyError, ValueError):
        status = "no summary.json"
    if record.get("code", 0) == 0 and status == "finished":
        return None
    return (f"run {name} did not finish (exit code {record.get('code')}, {status}; "
            f"log {record['folder']}.log)")


def summary_of(folder):
    """Status, cost and memory from a run's summary.json."""
    with open(os.path.join(folder, "summary.json")) as f:
        summary = json.load(f)
    steps = summary["steps"]
    applications = steps["rhs evaluations"] + steps.get("linear iterations", 0) + steps.get("linearisations", 0)
    timings = summary.get("timings", {})
    return {"status": summary["status"], "time": summary["time"], "ranks": summary["ranks"],
            "steps": steps["accepted"], "rejected": steps["rejected"], "applications": applications,
            "memory": summary.get("peak memory (MiB) per rank", []),
            "wall (process)": timings.get("wall seconds (this process)"),
            "summation": summary_deck_value(summary["deck"], "Summation")}


def summary_deck_value(deck, key):
    """The value of the first parameter KEY in the validated deck text."""
    marker = f'name="{key}" type="string" value="'
    at = deck.find(marker)
    return deck[at + len(marker):deck.find('"', at + len(marker))] if at >= 0 else "?"


def metrics(folder):
    """{time: {column: value}} of a metrics.csv."""
    with open(os.path.join(folder, "metrics.csv")) as f:
        return {float(row["time"]): {k: float(v) for k, v in row.items() if v != ""} for row in csv.DictReader(f)}


def compare(direct, fast, cells):
    """Per column: (largest |fast - direct|, its cell, its time, largest |value| of either run); cell and
    time are None when no cell has the column in both tables."""
    times = sorted(set(direct) & set(fast))
    result = {}
    for column in COLUMNS:
        worst, scale = (0.0, None, None), 0.0
        for t in times:
            for c in range(cells):
                key = f"{column}_{c}"
                if key not in direct[t] or key not in fast[t]:
                    continue
                difference = abs(fast[t][key] - direct[t][key])
                scale = max(scale, abs(direct[t][key]), abs(fast[t][key]))
                if difference >= worst[0]:
                    worst = (difference, c, t)
        result[column] = worst + (scale,)
    return times, result


def cell_count(table):
    first = next(iter(table.values()))
    return sum(1 for k in first if k.startswith("D12_"))


def report(direct_dir, fast_dir, tolerance, records):
    direct_summary, fast_summary = summary_of(direct_dir), summary_of(fast_dir)
    direct, fast = metrics(direct_dir), metrics(fast_dir)
    cells = cell_count(direct)
    times, result = compare(direct, fast, cells)
    lines = [f"# Fast summation against Direct over a whole run (git {report_helpers.git_sha()})", "",
             f"{cells} cells, {len(times)} common output times up to t = {times[-1]:g}; "
             f"direct: {direct_dir}; fast ({fast_summary['summation']}): {fast_dir}", "",
             "| run | status | t | steps (rejected) | operator applications | wall s | CPU s | peak MiB per rank |",
             "|---|---|---|---|---|---|---|---|"]
    for name, summary, folder in [("Direct", direct_summary, direct_dir), (fast_summary["summation"], fast_summary, fast_dir)]:
        record = records.get(folder, {})
        wall = record.get("wall", summary["wall (process)"])
        cpu = record.get("cpu")
        memory = ", ".join(f"{m:.0f}" for m in summary["memory"])
        lines.append(f"| {name} | {summary['status']} | {summary['time']:g} | {summary['steps']} ({summary['rejected']}) | "
                     f"{summary['applications']} | {wall:.0f} | {'' if cpu is None else f'{cpu:.0f}'} | {memory} |")
    wall_direct = records.get(direct_dir, {}).get("wall", direct_summary["wall (process)"])
    wall_fast = records.get(fast_dir, {}).get("wall", fast_summary["wall (process)"])
    lines += ["", f"Wall time ratio Direct / {fast_summary['summation']}: {wall_direct / wall_fast:.2f}; "
              f"applications ratio: {direct_summary['applications'] / fast_summary['applications']:.3f}", "",
              f"| metric | largest abs difference | cell | t | largest abs value | passes (<= {tolerance:g} max(1, value)) |",
              "|---|---|---|---|---|---|"]
    passed = direct_summary["status"] == "finished" and fast_summary["status"] == "finished"
    for column, (difference, cell, t, scale) in result.items():
        # A column neither table holds for any cell compares nothing, so it fails.
        ok = cell is not None and difference <= tolerance * max(1.0, scale)
        passed = passed and ok
        where = ("", "") if cell is None else (str(cell), f"{t:g}")
        lines.append(f"| {column} | {difference:.2e} | {where[0]} | {where[1]} | {scale:.4g} | {'yes' if ok else 'NO'} |")
    lines += ["", "agreement: " + ("PASS" if passed else "FAIL")]
    return "\n".join(lines) + "\n", passed


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build")
    parser.add_argument("--deck", default=DECK)
    parser.add_argument("--ranks", type=int, default=2)
    parser.add_argument("--runs", default="out/bench/suspension-agreement")
    parser.add_argument("--summation", default="Treecode")
    parser.add_argument("--tolerance", type=float, default=1e-4)
    parser.add_argument("--set", action="append", default=[], dest="assignments", metavar="List/Key=value")
    parser.add_argument("--compare", nargs=2, metavar=("DIRECT_DIR", "FAST_DIR"))
    parser.add_argument("--report")
    parser.add_argument("--quick", action="store_true")
    args = parser.parse_args(argv)
    records = {}
    if args.compare:
        direct_dir, fast_dir = args.compare
    else:
        if not args.build:
            parser.error("--build is needed unless --compare names two finished runs")
        deck = os.path.join(ROOT, args.deck) if not os.path.isabs(args.deck) else args.deck
        sets = dict(QUIET, **(quick_settings(deck) if args.quick else {}))
        for assignment in args.assignments:
            key, _, value = assignment.partition("=")
            sets[key] = value
        os.makedirs(args.runs, exist_ok=True)
        problems = []
        for name, summation in [("fast", args.summation), ("direct", "Direct")]:
            record = run(args.build, args.runs, name, deck, args.ranks, dict(sets, **{"Operator/Summation": summation}))
            records[record["folder"]] = record
            problem = finished(record, name)
            if problem:
                problems.append(problem)
        if problems:
            print("suspension_agreement: " + "; ".join(problems), file=sys.stderr)
            return 1
        direct_dir, fast_dir = os.path.join(args.runs, "direct"), os.path.join(args.runs, "fast")
    try:
        text, passed = report(direct_dir, fast_dir, args.tolerance, records)
    except (OSError, KeyError, ValueError, StopIteration) as e:
        print(f"suspension_agreement: cannot compare {direct_dir} and {fast_dir}: {e}", file=sys.stderr)
        return 1
    print(text, end="")
    if args.report:
        with open(args.report, "w") as f:
            f.write(text)
    return 0 if passed else 1


if __name__ == "__main__":
    sys.exit(main())
