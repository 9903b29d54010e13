"""Writes docs/accuracy-cost.md from the results of `accuracy_cost.py all` (and, when present,
the bench_targets.py JSON). Every number in the report is one the sweep measured and printed;
the figures are copied next to the report (docs/figures/accuracy-cost/)."""
import json
import math
import os
import platform
import shutil
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "utils", "docs"))
import generated_pages  # noqa: E402 (the header of a generated page: command and code version)

TITLES = {
    "cell3d_shear": "3D: a capsule in free shear (Lac et al. 2004 neo-Hookean, Ca = 0.6), D12 at the end time",
    "cell3d_wall": "3D: D12_max of a cell near the wall (h/a = 1.2, Ca = 0.9, Skalak C = 2.5; thesis Fig. 3.7)",
    "tether2d_fmax": "2D: maximum tether force F_max (a/b = 1, Ca = 0.25, lambda = 1; thesis Fig. 3.6, Table 3.2)",
    "tether2d_fmax_gap0.1": "2D: F_max as above, with the cell released and tethered 0.1 above the wall",
    "gmres_lambda5": "lambda = 5: GMRES tolerance against the error and the time (D12 at the end time)",
}


GRIDS = {"axes": "each varied alone from the first value of the others", "product": "every combination",
         "mixed": "every combination of the first two; each further knob at every value of the first, the "
                  "others at their first value",
         "blocks": "the union of the products listed below, every other knob at its first value"}

# The thesis's own convergence numbers (Section 3.12.1), for the comparisons below.
THESIS_TABLE_3_2 = {"5": 3.2525, "6": 3.2469, "8": 3.2474, "12": 3.2475}  # F_max at 256 points
THESIS_FIG_3_6 = dict(order=-1.45, spread=0.034, last_change=0.005)       # N_E 64-320, 256 -> 320
THESIS_FIG_3_7 = dict(order=-0.75, spread=0.016)                          # D12_max against N_E
ELEMENTS = {"0": 20, "1": 80, "2": 320, "3": 1280, "4": 5120}              # icosphere level -> N_E


def fmt(x, digits=4):
    if x is None or (isinstance(x, float) and not math.isfinite(x)):
        return "-"
    if isinstance(x, float):
        return f"{x:.{digits}g}"
    return str(x)


def git_sha():
    """The code version a report names: `git describe --always --dirty`."""
    return generated_pages.code_version(ROOT)


def cpu_model():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


