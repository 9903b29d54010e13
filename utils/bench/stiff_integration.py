#!/usr/bin/python3
"""The stiff time integrators (ROS34PW2, Auto) against the explicit RKF45 with its stability
limit: accuracy and cost side by side, measured with the cell3d app in one session.

  stiff_integration.py --build BUILD [--runs DIR] [--report FILE] [--quick] [--case NAME]... [--level N]...

Cases (docs/stiff-integration-results.md explains them):
  goldman  nearly rigid neo-Hookean capsule held at h/a = 1.5431 (the Goldman deck), level 2,
           Ca = 0.01 and 0.005, to t = 0.3: the instantaneous slip of every method and
           tolerance against RKF45's, and the operator applications each needs.
  stiff    the same capsule at Ca = 0.002, h/a = 1.543081, levels 2 and 3, to t = 3: ROS34PW2 and
           Auto at 1e-4 and ROS34PW2 at 1e-5 against a ROS34PW2 reference (1e-7 at level 2, 1e-6 at level 3);
           RKF45 to t = 3 at level 2 and, at level 3, to t = 0.02 with its cost to t = 3
           projected from its measured steps.
  soft     the demo deck (Skalak C = 2.5, Ca = 0.3, level 2, to t = 2): RKF45, ROS34PW2 and Auto
           at the deck's tolerance 1e-5, against RKF45 at 1e-8.
  c10      Skalak C = 10, Ca = 0.9, unbounded, level 2, to t = 5, tolerances 1e-4 and 1e-3, ROS34PW2
           also with 40 kept products of the Jacobian (Solver/Stiff/Recycled products).
  gmres    GMRES iterations per stage solve of ROS34PW2 (1e-4, to t = 0.1) on the Goldman
           capsule over Ca = 0.1 ... 5e-4 and mesh levels 1-3, with and without the
           local-mobility preconditioner.

Cost: operator applications (right-hand sides, GMRES iterations, linearisations: each one
evaluation of the layer potentials or a geometry set-up), CPU seconds of the run (user +
system: less inflated than wall time by other jobs on the machine) and wall seconds. Speed is
stated as ratios of runs made one after the other in the same session.

Finished runs in RUNS are reused (delete RUNS, or a run's folder, for fresh numbers). From
scratch the full set takes about 3 hours on 2 cores; --quick (level 1, short end times, a
pipeline check, about 2 minutes) writes its report to RUNS/stiff-integration-results.md.
"""
import argparse
import json
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
import accuracy_cost as ac  # noqa: E402 (run_app: one app run with its wall and CPU time)
import accuracy_cost_report as report_helpers  # noqa: E402 (git_sha)

QUIET = {"Output/Snapshots": "false", "Output/Wall shear stress/Enabled": "false", "Output/Progress steps": "100000"}


def run(build, runs, name, deck, sets, timeout):
    """Runs cell3d once (or reuses a finished run); returns its record."""
    out = os.path.join(runs, name)
    record_file = out + ".json"
    if os.path.exists(record_file):
        with open(record_file) as f:
            return json.load(f)
    app = os.path.join(build, "apps/cell3d/cell3d")
    code, wall, rss, before, after, cpu = ac.run_app(app, deck, {}, dict(QUIET, **sets), 1, out, timeout)
    record = {"name": name, "code": code, "wall": wall, "cpu": cpu, "load": [before, after]}
    try:
        with open(os.path.join(out, "summary.json")) as f:
            summary = json.load(f)
        steps = summary["steps"]
        final = summary["cells"][0]["final"]
        record.update(
            time=summary["time"], status=summary["status"], steps=steps["accepted"], rejected=steps["rejected"],
            rhs=steps["rhs evaluations"], iterations=steps.get("linear iterations", 0),
            linearisations=steps.get("linearisations", 0), stiff_steps=steps.get("stiff steps", 0),
            switches=steps.get("method switches", 0), u_slip_inst=final["u_slip"],
            u_slip_spline=final["u_slip (spline of outputs)"], D12=final["D12"], volume_change=final["volume change"])
        record["applications"] = record["rhs"] + record["iterations"] + record["linearisations"]
        record["rows"] = metrics_rows(os.path.join(out, "metrics.csv"))
    except (OSError, KeyError, ValueError) as e:
        record["status"] = f"failed: {e}"
    with open(record_file, "w") as f:
        json.dump(record, f, indent=1)
    return record


