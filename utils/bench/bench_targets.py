#!/usr/bin/python3
"""The speed and memory targets, measured with the apps themselves (not a test).

  bench_targets.py --build BUILD [--out DIR] [--json FILE] [--steps 30] [--quick]

Runs, each for a fixed number of RKF45 steps of 1e-3 (Initial = Maximum step, no outputs but
the first and last): one Skalak cell at mesh level 3 (2562 nodes) at h/a = 1.6 above the wall,
lambda = 1, on 1 and 2 ranks; the same with lambda = 5 on 2 ranks; two cells at level 3
(input/twocell3d/side-by-side/h1.25-dz1-free.xml) on 2 ranks; the 2D tethered cell with 256
points on 1 rank. The step cost is 6 right-hand sides (RKF45's stages) at the measured time
per right-hand side (the Teuchos timers of the right-hand side: membrane loads, boundary-
integral velocity, fixed-height constraint; setup and outputs excluded); wall / accepted steps
is printed too. Peak memory: the largest resident set of any process of the run (wait4's
rusage of the process tree); on 1 rank that is the whole run. Prints measured / target and
measured / thesis (Table 3.4), the load average before and after each run, and the share of
each Teuchos timer. --quick: level 1 and 64 points (a pipeline check; targets do not apply).
"""
import argparse
import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
import accuracy_cost as ac  # noqa: E402 (the sweep's runner, next to this file)

STAGES = 6  # RKF45 right-hand sides per step (eq 3.47-3.50)