def study_section(name, rows, meta, figdir, docdir):
    out = [f"## {TITLES.get(name, name)}", ""]
    fixed = "; ".join(f"`{k}={v}`" for k, v in meta["fixed"].items() if not k.startswith("Output/"))
    knobs = "; ".join(f"`{k}` in {{{', '.join(v)}}}" for k, v in meta["knobs"])
    out += [f"Deck `{meta['deck']}` ({meta['app']}, {', '.join(map(str, meta['ranks']))} rank(s)) with {fixed}.",
            f"Knobs ({meta['grid']}: {GRIDS[meta['grid']]}): {knobs}."]
    for block in meta.get("blocks") or []:
        out.append("- " + " x ".join(f"`{k.split('/')[-1]}` {{{', '.join(v)}}}" for k, v in block.items()))
    if meta.get("blocks"):
        out.append("")
    out += [f"QoI `{meta['qoi']}`; reference {fmt(meta['reference'], 7)} ({meta['reference_how']}).", ""]
    keys = [k for k, _ in meta["knobs"]]
    distortion = any(math.isfinite(r.get("distortion", float("nan"))) for r in rows)
    head = [k.split("/")[-1] for k in keys] + ["QoI", "rel. error", "knob's own change", "drift"] + \
        (["max distortion"] if distortion else []) + ["s / rhs", "s / step", "steps", "rhs", "wall s", "peak MB", "load"]
    out.append("| " + " | ".join(head) + " |")
    out.append("|" + "---|" * len(head))
    for r in rows:
        partial = r.get("partial", {})
        own = ", ".join(f"{k.split('/')[-1]}: {fmt(v, 2)}" for k, v in partial.items() if v > 0)
        cells = [r["combo"][k] for k in keys] + [
            fmt(r["qoi"], 6), fmt(r["rel_error"], 2), own or "-", fmt(r.get("drift"), 2)] + (
            [fmt(r.get("distortion"), 2)] if distortion else []) + [fmt(r.get("s_per_rhs"), 3),
            fmt(r["wall_s"] / r["steps"] if r.get("steps") else float("nan"), 3), str(r.get("steps", 0)),
            str(r.get("rhs", 0)), fmt(r["wall_s"], 3), fmt(r["peak_rss_mb"], 3), f"{r['load_before']:.1f}"]
        if not str(r.get("status", "")).startswith(("finished", "steady")):
            cells[len(keys)] = f"{cells[len(keys)]} ({r.get('status')})"
        out.append("| " + " | ".join(cells) + " |")
    orders = meta.get("orders", {})
    if orders:
        out += ["", "Fitted orders (least-squares slope of log error against log knob, runs with zero error left "
                "out: for the mesh the error against h, for the other knobs the change from the knob's tightest "
                "value against the knob's value, so a negative slope means the error falls as the knob grows): " +
                "; ".join(f"{k.split('/')[-1]}: {v:.2f}" for k, v in orders.items()) + "."]
    line = meta.get("refine_line") or []
    if len(line) >= 2 and meta.get("refine"):
        what = meta["refine"].split("/")[-1]
        steps = ", ".join(f"{fmt(b - a, 3)}" for (_, a), (_, b) in zip(line, line[1:]))
        out += ["", f"Along `{what}` (others at base), coarse to fine: QoI " +
                ", ".join(fmt(q, 7) for _, q in line) + f"; successive changes {steps}."]
    out += history_table(meta)
    out += compare_with_thesis(name, rows, meta)
    out += [f"Sum of the runs' wall times: {sum(r['wall_s'] for r in rows):.0f} s.", ""]
    for suffix in ("pareto", "orders"):
        src = os.path.join(meta["runs"], name, f"{name}_{suffix}.png")
        if os.path.exists(src):
            shutil.copyfile(src, os.path.join(figdir, f"{name}_{suffix}.png"))
            out.append(f"![{name} {suffix}]({os.path.relpath(os.path.join(figdir, f'{name}_{suffix}.png'), docdir)})")
    out.append("")
    return out


def history_table(meta):
    """The refinement line's runs over time (metrics.csv columns at a subset of the outputs)."""
    history = meta.get("history") or {}
    if len(history) < 2:
        return []
    what = meta["refine"].split("/")[-1]
    columns = list(next(iter(history.values())).keys())
    values = list(history)
    times = [t for t, _ in history[values[-1]][columns[0]]]
    out = ["", f"The `{what}` line over time (output rows of metrics.csv, others at base): " +
           ", ".join(f"`{c}`" for c in columns) + " per run.", "",
           "| time | " + " | ".join(f"{what} {v}: {c}" for v in values for c in columns) + " |",
           "|" + "---|" * (1 + len(values) * len(columns))]
    # Output times that differ in their last digits (3.9999 and 4: a stage's own clock) match.
    def key(t):
        return round(t, 2)
    for i, t in enumerate(times):
        cells = [fmt(t, 4)]
        for v in values:
            for c in columns:
                series = {key(u): x for u, x in history[v][c]}
                cells.append(fmt(series.get(key(t)), 5))
        out.append("| " + " | ".join(cells) + " |")
    return out