def run_versions(runs):
    """The code versions of the runs in RUNS (summary.json): finished runs are reused, so they
    may be older than the report."""
    summaries = []
    for name in sorted(os.listdir(runs)):
        try:
            with open(os.path.join(runs, name, "summary.json")) as f:
                summaries.append(json.load(f))
        except (OSError, ValueError):
            continue
    return report_helpers.generated_pages.run_versions(summaries)


def metrics_rows(path):
    """time, step, u_slip_spline, D12, u_slip of every output row."""
    import csv
    rows = []
    with open(path) as f:
        for row in csv.DictReader(f):
            rows.append({k: float(row[k]) for k in ("time", "step", "u_slip_spline", "D12", "u_slip")})
    return rows


def levels(args, default):
    """The mesh levels of a case: --level where given, else the case's own."""
    return tuple(args.level) if args.level else default


def lowest_tension(path):
    """The smallest min_tension of a run's metrics.csv (None if it is not there)."""
    import csv
    try:
        with open(path) as f:
            return min(float(row["min_tension"]) for row in csv.DictReader(f))
    except (OSError, KeyError, ValueError):
        return None


def relative(value, reference):
    return abs(value - reference) / abs(reference) if reference else float("nan")


def accuracy_columns(record, ref):
    """u_slip (instantaneous), D12, their deviations from the reference (%), then u_slip_spline and its deviation."""
    def deviation(key):
        return 100 * relative(record[key], ref[key]) if ok(ref) else float("nan")
    return [f"{record['u_slip_inst']:.6f}", f"{record['D12']:.6f}", deviation("u_slip_inst"), deviation("D12"),
            f"{record['u_slip_spline']:.6f}", deviation("u_slip_spline")]


def ok(record):
    return record.get("status") in ("finished", "steady")


def fmt(value, digits=4):
    if isinstance(value, float) and not math.isfinite(value):
        return "-"
    if isinstance(value, float):
        return f"{value:.{digits}g}"
    return str(value)


def table(header, rows):
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(fmt(c) for c in row) + " |" for row in rows]
    return "\n".join(lines)


def goldman(args, report):
    deck = os.path.join(ROOT, "input/cell3d/validation/goldman-rigid-h1.5431.xml")
    base = {"Cells/Cell 0/Mesh level": "1" if args.quick else "2"}
    if args.quick:
        base["Time integration/End time"] = "0.05"
    report.append("## Nearly rigid capsule held at h/a = 1.5431 (Goldman deck), t = %s\n"
                  % base.get("Time integration/End time", "0.3"))
    for ca in ("0.01", "0.005"):
        sets = dict(base, **{"Flow/Capillary number": ca})
        runs = {"RKF45 1e-6": run(args.build, args.runs, f"goldman-ca{ca}-rkf45", deck, sets, args.timeout)}
        for method in ("ROS34PW2", "Auto"):
            for tol in ("1e-4", "1e-6"):
                runs[f"{method} {tol}"] = run(
                    args.build, args.runs, f"goldman-ca{ca}-{method.lower()}-{tol}", deck,
                    dict(sets, **{"Time integration/Method": method, "Time integration/Tolerance": tol}), args.timeout)
        explicit = runs["RKF45 1e-6"]
        rows = []
        for label, r in runs.items():
            if not ok(r):
                rows.append([label, r.get("status", "?")] + [float("nan")] * 9)
                continue
            method = label.split()[0]
            tight = runs.get(f"{method} 1e-6", r)
            rows.append([label, r["steps"], r["rhs"], r["iterations"], r["applications"],
                         r["applications"] / explicit["applications"], f"{r['u_slip_inst']:.7f}",
                         100 * relative(r["u_slip_inst"], explicit["u_slip_inst"]),
                         100 * relative(r["u_slip_inst"], tight["u_slip_inst"]) if ok(tight) else float("nan"),
                         r["cpu"], explicit["cpu"] / r["cpu"]])
        report.append(f"### Ca = {ca}\n")
        report.append(table(["method, tolerance", "steps", "rhs", "GMRES it", "applications",
                             "applications / RKF45's", "u_slip (instantaneous)", "vs RKF45 (%)",
                             "vs same method at 1e-6 (%)", "CPU s", "speed-up (CPU)"], rows) + "\n")
        if all(ok(r) for r in runs.values()):
            worst = max(relative(runs[f"{m} {t}"]["u_slip_inst"], explicit["u_slip_inst"])
                        for m in ("ROS34PW2", "Auto") for t in ("1e-4", "1e-6"))
            change = max(relative(runs[f"{m} 1e-4"]["u_slip_inst"], runs[f"{m} 1e-6"]["u_slip_inst"])
                         for m in ("ROS34PW2", "Auto"))
            ros = runs["ROS34PW2 1e-4"]
            report.append(
                f"Every stiff run gives RKF45's instantaneous slip to {100 * worst:.3f}% or better; from tolerance "
                f"1e-4 to 1e-6 it changes by at most {100 * change:.3f}%. ROS34PW2 at 1e-4 needs "
                f"{100 * ros['applications'] / explicit['applications']:.1f}% of RKF45's operator applications "
                f"({ros['steps']} steps against {explicit['steps']}) and {explicit['cpu'] / ros['cpu']:.1f} times less "
                f"CPU time.\n")