def measure(app, deck, sets, ranks, out, name, steps, timeout):
    sets = dict(sets)
    sets.update({"Time integration/Initial step": "1e-3", "Time integration/Maximum step": "1e-3",
                 "Time integration/End time": f"{steps}e-3"})
    code, wall, rss, lb, la, cpu = ac.run_app(app, deck, {}, sets, ranks, os.path.join(out, name), timeout)
    rec = dict(name=name, ranks=ranks, code=code, wall_s=wall, peak_rss_mb=rss, load_before=lb, load_after=la,
               cpu_s=cpu)
    try:
        rec.update(ac.read_costs(os.path.join(out, name)))
    except (OSError, KeyError, ValueError) as e:
        rec["status"] = f"failed: {e}"
        return rec
    rec["s_per_step"] = STAGES * rec["s_per_rhs"]
    rec["wall_per_accepted_step"] = rec["app_wall"] / rec["steps"] if rec["steps"] else float("nan")
    # CPU seconds of all processes per step (setup included): what the step costs in core time,
    # which other jobs on the machine do not inflate the way they inflate the wall time.
    rec["cpu_per_step"] = cpu / rec["steps"] if rec["steps"] else float("nan")
    return rec


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--build", required=True)
    p.add_argument("--out", default=os.path.join(ROOT, "out/bench-targets"))
    p.add_argument("--json")
    # 30 steps: the first steps carry one-time work (caches, the first stability-limit
    # estimate); at 8 steps it added 20-25% to the 2D step and 8% to the lambda = 5 one.
    p.add_argument("--steps", type=int, default=30)
    p.add_argument("--quick", action="store_true")
    p.add_argument("--timeout", type=float, default=1200)
    args = p.parse_args()
    cell3d = os.path.join(args.build, "apps/cell3d/cell3d")
    two = os.path.join(args.build, "apps/twocell3d/twocell3d")
    tether = os.path.join(args.build, "apps/tether2d/tether2d")
    level = "1" if args.quick else "3"
    quiet = {"Output/Snapshots": "false", "Output/Checkpoint": "false", "Output/Interval": "0",
             "Output/Wall shear stress/Enabled": "false", "Output/Progress steps": "1000"}
    one = dict(quiet, **{"Cells/Cell 0/Mesh level": level})
    pair = dict(one, **{"Cells/Cell 1/Mesh level": level})
    demo = os.path.join(ROOT, "input/cell3d/demo.xml")
    cases = [
        ("one_cell_np1", cell3d, demo, one, 1),
        ("one_cell_np2", cell3d, demo, one, 2),
        ("one_cell_lambda5_np2", cell3d, demo, dict(one, **{"Flow/Viscosity ratio": "5"}), 2),
        ("two_cells_np2", two, os.path.join(ROOT, "input/twocell3d/side-by-side/h1.25-dz1-free.xml"), pair, 2),
        ("tether2d_256_np1", tether, os.path.join(ROOT, "input/tether2d/demo.xml"),
         {"Cell/Number of points": "64" if args.quick else "256", "Output/Snapshot every": "0",
          "Output/Checkpoint every": "0", "Tether/Enabled": "false", "Output/Interval": f"{args.steps}e-3"}, 1),
    ]
    os.makedirs(args.out, exist_ok=True)
    res = {}
    for name, app, deck, sets, ranks in cases:
        if not os.path.exists(app):
            print(f"bench_targets: {name}: {app} not built, skipped")
            continue
        rec = measure(app, deck, sets, ranks, args.out, name, args.steps, args.timeout)
        res[name] = rec
        print(f"  {name}: {rec.get('s_per_step', float('nan')):.4f} s per step ({STAGES} rhs), "
              f"{rec.get('wall_per_accepted_step', float('nan')):.4f} s wall per accepted step, "
              f"{rec.get('cpu_per_step', float('nan')):.4f} CPU s per step (all ranks), "
              f"{rec.get('steps', 0)} steps, peak RSS {rec['peak_rss_mb']:.0f} MB, "
              f"load {rec['load_before']:.2f}->{rec['load_after']:.2f} [{rec.get('status')}]", flush=True)

    def val(name, key="s_per_step"):
        return res.get(name, {}).get(key, float("nan"))

    # (what, measured, target, thesis Table 3.4 or None, unit); a speed-up is better when larger.
    rows = [
        ("one cell, level 3, wall, lambda = 1, 2 ranks: s per step", val("one_cell_np2"), 0.4, 12.9, "s"),
        ("one cell, 1 rank: s per step", val("one_cell_np1"), None, 12.9, "s"),
        ("two cells, level 3, 2 ranks: s per step", val("two_cells_np2"), 1.6, 26.3, "s"),
        ("2D tether, 256 points, 1 rank: s per step", val("tether2d_256_np1"), 0.010, 6.9, "s"),
        ("lambda = 5 / lambda = 1 step (2 ranks)", val("one_cell_lambda5_np2") / val("one_cell_np2"), 4.0, None, "x"),
        ("1 -> 2 rank speed-up (one cell)", val("one_cell_np1") / val("one_cell_np2"), 1.8, None, "x"),
        ("peak memory, one cell, 1 rank", val("one_cell_np1", "peak_rss_mb"), 100.0, 130.0, "MB"),
        ("peak memory, two cells, largest of 2 ranks", val("two_cells_np2", "peak_rss_mb"), 200.0, 550.0, "MB"),
        ("peak memory, 2D tether, 256 points", val("tether2d_256_np1", "peak_rss_mb"), None, 34.0, "MB"),
    ]
    print(f"\nbench_targets ({'quick: level 1, 64 points; targets do not apply' if args.quick else 'level 3, 256 points'}):")
    print(f"  {'what':58s} {'measured':>10s} {'target':>8s} {'meas/target':>11s} {'meas/thesis':>11s}")
    table = []
    for what, m, target, thesis, unit in rows:
        mt = m / target if target else float("nan")
        mth = m / thesis if thesis else float("nan")
        print(f"  {what:58s} {m:10.4g} {target if target else float('nan'):8.3g} {mt:11.3g} {mth:11.3g}  {unit}")
        table.append(dict(what=what, measured=m, target=target, thesis=thesis, unit=unit))
    print("  (speed-up: meas/target >= 1 meets it; every other row: <= 1 meets it)")
    # Where the time goes (Teuchos timers of the run, shares of the right-hand side).
    for name, rec in res.items():
        t = rec.get("timers", {})
        if "Single layer" in t:
            total = rec.get("app_wall", float("nan"))
            parts = {k: v for k, v in t.items() if isinstance(v, (int, float)) and not k.startswith("wall")}
            print(f"  profile {name}: " + ", ".join(f"{k} {100 * v / total:.0f}%" for k, v in parts.items() if v > 0)
                  + f" of {total:.1f} s")
    if args.json:
        with open(args.json + ".tmp", "w") as f:
            json.dump(dict(runs=res, table=table, quick=args.quick, steps=args.steps), f, indent=1)
        os.replace(args.json + ".tmp", args.json)
    return 0 if all(r.get("status") in ("finished", "steady") for r in res.values()) else 1


if __name__ == "__main__":
    sys.exit(main())