def compare_with_thesis(name, rows, meta):
    """The thesis's own figures for the same study (Section 3.12.1), next to this code's."""
    ok = [r for r in rows if math.isfinite(r["qoi"]) and str(r.get("status", "")).startswith(("finished", "steady"))]
    keys = [k for k, _ in meta["knobs"]]
    out = []
    if name == "tether2d_fmax":
        points, gauss = keys[0], keys[1]
        at256 = {r["combo"][gauss]: r["qoi"] for r in ok if r["combo"][points] == "256"}
        if at256:
            out += ["", "Against the thesis's Table 3.2 (F_max at 256 points):", "",
                    "| N_GL | thesis | this code | difference |", "|---|---|---|---|"]
            for n, value in THESIS_TABLE_3_2.items():
                mine = at256.get(n)
                out.append(f"| {n} | {value} | {fmt(mine, 6)} | "
                           f"{fmt((mine - value) / value, 2) if mine is not None else '-'} |")
        base = {r["combo"][points]: r["qoi"] for r in ok if r["combo"][gauss] == meta["knobs"][1][1][0]}
        if all(n in base for n in ("64", "256", "320")):
            sel = [base[n] for n in ("64", "128", "256", "320") if n in base]
            spread = (max(sel) - min(sel)) / min(sel)
            last = abs(base["320"] - base["256"]) / base["256"]
            out += ["", f"Thesis Fig. 3.6: spread {THESIS_FIG_3_6['spread']:.1%} over N_E = 64-320, change "
                    f"< {THESIS_FIG_3_6['last_change']:.1%} from 256 to 320, fitted order N_E^{THESIS_FIG_3_6['order']}; "
                    f"this code (N_GL = {meta['knobs'][1][1][0]}): spread {spread:.2%}, change {last:.2%} from 256 to 320, "
                    f"Richardson order {fmt(meta.get('richardson_order'), 3)} "
                    f"({'none: ' + meta['reference_how'] if not meta.get('richardson_order') else 'N_E^-p'})."]
    if name == "cell3d_wall":
        line = meta.get("refine_line") or []
        if len(line) >= 2:
            qs = [q for _, q in line]
            spread = (max(qs) - min(qs)) / min(qs)
            order = meta.get("richardson_order")
            out += ["", f"Thesis Fig. 3.7: spread {THESIS_FIG_3_7['spread']:.1%} of D12_max over its meshes, fitted "
                    f"order N_E^{THESIS_FIG_3_7['order']}; this code: spread {spread:.2%} over N_E = "
                    + ", ".join(f"{ELEMENTS.get(str(round(-math.log2(h))), '?')}" for h, _ in line)
                    + (f", Richardson order {order:.2f} in h, i.e. N_E^{-order / 2:.2f} (N_E ~ h^-2)." if order else
                       f"; {meta['reference_how']}.")]
    if name == "cell3d_shear" and len(keys) > 1:
        quad = keys[1]
        for level in ("3", "2"):
            by = {r["combo"][quad]: r["qoi"] for r in ok if r["combo"][keys[0]] == level
                  and all(r["combo"][k] == v[0] for k, v in meta["knobs"][2:])}
            if len(by) >= 3:
                vals = list(by.values())
                out += ["", f"Thesis Table 3.3 (N_Q = 6, 7, 9, 13; a prestressed Skalak capsule at Ca = 1.8): D12 "
                        f"changes by less than 0.2%; here (level {level}, N_Q = {', '.join(by)}): "
                        f"{(max(vals) - min(vals)) / min(vals):.3%}."]
                break
    return out


def cheapest(rows, target):
    good = [r for r in rows if math.isfinite(r["rel_error"]) and r["rel_error"] <= target
            and str(r.get("status", "")).startswith(("finished", "steady"))]
    return min(good, key=lambda r: r["wall_s"]) if good else None


def choose_section(results):
    out = ["## How to choose", "",
           "The cheapest run of each sweep (wall time on this machine) whose error against the reference is "
           "within the accuracy asked for; the errors are those of the sweep's QoI and reference, so they hold for "
           "runs like these (other Ca, shapes or end times move them; rerun the sweep for a new case).", "",
           "| study | accuracy | cheapest settings | its error | wall s |", "|---|---|---|---|---|"]
    for name, (rows, meta) in results.items():
        if name == "gmres_lambda5":
            continue
        for target in (0.01, 0.001):
            # The reference run itself has no measured error: it cannot be recommended from the sweep.
            r = cheapest([x for x in rows if x["rel_error"] > 0], target)
            if r is None:
                what = ("none but the reference run itself" if meta["reference_how"].startswith("finest")
                        else "none of the runs")
                out.append(f"| {name} | {target:.1%} | {what}: not reached by this sweep | - | - |")
            else:
                settings = ", ".join(f"{k.split('/')[-1]} {v}" for k, v in r["combo"].items())
                out.append(f"| {name} | {target:.1%} | {settings} | {r['rel_error']:.2g} | {r['wall_s']:.3g} |")
    if "gmres_lambda5" in results:
        rows, meta = results["gmres_lambda5"]
        for target in (0.01, 0.001):
            # The solver's error should stay a tenth of the accuracy asked for, so that the
            # discretisation's error, not GMRES's, sets it; of those runs the cheapest (a loose
            # tolerance is not always cheaper: a noisy right-hand side makes RKF45 reject steps).
            good = [x for x in rows if math.isfinite(x["rel_error"]) and x["rel_error"] <= target * 0.1
                    and str(x.get("status", "")).startswith(("finished", "steady"))]
            r = min(good, key=lambda x: x["wall_s"]) if good else None
            if r:
                out.append(f"| gmres_lambda5 (GMRES error 10x below the accuracy) | {target:.1%} | "
                           f"{', '.join(f'{k} {v}' for k, v in r['combo'].items())} | {r['rel_error']:.2g} | "
                           f"{r['wall_s']:.3g} |")
    out.append("")
    return out