def projected(short, end):
    """RKF45's cost to `end` from a run cut short: its rate of applications and CPU seconds per
    unit time over the second half of the run (the stability limit holds the step nearly constant)."""
    rows = short["rows"]
    half = [r for r in rows if r["time"] >= rows[-1]["time"] / 2]
    steps_per_time = (half[-1]["step"] - half[0]["step"]) / (half[-1]["time"] - half[0]["time"])
    applications_per_step = short["applications"] / short["steps"]
    cpu_per_application = short["cpu"] / short["applications"]
    applications = short["applications"] + steps_per_time * (end - short["time"]) * applications_per_step
    return applications, applications * cpu_per_application, steps_per_time * end


def stiff(args, report):
    deck = os.path.join(ROOT, "input/cell3d/validation/goldman-rigid-h1.5431.xml")
    end = 0.1 if args.quick else 3.0
    short_end = 0.02 if not args.quick else 0.01
    report.append(f"## Stiff neo-Hookean capsule: Ca = 0.002, h/a = 1.543081, fixed height, t = {end:g}\n")
    for level in levels(args, (1,) if args.quick else (2, 3)):
        sets = {"Flow/Capillary number": "0.002", "Cells/Cell 0/Center": "{0.0, 1.543081, 0.0}",
                "Cells/Cell 0/Mesh level": str(level), "Time integration/End time": f"{end:g}",
                "Output/Interval": f"{end / 6:g}"}
        name = f"stiff-level{level}"
        reference_tolerance = "1e-6" if level >= 3 else "1e-7"
        ref = run(args.build, args.runs, f"{name}-reference", deck,
                  dict(sets, **{"Time integration/Method": "ROS34PW2",
                                "Time integration/Tolerance": reference_tolerance}), args.timeout)
        # ROS34PW2 and Auto at 1e-4; ROS34PW2 at 1e-5 shows how the error moves with the tolerance.
        stiff_runs = {f"{m} {tol}": run(args.build, args.runs, f"{name}-{m.lower()}-{tol}", deck,
                                        dict(sets, **{"Time integration/Method": m, "Time integration/Tolerance": tol}),
                                        args.timeout)
                      for m, tol in (("ROS34PW2", "1e-4"), ("Auto", "1e-4"), ("ROS34PW2", "1e-5"))}
        full_explicit = level <= 2
        explicit_end = end if full_explicit else short_end
        # The instantaneous u_slip (the centroid velocity of the state) is the primary column;
        # u_slip_spline, the slope of the spline through the outputs, depends on the output
        # interval: the full explicit run keeps the others' interval, so its u_slip_spline
        # compares with theirs.
        explicit = run(args.build, args.runs, f"{name}-rkf45", deck,
                       sets if full_explicit else dict(sets, **{"Time integration/End time": f"{explicit_end:g}",
                                                                "Output/Interval": f"{explicit_end / 4:g}"}),
                       args.timeout)
        rows = []
        if ok(explicit):
            if full_explicit:
                apps, cpu, steps = explicit["applications"], explicit["cpu"], explicit["steps"]
                note = "measured"
            else:
                apps, cpu, steps = projected(explicit, end)
                note = f"projected from t = {explicit_end:g}"
        else:
            apps = cpu = steps = float("nan")
            note = explicit.get("status", "?")
        for label, r in [(f"ROS34PW2 {reference_tolerance} (reference)", ref)] + list(stiff_runs.items()):
            if not ok(r):
                rows.append([label, r.get("status", "?")] + [float("nan")] * 9)
                continue
            rows.append([label, r["steps"], r["applications"]] + accuracy_columns(r, ref) + [r["cpu"], cpu / r["cpu"]])
        if full_explicit and ok(explicit):
            rows.append(["RKF45 1e-6 + stability limit", explicit["steps"], explicit["applications"]]
                        + accuracy_columns(explicit, ref) + [explicit["cpu"], 1.0])
        else:
            rows.append([f"RKF45 1e-6 + stability limit ({note})", fmt(steps, 3), fmt(apps, 3)] + ["-"] * 6
                        + [cpu, 1.0])
        report.append(f"### Mesh level {level}\n")
        report.append(table(["method, tolerance", "steps", "applications", "u_slip (instantaneous)", "D12",
                             "u_slip vs reference (%)", "D12 vs reference (%)", "u_slip_spline",
                             "u_slip_spline vs reference (%)", "CPU s", "speed-up (CPU) over RKF45"], rows) + "\n")
        ros = stiff_runs["ROS34PW2 1e-4"]
        if ok(ref) and ok(ros) and math.isfinite(apps):
            report.append(
                f"ROS34PW2 at 1e-4 gives the instantaneous u_slip and D12 at t = {end:g} within "
                f"{100 * relative(ros['u_slip_inst'], ref['u_slip_inst']):.3f}% and {100 * relative(ros['D12'], ref['D12']):.3f}% "
                f"of the reference with {ros['steps']} steps; RKF45 under its stability limit needs "
                f"{apps / ros['applications']:.0f} times its operator applications and "
                f"{cpu / ros['cpu']:.0f} times its CPU time ({note}).\n")
        if ok(ref):
            tail = [r for r in ref["rows"] if r["time"] >= end / 2]
            report.append("u_slip (instantaneous) of the reference at t = "
                          + ", ".join(f"{r['time']:g}: {r['u_slip']:.6f}" for r in tail)
                          + "; u_slip_spline at t = " + ", ".join(f"{r['time']:g}: {r['u_slip_spline']:.6f}" for r in tail)
                          + "; D12 at t = " + ", ".join(f"{r['time']:g}: {r['D12']:.6f}" for r in tail) + ".\n")
            tension = lowest_tension(os.path.join(args.runs, f"{name}-reference", "metrics.csv"))
            if tension is not None:
                report.append(f"Lowest membrane tension of the reference over the run: {tension:.4f}"
                              + (" (part of the membrane is in compression)" if tension < 0 else "") + ".\n")
        if ok(explicit) and not full_explicit:
            short_ref = run(args.build, args.runs, f"{name}-reference-short", deck,
                            dict(sets, **{"Time integration/Method": "ROS34PW2",
                                          "Time integration/Tolerance": reference_tolerance,
                                          "Time integration/End time": f"{explicit_end:g}",
                                          "Output/Interval": f"{explicit_end / 4:g}"}), args.timeout)
            if ok(short_ref):
                report.append(
                    f"RKF45 to t = {explicit_end:g}: {explicit['steps']} steps, {explicit['applications']} applications, "
                    f"{explicit['cpu']:.0f} CPU s; its D12 there differs from the reference's by "
                    f"{100 * relative(explicit['D12'], short_ref['D12']):.2g}%.\n")


