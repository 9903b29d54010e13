#!/usr/bin/python3
"""The key numbers of a set of tether2d runs as one Markdown table (docs/tether2d-results.md keeps the
full study's): per run a/b, lambda, Ca, points, the end of the preparation, the largest tether
force (every step, and after the tethering transient) with its time, A_max/A0, L_cell,max, the
largest |area drift| against the thesis's bounds (0.5% at lambda = 1, 1.5% at lambda = 10,
Section 3.12.2), whether the equilibrium criterion was met, the end time, steps and wall time.
Rows sorted by lambda, a/b, Ca; a summary line per lambda gives the largest drift.

Usage: tether2d_table.py RUNDIR_OR_PARENT... [--out FILE.md | --out FOLDER]
"""
import argparse
import os
import sys

import capsula_outputs as co

# Thesis Section 3.12.2: area changes "less than 0.5% in most cases"; "less than 1.5%" at 10.
DRIFT_BOUND = {1.0: 0.005, 10.0: 0.015}


def row(run):
    s = run.summary
    m = s["max"]
    t = s["timings"]
    return dict(ab=run.value("Cell/Aspect ratio"), lam=run.value("Flow/Viscosity ratio"),
                ca=run.value("Flow/Capillary number"), n=run.value("Cell/Number of points"),
                prep=s.get("preparation time", float("nan")), fmax=m["tether_force"], tfmax=m["time_of_max_tether_force"],
                fafter=m.get("tether_force_after_transient", float("nan")),
                amax=m["contour_length_ratio"], lmax=m["cell_length"], drift=m["abs_area_drift"],
                steady=s.get("status") == "steady", end=s["final"]["time"], steps=s["steps"]["accepted"],
                wall=t["wall seconds (this process)"])


def table(rows):
    out = ["| a/b | lambda | Ca | N | tethered at tau | F_max (tau) | F_max after transient | A_max/A0 | "
           "L_cell max | max area drift | equilibrium | end tau | steps | wall s |",
           "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in sorted(rows, key=lambda r: (r["lam"], -r["ab"], -r["ca"])):
        out.append(f"| {r['ab']:g} | {r['lam']:g} | {r['ca']:g} | {r['n']} | {r['prep']:.3f} | {r['fmax']:.4f} "
                   f"({r['tfmax']:.2f}) | {r['fafter']:.4f} | {r['amax']:.4f} | {r['lmax']:.4f} | "
                   f"{100 * r['drift']:.3f}% | {'yes' if r['steady'] else 'no'} | {r['end']:g} | {r['steps']} | "
                   f"{r['wall']:.0f} |")
    out.append("")
    for lam in sorted({r["lam"] for r in rows}):
        group = [r for r in rows if r["lam"] == lam]
        worst = max(group, key=lambda r: r["drift"])
        bound = DRIFT_BOUND.get(lam)
        verdict = (f" (thesis bound {100 * bound:.1f}%: {'met' if worst['drift'] < bound else 'NOT met'})"
                   if bound else "")
        out.append(f"- lambda = {lam:g}: {len(group)} runs, largest area drift {100 * worst['drift']:.3f}% "
                   f"(a/b = {worst['ab']:g}, Ca = {worst['ca']:g}){verdict}.")
    return "\n".join(out) + "\n"


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("runs", nargs="+")
    parser.add_argument("--out", help="write the table to this file (or to tether2d_table.md in this folder) "
                                      "instead of printing it")
    args = parser.parse_args(argv)
    runs = [r for r in co.find_runs(args.runs, "tether2d") if r.value("Tether/Enabled")]
    if not runs:
        print(f"no tethered tether2d runs under {' '.join(args.runs)}", file=sys.stderr)
        return 1
    text = table([row(r) for r in runs])
    if args.out:
        path = os.path.join(args.out, "tether2d_table.md") if os.path.isdir(args.out) else args.out
        co.write_markdown_table(path, text.rstrip("\n").split("\n"), runs)
        print(f"wrote {path} ({len(runs)} runs)")
    else:
        sys.stdout.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