def targets_section(path):
    with open(path) as f:
        data = json.load(f)
    out = ["## Performance targets (utils/bench/bench_targets.py)", "",
           f"{data['steps']} RKF45 steps of 1e-3 per case; step cost = 6 x the time per right-hand side "
           "(the right-hand side's Teuchos timers, setup and outputs excluded; the 3D apps' stability-limit "
           "estimates, 12 right-hand sides at the first step and 3 every 10 steps, are in the wall time per "
           "accepted step, not in the step cost); peak memory = the largest "
           "resident set of any process of the run. Speed-up: measured/target >= 1 meets it; every other row: "
           "<= 1 meets it." + (" QUICK MODE (level 1, 64 points): the targets do not apply." if data["quick"] else ""),
           "", "| what | measured | target | measured / target | measured / thesis Table 3.4 |", "|---|---|---|---|---|"]
    for row in data["table"]:
        m, t, th = row["measured"], row["target"], row["thesis"]
        out.append(f"| {row['what']} | {fmt(m, 3)} {row['unit']} | {fmt(t, 3) if t else '-'} | "
                   f"{fmt(m / t, 3) if t else '-'} | {fmt(m / th, 3) if th else '-'} |")
    out += ["", "| run | ranks | s per step | wall s per accepted step | CPU s per step (all ranks) | steps | peak MB | "
            "load before -> after |", "|---|---|---|---|---|---|---|---|"]
    for name, r in data["runs"].items():
        out.append(f"| {name} | {r['ranks']} | {fmt(r.get('s_per_step'), 3)} | {fmt(r.get('wall_per_accepted_step'), 3)} | "
                   f"{fmt(r.get('cpu_per_step'), 3)} | "
                   f"{r.get('steps', 0)} | {fmt(r['peak_rss_mb'], 3)} | {r['load_before']:.2f} -> {r['load_after']:.2f} |")
    out += ["", "Profile (Teuchos timers of rank 0, share of the run's wall time; nested timers overlap: "
            "`Single layer` and `Viscosity-ratio GMRES solve` are inside `Boundary-integral velocity`):", ""]
    for name, r in data["runs"].items():
        t = r.get("timers", {})
        total = r.get("app_wall")
        if not total or "Single layer" not in t:
            continue
        parts = ", ".join(f"{k} {100 * v / total:.0f}%" for k, v in t.items()
                          if isinstance(v, (int, float)) and not k.startswith("wall") and v > 0)
        out.append(f"- {name} ({total:.2f} s): {parts}")
    out.append("")
    return out


def kernels_section(path):
    with open(path) as f:
        data = json.load(f)
    ctx = data.get("context", {})
    out = ["## Kernel and operator microbenchmarks (apps/bench_kernels, Google Benchmark)", "",
           f"One rank; load average {', '.join(f'{x:.2f}' for x in ctx.get('load_avg', []))} at the start. Sums: one "
           "block of 128 targets against the 8960 quadrature points of a level-3 cell (N_Q = 7); a whole "
           "level-3 evaluation is 20 such blocks (2562 targets), so 20 x the single-layer wall-kernel CPU time is "
           "the direct-sum floor of one velocity evaluation. nodeVelocities/lambdaL/n: one node-velocity "
           "evaluation at level n (single layer with all corrections; GMRES for lambda = 5).", "",
           "| benchmark | wall ms | CPU ms | iterations | counters |", "|---|---|---|---|---|"]
    skip = {"name", "run_name", "run_type", "repetitions", "repetition_index", "threads", "iterations", "real_time",
            "cpu_time", "time_unit", "family_index", "per_family_instance_index", "aggregate_name"}
    for b in data.get("benchmarks", []):
        scale = {"ms": 1.0, "us": 1e-3, "ns": 1e-6, "s": 1e3}[b.get("time_unit", "ns")]
        counters = ", ".join(f"{k} {v:.4g}" for k, v in b.items() if k not in skip and isinstance(v, (int, float)))
        out.append(f"| {b['name']} | {b['real_time'] * scale:.3g} | {b['cpu_time'] * scale:.3g} | {b['iterations']} | "
                   f"{counters} |")
    by_name = {b["name"]: b for b in data.get("benchmarks", [])}
    block = by_name.get("singleLayerSums<Wall3DKernel>")
    evaluation = by_name.get("nodeVelocities/lambda1/3")
    if block and evaluation:
        floor = 2562 / 128 * block["cpu_time"]  # same time unit for both (ms)
        out += ["", f"Direct-sum floor of one level-3 wall evaluation on one core: 2562/128 x "
                f"{block['cpu_time']:.3g} = {floor:.3g} ms of CPU; the full evaluation (corrections included) takes "
                f"{evaluation['cpu_time']:.3g} ms, {evaluation['cpu_time'] / floor:.2f} x the floor. Six stages: "
                f"{6 * floor / 1e3:.3g} s per RKF45 step at the floor on one core, {3 * floor / 1e3:.3g} s on two."]
    out.append("")
    return out