def soft(args, report):
    deck = os.path.join(ROOT, "input/cell3d/demo.xml")
    sets = {"Cells/Cell 0/Mesh level": "1" if args.quick else "2"}
    if args.quick:
        sets["Time integration/End time"] = "0.2"
    report.append("## Soft capsule: the demo deck (Skalak C = 2.5, Ca = 0.3, h/a = 1.6), t = %s\n"
                  % sets.get("Time integration/End time", "2"))
    ref = run(args.build, args.runs, "soft-reference", deck, dict(sets, **{"Time integration/Tolerance": "1e-8"}),
              args.timeout)
    runs = {"RKF45 1e-5": run(args.build, args.runs, "soft-rkf45", deck, sets, args.timeout)}
    for method in ("ROS34PW2", "Auto"):
        runs[f"{method} 1e-5"] = run(args.build, args.runs, f"soft-{method.lower()}", deck,
                                     dict(sets, **{"Time integration/Method": method}), args.timeout)
    explicit = runs["RKF45 1e-5"]
    rows = []
    for label, r in runs.items():
        if not ok(r):
            rows.append([label, r.get("status", "?")] + [float("nan")] * 7)
            continue
        rows.append([label, r["steps"], r["applications"], r["switches"], f"{r['D12']:.6f}",
                     100 * relative(r["D12"], ref["D12"]) if ok(ref) else float("nan"), r["cpu"], r["cpu"] / explicit["cpu"]])
    report.append(table(["method, tolerance", "steps", "applications", "method switches", "D12", "D12 vs RKF45 1e-8 (%)",
                         "CPU s", "CPU / RKF45's"], rows) + "\n")
    if all(ok(r) for r in runs.values()):
        automatic, ros = runs["Auto 1e-5"], runs["ROS34PW2 1e-5"]
        report.append(
            f"Auto {'stays with RKF45' if automatic['switches'] == 0 else 'switches ' + str(automatic['switches']) + ' times'}"
            f" ({automatic['stiff_steps']} of its steps taken by ROS34PW2) at {automatic['cpu'] / explicit['cpu']:.2f} "
            f"times RKF45's CPU time; ROS34PW2 throughout costs {ros['cpu'] / explicit['cpu']:.2f} times RKF45's.\n")


def c10(args, report):
    deck = os.path.join(ROOT, "input/cell3d/unbounded/Ca0.9-C0.5-prestress0.xml")
    end = "0.3" if args.quick else "5"
    sets = {"Cells/Cell 0/Area dilation C": "10", "Cells/Cell 0/Mesh level": "1" if args.quick else "2",
            "Time integration/End time": end, "Output/Interval": "0.25"}
    report.append(f"## Skalak C = 10, Ca = 0.9, unbounded shear, t = {end}\n")
    # RKF45's steps are set by its stability limit, so its tolerance changes nothing; each
    # stiff run is compared with RKF45 at the same tolerance.
    runs, explicit_at = {}, {}
    for tol, suffix in (("1e-4", ""), ("1e-3", "-1e-3")):
        tol_sets = dict(sets, **{"Time integration/Tolerance": tol})
        explicit_at[tol] = runs[f"RKF45 {tol}"] = run(args.build, args.runs, f"c10-rkf45{suffix}", deck, tol_sets,
                                                     args.timeout)
        for method in ("ROS34PW2", "Auto") if tol == "1e-4" else ("ROS34PW2",):
            runs[f"{method} {tol}"] = run(args.build, args.runs, f"c10-{method.lower()}{suffix}", deck,
                                          dict(tol_sets, **{"Time integration/Method": method}), args.timeout)
        # Stage solves started from the step's kept products of J~ (docs/stiff-integration.md).
        runs[f"ROS34PW2 {tol} kept products 40"] = run(
            args.build, args.runs, f"c10-ros34pw2-kept40{suffix}", deck,
            dict(tol_sets, **{"Time integration/Method": "ROS34PW2", "Solver/Stiff/Recycled products": "40"}),
            args.timeout)
    rows = []
    for label, r in runs.items():
        explicit = explicit_at[label.split()[1]]
        if not ok(r) or not ok(explicit):
            rows.append([label, r.get("status", "?")] + [float("nan")] * 7)
            continue
        rows.append([label, r["steps"], r["applications"], explicit["applications"] / r["applications"],
                     f"{r['D12']:.6f}", 100 * relative(r["D12"], explicit_at["1e-4"]["D12"]), r["cpu"],
                     explicit["cpu"] / r["cpu"]])
    report.append(table(["method, tolerance", "steps", "applications",
                         "fewer applications than RKF45 at the same tolerance (x)", "D12", "D12 vs RKF45 1e-4 (%)",
                         "CPU s", "speed-up (CPU)"], rows) + "\n")
    if all(ok(r) for r in runs.values()):
        explicit = explicit_at["1e-4"]
        ros, loose = runs["ROS34PW2 1e-4"], runs["ROS34PW2 1e-3"]
        report.append(
            f"At 1e-4 ROS34PW2 needs {100 * ros['applications'] / explicit['applications']:.0f}% of RKF45's operator "
            f"applications ({ros['steps']} steps against {explicit['steps']}) and "
            f"{100 * ros['cpu'] / explicit['cpu']:.0f}% of its CPU time; D12 at t = {end} agrees to "
            f"{100 * relative(ros['D12'], explicit['D12']):.3f}%. At 1e-3 (RKF45 unchanged: "
            f"{explicit_at['1e-3']['steps']} steps) it needs "
            f"{100 * loose['applications'] / explicit_at['1e-3']['applications']:.0f}% of the applications and "
            f"D12 agrees to {100 * relative(loose['D12'], explicit['D12']):.3f}%.\n")