def write(report, results, args, seconds):
    docdir = os.path.dirname(os.path.abspath(report))
    figdir = os.path.join(docdir, "figures", "accuracy-cost")
    os.makedirs(figdir, exist_ok=True)
    loads = [r["load_before"] for rows, _ in results.values() for r in rows]
    cmd = os.environ.get("ACCURACY_COST_COMMAND") or "utils/bench/accuracy_cost.py " + " ".join(os.sys.argv[1:])
    swept = sum(r["wall_s"] for rows, _ in results.values() for r in rows)
    out = ["# What accuracy costs", "",
           f"{generated_pages.header_line(cmd.strip(), ROOT)[:-1]} (it runs utils/bench/bench_targets.py, "
           f"apps/bench_kernels and utils/bench/accuracy_cost.py), on {os.cpu_count()} cores ({cpu_model()}) shared "
           f"with other jobs: load average {min(loads):.1f}-{max(loads):.1f} during the runs (1-minute, "
           f"/proc/loadavg). The sweeps' runs took {swept:.0f} s of wall time in all. Times on a loaded machine "
           "are upper bounds: rerun the command on a quiet machine for clean numbers (finished runs in "
           f"`{os.path.relpath(args.runs, ROOT)}` are reused; delete it first).", "",
           "Columns: QoI and its relative error against the reference; the knob's own change (the change of the QoI "
           "from the same line's run at the knob's tightest value: the part of the error that knob controls); drift "
           "= largest |volume (3D) or area (2D) change| / initial; max distortion (3D) = the largest "
           "`max_distortion` of the output rows (docs/stability.md: how far midside nodes slid along their edges, "
           "which grows with a mesh-scale mode such as the wrinkles of a compressed membrane); s / rhs = "
           "integration time per right-hand side "
           "(3D: membrane loads + boundary-integral velocity; 2D: the app's own figure); s / step = wall time of the "
           "run / accepted steps (setup and outputs included); peak MB = largest resident set of any process of the "
           "run; load = 1-minute load average when the run started.", "",
           "Where the membrane is stiff (low Ca, large area dilation) the explicit time step is set by stability, "
           "not by the tolerance: the linearly implicit methods and what they save are measured in "
           "docs/stiff-integration-results.md (method and keys: docs/stiff-integration.md).", ""]
    if args.quick:
        out += ["QUICK MODE: tiny meshes and short end times; the numbers check the pipeline, not the method.", ""]
    for name, (rows, meta) in results.items():
        meta["runs"] = args.runs
        out += study_section(name, rows, meta, figdir, docdir)
    out += choose_section(results)
    targets = getattr(args, "targets", None)
    if targets and os.path.exists(targets):
        out += targets_section(targets)
    kernels = getattr(args, "kernels", None)
    if kernels and os.path.exists(kernels):
        out += kernels_section(kernels)
    notes = os.path.join(HERE, "accuracy-cost-notes.md")
    if os.path.exists(notes):
        with open(notes) as f:
            out += [f.read()]
    with open(report + ".tmp", "w") as f:
        f.write("\n".join(out) + "\n")
    os.replace(report + ".tmp", report)
    print(f"accuracy-cost: wrote {report} and {figdir}/")