def gmres(args, report):
    deck = os.path.join(ROOT, "input/cell3d/validation/goldman-rigid-h1.5431.xml")
    numbers = ("0.1", "0.01") if args.quick else ("0.1", "0.01", "0.002", "0.0005")
    end = "0.02" if args.quick else "0.1"
    report.append(f"## GMRES iterations per stage solve (ROS34PW2, tolerance 1e-4, Goldman capsule, to t = {end})\n")
    rows = []
    for level in levels(args, (1,) if args.quick else (1, 2, 3)):
        for ca in numbers:
            row = [level, ca]
            for preconditioner in ("Local mobility", "None"):
                tag = "lm" if preconditioner == "Local mobility" else "none"
                r = run(args.build, args.runs, f"gmres-level{level}-ca{ca}-{tag}", deck,
                        {"Cells/Cell 0/Mesh level": str(level), "Flow/Capillary number": ca,
                         "Time integration/Method": "ROS34PW2", "Time integration/Tolerance": "1e-4",
                         "Time integration/End time": end, "Output/Interval": end,
                         "Solver/Stiff/Preconditioner": preconditioner, "Solver/Stiff/Maximum iterations": "2000",
                         "Solver/Stiff/Restart": "200"}, args.timeout)
                if ok(r):
                    solves = 4 * (r["steps"] + r["rejected"])
                    row += [r["steps"], r["iterations"] / solves]
                else:
                    row += [r.get("status", "?"), float("nan")]
            rows.append(row)
    report.append(table(["level", "Ca", "steps", "iterations per solve", "steps (no preconditioner)",
                         "iterations per solve (no preconditioner)"], rows) + "\n")


CASES = {"goldman": goldman, "stiff": stiff, "soft": soft, "c10": c10, "gmres": gmres}


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--build", default=os.path.join(ROOT, "build"))
    p.add_argument("--runs", default=os.path.join(ROOT, "out/stiff-integration"))
    p.add_argument("--report")
    p.add_argument("--quick", action="store_true")
    p.add_argument("--case", action="append", choices=sorted(CASES), help="run only these cases (repeatable)")
    p.add_argument("--level", action="append", type=int,
                   help="mesh levels of the stiff and gmres cases (repeatable; default: theirs)")
    p.add_argument("--timeout", type=float, default=6 * 3600.0, help="seconds one run may take")
    args = p.parse_args()
    args.runs = os.path.abspath(args.runs)
    os.makedirs(args.runs, exist_ok=True)
    report_path = args.report or (os.path.join(args.runs, "stiff-integration-results.md") if args.quick
                                  else os.path.join(ROOT, "docs/stiff-integration-results.md"))
    command = "/usr/bin/python3 utils/bench/stiff_integration.py --build build" + (" --quick" if args.quick else "")
    report = ["# Stiff time integration: measured accuracy and cost (cell3d)\n"]
    failed = False
    for name in args.case or list(CASES):
        CASES[name](args, report)
    # After the runs: the versions of the runs the report reads (reused ones included).
    report.insert(1, f"{report_helpers.generated_pages.header_line(command, ROOT)} The runs ran "
                     f"{run_versions(args.runs)}; one rank. Method and keys: docs/stiff-integration.md.\n")
    loads = []
    for name in os.listdir(args.runs):
        if name.endswith(".json"):
            with open(os.path.join(args.runs, name)) as f:
                loads += json.load(f).get("load", [])
    if loads:
        report.insert(2, f"Load average (1 minute) at the start and end of the runs: {min(loads):.1f} to "
                         f"{max(loads):.1f} on {os.cpu_count()} cores. CPU seconds are the run's own (user + system), "
                         f"which other jobs inflate less than wall time; ratios compare runs of one session.\n")
    text = "\n".join(report)
    with open(report_path, "w") as f:
        f.write(text)
    print(text)
    print(f"stiff_integration.py: report written to {report_path}")
    for name in os.listdir(args.runs):
        if name.endswith(".json"):
            with open(os.path.join(args.runs, name)) as f:
                if not ok(json.load(f)):
                    print(f"stiff_integration.py: run {name[:-5]} did not finish", file=sys.stderr)
                    failed = True
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
