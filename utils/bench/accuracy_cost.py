#!/usr/bin/python3
"""What accuracy costs in time: sweeps of an app deck over lists of knobs, the error of
each run against a reference, its cost, and the report docs/accuracy-cost.md. (Length: the
sweep, its error measures, plots and the study list all read and write the same run records.)

  accuracy_cost.py sweep --app BUILD/apps/cell3d/cell3d --deck DECK --out DIR \\
      --knob "Cells/Cell 0/Mesh level=1,2,3" --knob "Discretisation/Quadrature points=3,7" \\
      [--grid product|axes|mixed|blocks] [--block "KEY=v1,v2;KEY2=v3"]... [--set KEY=VALUE]... \\
      [--ranks 2] [--qoi metrics:D12] [--refine "Cells/Cell 0/Mesh level:level"] [--exact VALUE]
  accuracy_cost.py all --build BUILD [--quick] [--runs DIR] [--report docs/accuracy-cost.md] [--check]

sweep: runs every combination (product), every knob varied alone from the first value of the
others (axes; the first value of each knob is the base point), (mixed) the product of the
first two knobs plus each further knob's values at every value of the first, or (blocks) the
union of the products given by each --block (knobs a block does not name stay at their first
value), through `--set` overrides.
Per run it records the quantity of interest (QoI), its error against the reference, the
volume (3D) or area (2D) drift, time per right-hand side, time per accepted step, steps,
right-hand sides, wall time, peak memory (largest resident set of any process of the run,
from wait4's rusage of the whole process tree) and ranks, with /proc/loadavg before and after,
into DIR/results.csv; and draws DIR/<name>_pareto.png (error against wall time, Pareto front)
and DIR/<name>_orders.png (error against each knob, fitted orders).

QoI: `metrics:COL` (last row of metrics.csv), `metrics-max:COL` (largest value of the column),
`metrics-peak:COL` (the maximum of the parabola through the largest value and its two
neighbouring rows: the peak between output times, error O(interval^3) instead of the
O(interval^2) of metrics-max), `summary:a.b.c` (a key path in summary.json; integer parts index
lists).
Reference: --exact VALUE, or Richardson extrapolation of the three finest runs along the
--refine knob (the others at their base values), with the observed order; `level` means
h = 2^-n (icosphere level), `points` h = 1/N; two runs only: the finest run is the reference.

all: the five studies (3D free shear, 3D D12_max near the wall, 2D tether F_max at the thesis's
gap and at gap 0.1, lambda = 5 GMRES tolerance); with --report, writes the markdown report from
what was measured, with the performance targets of bench_targets.py (--targets) and the kernel
microbenchmarks (--kernels). --quick: tiny meshes and short end times, a pipeline check (--check exits
non-zero unless every study has rows with finite errors and its plots exist). Runs already
finished in --runs are reused (delete the folder to start from scratch).
"""
import argparse
import csv
import itertools
import json
import math
import os
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))

COLUMNS = ["study", "run", "ranks", "knobs", "status", "qoi", "reference", "error", "rel_error",
           "drift", "s_per_rhs", "s_per_step", "steps", "rejected", "rhs", "wall_s", "cpu_s",
           "peak_rss_mb", "load_before", "load_after", "h"]


def loadavg():
    with open("/proc/loadavg") as f:
        return float(f.read().split()[0])


def parse_knob(text):
    if "=" not in text:
        raise SystemExit(f"accuracy-cost: --knob '{text}' is not KEY=v1,v2,...")
    key, values = text.split("=", 1)
    vals = [v.strip() for v in values.split(",") if v.strip()]
    if not vals:
        raise SystemExit(f"accuracy-cost: --knob '{text}' has no values")
    return key.strip(), vals


def parse_block(text, knobs):
    """'KEY=v1,v2;KEY2=v3' -> {KEY: [v1, v2], KEY2: [v3]}; every KEY must be a knob."""
    block = {}
    for part in text.split(";"):
        key, vals = parse_knob(part)
        if key not in dict(knobs):
            raise SystemExit(f"accuracy-cost: --block names '{key}', which is not a --knob")
        block[key] = vals
    return block


def combinations(knobs, grid, blocks=()):
    """(dict key -> value) for every run; 'axes' varies one knob at a time from the base."""
    if grid == "blocks":
        base = {k: v[0] for k, v in knobs}
        out = []
        for block in blocks:
            keys = list(block)
            for values in itertools.product(*[block[k] for k in keys]):
                combo = dict(base, **dict(zip(keys, values)))
                if combo not in out:
                    out.append(combo)
        return out
    if grid == "product":
        keys = [k for k, _ in knobs]
        return [dict(zip(keys, c)) for c in itertools.product(*[v for _, v in knobs])]
    base = {k: v[0] for k, v in knobs}
    if grid == "mixed":
        # The product of the first two knobs; each further knob's values at every value of the
        # first (the others at base): e.g. mesh x quadrature, and the tolerance at every mesh.
        (k1, v1), (k2, v2) = knobs[:2]
        out = [dict(base, **{k1: a, k2: b}) for a in v1 for b in v2]
        out += [dict(base, **{k1: a, k: v}) for k, vals in knobs[2:] for a in v1 for v in vals[1:]]
        return out
    out = [dict(base)]
    for k, vals in knobs:
        for v in vals[1:]:
            c = dict(base)
            c[k] = v
            out.append(c)
    return out


def run_name(combo, ranks):
    parts = [f"{k.split('/')[-1].replace(' ', '')}{v}" for k, v in combo.items()]
    return "_".join(parts + [f"np{ranks}"]).replace("/", "-")


def run_app(app, deck, combo, fixed, ranks, outdir, timeout):
    """Runs one case; returns (returncode, wall seconds, peak RSS in MB, load before, after, CPU
    seconds of all its processes)."""
    cmd = []
    if ranks > 1:
        cmd = ["mpiexec", "-n", str(ranks), "--oversubscribe"]
    cmd += [app, deck]
    for k, v in list(fixed.items()) + list(combo.items()):
        cmd += ["--set", f"{k}={v}"]
    cmd += ["--output", outdir]
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    os.makedirs(outdir, exist_ok=True)
    before = loadavg()
    start = time.monotonic()
    with open(outdir + ".log", "w") as log:
        log.write(" ".join(f"'{c}'" if " " in c else c for c in cmd) + "\n")
        log.flush()
        try:
            proc = subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT, env=env)
        except OSError as e:
            log.write(f"accuracy-cost: cannot start {cmd[0]}: {e}\n")
            return 127, 0.0, 0.0, before, loadavg(), 0.0
        deadline = start + timeout
        while True:
            pid, status, usage = os.wait4(proc.pid, os.WNOHANG)
            if pid:
                break
            if time.monotonic() > deadline:
                proc.kill()
                pid, status, usage = os.wait4(proc.pid, 0)
                break
            time.sleep(0.05)
    wall = time.monotonic() - start
    code = os.waitstatus_to_exitcode(status)
    # ru_maxrss (kB) of a reaped child covers its waited-for descendants too: the largest rank.
    return code, wall, usage.ru_maxrss / 1024.0, before, loadavg(), usage.ru_utime + usage.ru_stime


def lookup(obj, path):
    for part in path.split("."):
        if isinstance(obj, list):
            obj = obj[int(part)]
        else:
            obj = obj[part]
    return float(obj)


def read_qoi(outdir, qoi):
    kind, _, what = qoi.partition(":")
    if kind == "summary":
        with open(os.path.join(outdir, "summary.json")) as f:
            return lookup(json.load(f), what)
    with open(os.path.join(outdir, "metrics.csv")) as f:
        rows = list(csv.DictReader(f))
    col = [float(r[what]) for r in rows if r.get(what, "") not in ("", None)]
    if not col:
        raise KeyError(f"metrics.csv has no column {what}")
    if kind == "metrics-peak":
        times = [float(r["time"]) for r in rows if r.get(what, "") not in ("", None)]
        return peak(times, col)
    return max(col) if kind == "metrics-max" else col[-1]


def peak(times, values):
    """The largest value of a sampled curve, refined by the parabola through the largest sample
    and its two neighbours (the sample itself at either end of the record)."""
    k = max(range(len(values)), key=lambda i: values[i])
    if k == 0 or k == len(values) - 1:
        return values[k]
    (t0, t1, t2), (v0, v1, v2) = times[k - 1:k + 2], values[k - 1:k + 2]
    # Newton form: v = v0 + a (t - t0) + b (t - t0)(t - t1); the vertex of the parabola.
    a = (v1 - v0) / (t1 - t0)
    b = ((v2 - v1) / (t2 - t1) - a) / (t2 - t0)
    if b >= 0.0:
        return v1
    tv = 0.5 * (t0 + t1) - a / (2.0 * b)
    return v0 + a * (tv - t0) + b * (tv - t0) * (tv - t1)


def read_costs(outdir):
    """Steps, right-hand sides, drift and the integration time per rhs from summary.json."""
    with open(os.path.join(outdir, "summary.json")) as f:
        s = json.load(f)
    t = s.get("timings", {})
    st = s.get("steps", {})
    rhs = st.get("rhs evaluations", 0)
    costs = dict(status=s.get("status", "?"), steps=st.get("accepted", 0), rejected=st.get("rejected", 0), rhs=rhs,
                 app_wall=t.get("wall seconds (this process)", float("nan")), timers=t)
    if s.get("application") == "tether2d":
        costs.update(drift=s.get("max", {}).get("abs_area_drift", float("nan")),
                     s_per_rhs=t.get("seconds per rhs evaluation (this process)", float("nan")))
        return costs
    # The right-hand side proper: membrane loads, the boundary-integral velocity (single layer,
    # double layer and GMRES inside) and the fixed-height constraint; outputs are apart.
    work = sum(t.get(k, 0.0) for k in ("Membrane tensions and loads", "Boundary-integral velocity",
                                       "Fixed-height constraint"))
    costs.update(drift=abs(s.get("max volume drift", float("nan"))), s_per_rhs=work / rhs if rhs else float("nan"),
                 distortion=column_max(outdir, "max_distortion"))
    return costs


def column_max(outdir, column):
    """The largest value of a metrics.csv column over the output rows after t = 0 (NaN if absent).
    For max_distortion (docs/stability.md): how far midside nodes slid along their edges, the
    mark of a mesh-scale mode such as the wrinkles of a compressed membrane."""
    try:
        with open(os.path.join(outdir, "metrics.csv")) as f:
            rows = list(csv.DictReader(f))
        values = [float(r[column]) for r in rows if r.get(column) not in ("", None) and float(r["time"]) > 0]
        return max(values) if values else float("nan")
    except (OSError, KeyError, ValueError):
        return float("nan")


def mesh_size(value, kind):
    v = float(value)
    return 2.0 ** -v if kind == "level" else 1.0 / v


def richardson(pairs):
    """pairs: (h, q) sorted coarse to fine. Returns (q_inf, observed order or None) from the three
    finest, fitting q = q_inf + C h^p exactly (any ratios of h). With a fourth, coarser run the
    fit must also predict it to within half the change between the coarser two of the three:
    three runs fit any sequence of monotone changes, a fourth tells an asymptotic range from
    one that is not."""
    if len(pairs) < 3:
        return pairs[-1][1], None
    (h1, q1), (h2, q2), (h3, q3) = pairs[-3:]
    d1, d2 = q1 - q2, q2 - q3
    if d1 * d2 <= 0 or not h1 > h2 > h3 > 0:
        # Not in the asymptotic range (oscillating or stalled): the finest run stands.
        return q3, None

    def mismatch(p):  # (h1^p - h2^p) / (h2^p - h3^p) - d1 / d2, increasing in p
        return (h1 ** p - h2 ** p) / (h2 ** p - h3 ** p) - d1 / d2

    lo, hi = 0.05, 12.0
    if mismatch(lo) > 0 or mismatch(hi) < 0:
        # Differences shrinking slower than order 0.05 or faster than order 12: no asymptotic fit.
        return q3, None
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if mismatch(mid) < 0 else (lo, mid)
    p = 0.5 * (lo + hi)
    # q = q_inf + C h^p: C = d2 / (h2^p - h3^p), q3 - q_inf = C h3^p.
    c = d2 / (h2 ** p - h3 ** p)
    q_inf = q3 - c * h3 ** p
    if len(pairs) >= 4:
        h0, q0 = pairs[-4]
        if abs(q_inf + c * h0 ** p - q0) > 0.5 * abs(d1):
            return q3, None
    return q_inf, p


def refine_line(ok, base, refine_key, refine_kind, ranks):
    """(h, QoI) of the runs along the refinement knob, the others at base, coarse to fine."""
    if not refine_key:
        return []
    line = [r for r in ok if r["ranks"] == ranks and all(r["combo"][k] == base[k] for k in base if k != refine_key)]
    return sorted(((mesh_size(r["combo"][refine_key], refine_kind), r["qoi"]) for r in line), key=lambda p: -p[0])


def line_history(out, ok, base, refine_key, refine_kind, ranks, columns, rows=13):
    """Columns of metrics.csv at the output times of the runs along the refinement line (others
    at base): {value of the knob: {column: [(time, value), ...]}}, every few rows so that at most
    `rows` are kept. Where the line's runs part, and what the mesh-scale diagnostics did then."""
    if not refine_key or not columns:
        return {}
    history = {}
    for r in ok:
        if r["ranks"] != ranks or any(r["combo"][k] != base[k] for k in base if k != refine_key):
            continue
        try:
            with open(os.path.join(out, r["run"], "metrics.csv")) as f:
                table = list(csv.DictReader(f))
        except OSError:
            continue
        stride = max(1, -(-len(table) // rows))
        kept = table[::stride]
        history[r["combo"][refine_key]] = {
            c: [(float(t["time"]), float(t[c])) for t in kept if t.get(c) not in (None, "")] for c in columns}
    return dict(sorted(history.items(), key=lambda kv: -mesh_size(kv[0], refine_kind)))


def pareto(points):
    """Indices of the (cost, error) points no other point beats in both."""
    order = sorted(range(len(points)), key=lambda i: (points[i][0], points[i][1]))
    front, best = [], float("inf")
    for i in order:
        if points[i][1] < best:
            front.append(i)
            best = points[i][1]
    return front


def fit_order(xs, errs):
    """Slope of log(err) against log(x) (least squares), or None with < 2 usable points."""
    pts = [(math.log(x), math.log(e)) for x, e in zip(xs, errs) if x > 0 and e > 0 and math.isfinite(e)]
    if len(pts) < 2:
        return None
    a = np.array(pts)
    return float(np.polyfit(a[:, 0], a[:, 1], 1)[0])


def sweep(args):
    knobs = [parse_knob(k) for k in args.knob]
    fixed = dict(parse_knob(s) for s in args.set)
    fixed = {k: v[0] for k, v in fixed.items()}
    ranks_list = [int(r) for r in str(args.ranks).split(",")]
    blocks = [parse_block(b, knobs) for b in (args.block or [])]
    if args.grid == "blocks" and not blocks:
        raise SystemExit("accuracy-cost: --grid blocks needs at least one --block")
    combos = combinations(knobs, args.grid, blocks)
    os.makedirs(args.out, exist_ok=True)
    refine_key, refine_kind = (args.refine.rsplit(":", 1) + ["level"])[:2] if args.refine else (None, None)
    rows = []
    for ranks in ranks_list:
        for combo in combos:
            name = run_name(combo, ranks)
            outdir = os.path.join(args.out, name)
            record_path = outdir + ".record.json"
            rec = None
            if os.path.exists(record_path):
                with open(record_path) as f:
                    rec = json.load(f)
                # Reuse a run only if it was made with the same app, deck and fixed settings.
                if rec.get("setup") != [os.path.basename(args.app), args.deck, fixed]:
                    rec = None
            if rec is None:
                code, wall, rss, lb, la, cpu = run_app(args.app, args.deck, combo, fixed, ranks, outdir,
                                                       args.timeout)
                rec = dict(run=name, ranks=ranks, combo=combo, code=code, wall_s=wall, peak_rss_mb=rss,
                           load_before=lb, load_after=la, cpu_s=cpu,
                           setup=[os.path.basename(args.app), args.deck, fixed])
                try:
                    rec.update(read_costs(outdir))
                    rec["qoi"] = read_qoi(outdir, args.qoi)
                except (OSError, KeyError, ValueError, IndexError) as e:
                    rec["status"] = f"failed ({e.__class__.__name__}: {e}; exit {code})"
                    rec["qoi"] = float("nan")
                if code != 0 and not rec.get("status", "").startswith("failed"):
                    rec["status"] = f"failed (exit {code})"
                tmp = record_path + ".tmp"
                with open(tmp, "w") as f:
                    json.dump(rec, f, indent=1)
                os.replace(tmp, record_path)
            print(f"  {args.name}: {name}: qoi {rec['qoi']:.6g}, {rec.get('steps', 0)} steps, "
                  f"{rec['wall_s']:.1f} s, {rec['peak_rss_mb']:.0f} MB, load {rec['load_before']:.2f} "
                  f"[{rec.get('status')}]", flush=True)
            rows.append(rec)
    base = {k: v[0] for k, v in knobs}
    ok = [r for r in rows if math.isfinite(r["qoi"])]
    order = None
    if args.exact is not None:
        reference, how = args.exact, "given value"
    else:
        line = refine_line(ok, base, refine_key, refine_kind, ranks_list[0])
        if line:
            reference, order = richardson(line)
            how = (f"Richardson from the three finest {refine_key} runs (observed order {order:.2f})"
                   if order else f"finest {refine_key} run (no asymptotic Richardson triple)")
        else:
            # No refinement line: the run with the tightest settings is the last of the first knob.
            reference, how = (ok[-1]["qoi"] if ok else float("nan")), "last run"
    for r in rows:
        r["reference"] = reference
        r["error"] = abs(r["qoi"] - reference)
        r["rel_error"] = r["error"] / abs(reference) if reference else float("nan")
        r["h"] = mesh_size(r["combo"][refine_key], refine_kind) if refine_key in r["combo"] else float("nan")
    write_csv(args.out, args.name, rows)
    orders = plot(args.out, args.name, rows, knobs, base, refine_key, refine_kind, args.qoi, how)
    meta = dict(name=args.name, app=os.path.basename(args.app), deck=os.path.relpath(args.deck, ROOT),
                fixed=fixed, knobs=knobs, grid=args.grid, blocks=blocks, qoi=args.qoi, reference=reference,
                reference_how=how, richardson_order=order, orders=orders, ranks=ranks_list,
                refine=refine_key, refine_line=refine_line(ok, base, refine_key, refine_kind, ranks_list[0]),
                history=line_history(args.out, ok, base, refine_key, refine_kind, ranks_list[0],
                                     getattr(args, "history", None) or []))
    with open(os.path.join(args.out, args.name + ".meta.json"), "w") as f:
        json.dump(meta, f, indent=1)
    return rows, meta


def write_csv(out, name, rows):
    path = os.path.join(out, name + ".csv")
    with open(path + ".tmp", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(COLUMNS)
        for r in rows:
            knobs = "; ".join(f"{k}={v}" for k, v in r["combo"].items())
            w.writerow([name, r["run"], r["ranks"], knobs, r.get("status"), r["qoi"], r["reference"], r["error"],
                        r["rel_error"], r.get("drift", float("nan")), r.get("s_per_rhs", float("nan")),
                        r["wall_s"] / r["steps"] if r.get("steps") else float("nan"), r.get("steps", 0),
                        r.get("rejected", 0), r.get("rhs", 0), r["wall_s"], r.get("cpu_s", float("nan")), r["peak_rss_mb"],
                        r["load_before"], r["load_after"], r["h"]])
    os.replace(path + ".tmp", path)


def plot(out, name, rows, knobs, base, refine_key, refine_kind, qoi, how):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    ok = [r for r in rows if math.isfinite(r["rel_error"])]
    fig, ax = plt.subplots(figsize=(7, 4.5))
    # The reference run itself (zero error by construction) has no error to show.
    shown = [r for r in ok if r["rel_error"] > 0]
    pts = [(r["wall_s"], r["rel_error"]) for r in shown]
    for r, (x, y) in zip(shown, pts):
        ax.loglog(x, y, "o", color="C%d" % (r["ranks"] % 10), ms=5)
        label = ",".join(str(v) for v in r["combo"].values()) + f" np{r['ranks']}"
        ax.annotate(label, (x, y), fontsize=6, alpha=0.7)
    front = pareto(pts)
    if front:
        ax.loglog([pts[i][0] for i in front], [pts[i][1] for i in front], "k--", lw=1, label="Pareto front")
    ax.set_xlabel("wall time of the run (s, shared 2-core machine)")
    ax.set_ylabel(f"relative error of {qoi}")
    ax.set_title(f"{name}: error vs cost (labels: " + ", ".join(k.split("/")[-1] for k, _ in knobs)
                 + f")\nreference: {how}; the reference run is not drawn", fontsize=8)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, f"{name}_pareto.png"), dpi=120)
    plt.close(fig)
    # Each non-mesh knob's own contribution, wherever the sweep has runs that differ in that knob
    # only: the change of the QoI from the run at its tightest value (smallest tolerance, most
    # points); the mesh error, common to such runs, cancels.
    for key, _ in knobs:
        if key == refine_key:
            continue
        groups = {}
        for r in ok:
            sig = (r["ranks"],) + tuple((k, v) for k, v in sorted(r["combo"].items()) if k != key)
            groups.setdefault(sig, []).append(r)
        for rs in groups.values():
            if len(rs) < 2:
                continue
            rs.sort(key=lambda r: float(r["combo"][key]))
            tight = rs[0] if "Tolerance" in key else rs[-1]
            for r in rs:
                r.setdefault("partial", {})[key] = abs(r["qoi"] - tight["qoi"]) / abs(tight["qoi"])
    orders = {}
    fig, axes = plt.subplots(1, len(knobs), figsize=(max(6, 4 * len(knobs)), 4.2), squeeze=False)
    for ax, (key, vals) in zip(axes[0], knobs):
        # One line per rank count and, for a knob other than the mesh, per mesh value (the other
        # knobs at base): how the knob's own error changes with the mesh. The fitted order is the
        # base line's.
        free = {key} if key == refine_key else {key, refine_key}
        line = [r for r in ok if all(r["combo"][k] == base[k] for k in base if k not in free)]
        by_rank = {}
        for r in line:
            mesh = r["combo"].get(refine_key) if key != refine_key else None
            by_rank.setdefault((r["ranks"], mesh), []).append(r)
        for (ranks, mesh), rs in sorted(by_rank.items(), key=lambda kv: (kv[0][0], str(kv[0][1]))):
            if len(rs) < 2:
                continue
            on_base = mesh is None or mesh == base.get(refine_key)
            rs.sort(key=lambda r: float(r["combo"][key]))
            xs = [mesh_size(r["combo"][key], refine_kind) if key == refine_key else float(r["combo"][key]) for r in rs]
            if key == refine_key:
                rel = [r["rel_error"] for r in rs]
            else:
                # This knob's own contribution: the change from the run with its tightest value
                # (smallest tolerance, most points), the mesh error (common to the line) cancels.
                tight = rs[0] if "Tolerance" in key else rs[-1]
                rel = [abs(r["qoi"] - tight["qoi"]) / abs(tight["qoi"]) for r in rs]
            # The reference (or tightest) run has zero error by construction: not drawn.
            drawn = [(x, e) for x, e in zip(xs, rel) if e > 1e-12]
            label = f"{ranks} rank(s)" + (f", {refine_key.split('/')[-1]} {mesh}" if mesh is not None else "")
            if drawn:
                ax.loglog([x for x, _ in drawn], [e for _, e in drawn], "o-" if on_base else "o--", label=label)
            elif on_base:
                ax.text(0.5, 0.5, "no non-zero change", transform=ax.transAxes, ha="center")
            # The reference is (close to) one of the runs: leave it out of the fit.
            fitted = fit_order(xs, [e if e > 1e-12 else float("nan") for e in rel])
            if fitted is not None and on_base:
                orders[key] = fitted
                ax.set_title(f"fitted order {fitted:.2f} (base line)", fontsize=8)
        ax.set_xlabel("h (mesh size)" if key == refine_key else key.split("/")[-1])
        ax.set_ylabel("relative error" if key == refine_key else "relative change from the tightest value")
        ax.legend(fontsize=7)
    fig.suptitle(f"{name}: error along each knob (others at base)\nthe zero-error reference run is not drawn",
                 fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(out, f"{name}_orders.png"), dpi=120)
    plt.close(fig)
    return orders


# --- the studies of docs/accuracy-cost.md -----------------------------------------------------

def studies(build, quick):
    cell3d = os.path.join(build, "apps/cell3d/cell3d")
    tether = os.path.join(build, "apps/tether2d/tether2d")
    lac = os.path.join(ROOT, "input/cell3d/validation/lac2004-neohookean-Ca0.6.xml")
    t2d = os.path.join(ROOT, "input/tether2d/study/ab1_lambda1_ca0.25.xml")
    quiet3d = ["Output/Snapshots=false", "Output/Checkpoint=false", "Output/Progress steps=1000"]
    quiet2d = ["Output/Snapshot every=0", "Output/Checkpoint every=0"]
    level = "Cells/Cell 0/Mesh level"
    wall = os.path.join(ROOT, "input/cell3d/heights/Ca0.9-C2.5-prestress0-h1.2.xml")
    quadrature, singular, tolerance = ("Discretisation/Quadrature points", "Discretisation/Singular quadrature points",
                                       "Time integration/Tolerance")
    points, gauss = "Cell/Number of points", "Discretisation/Gauss-Legendre points"
    if quick:
        return [
            dict(name="cell3d_shear", app=cell3d, deck=lac, ranks="2", grid="blocks", qoi="metrics:D12",
             history=["D12", "max_distortion", "min_tension"], 
                 refine=level + ":level",
                 knob=[level + "=1,0,2", quadrature + "=7,3", tolerance + "=1e-5,1e-7"],
                 block=[f"{level}=0,1;{quadrature}=7,3", f"{level}=0,1;{tolerance}=1e-5,1e-7", f"{level}=2"],
                 set=quiet3d + ["Time integration/End time=0.3", "Output/Interval=0.1",
                                "Time integration/Steady tolerance=0"]),
            dict(name="cell3d_wall", app=cell3d, deck=wall, ranks="2", grid="axes", qoi="metrics-peak:D12",
             history=["D12", "max_distortion", "min_tension"], 
                 refine=level + ":level", knob=[level + "=0,1"],
                 set=quiet3d + ["Time integration/End time=0.3", "Output/Interval=0.05",
                                "Time integration/Steady tolerance=0", "Output/Wall shear stress/Enabled=false"]),
            dict(name="tether2d_fmax", app=tether, deck=t2d, ranks="1", grid="axes", qoi="summary:max.tether_force",
             history=["tether_force", "tether_force_y"], 
                 refine="Cell/Number of points:points",
                 knob=["Cell/Number of points=24,48,96", "Discretisation/Gauss-Legendre points=6,5"],
                 set=quiet2d + ["Time integration/End time=0.5", "Tether/Minimum preparation time=0.3",
                                "Tether/Maximum preparation time=0.5", "Output/Interval=0.25"]),
            dict(name="gmres_lambda5", app=cell3d, deck=lac, ranks="2", grid="axes", qoi="metrics:D12",
                 refine=None, knob=["Solver/Tolerance=1e-3,1e-6,1e-10"],
                 set=quiet3d + ["Flow/Viscosity ratio=5", level + "=1", "Time integration/End time=0.2",
                                "Output/Interval=0.1", "Time integration/Steady tolerance=0"]),
        ]
    return [
        # Lac et al. (2004) neo-Hookean Ca = 0.6, free shear: D12 at t = 4 (the plateau, within
        # 0.1% of the maximum, docs/validation-cell3d.md). Levels 1-3 with every N_Q, N_GL and
        # RKF45 tolerance; level 4 (10242 nodes, ~16 x level 3 per right-hand side) at the
        # defaults only, for the Richardson triple 2-3-4.
        dict(name="cell3d_shear", app=cell3d, deck=lac, ranks="2", grid="blocks", qoi="metrics:D12",
             history=["D12", "max_distortion", "min_tension"], 
             refine=level + ":level",
             knob=[level + "=2,1,3,4", quadrature + "=7,3,6,12,13", singular + "=6,3,4,8",
                   tolerance + "=1e-6,1e-8,1e-10"],
             block=[f"{level}=1,2,3;{quadrature}=7,3,6,12,13", f"{level}=1,2,3;{singular}=6,3,4,8",
                    f"{level}=1,2,3;{tolerance}=1e-6,1e-8,1e-10", f"{level}=4"],
             set=quiet3d + ["Time integration/End time=4", "Output/Interval=0.5",
                            "Time integration/Steady tolerance=0"]),
        # Thesis Fig. 3.7: D12_max of a Skalak cell (C = 2.5) released at h/a = 1.2 near the wall,
        # Ca = 0.9; D12 peaks at t ~ 2.2, so t = 3 with outputs every 0.05 and the peak refined
        # between them (metrics-peak).
        dict(name="cell3d_wall", app=cell3d, deck=wall, ranks="2", grid="blocks", qoi="metrics-peak:D12",
             history=["D12", "max_distortion", "min_tension"], 
             refine=level + ":level",
             knob=[level + "=2,1,3", quadrature + "=7,3,12", tolerance + "=1e-6,1e-8"],
             block=[f"{level}=1,2,3;{quadrature}=7,3,12", f"{level}=1,2;{tolerance}=1e-8"],
             set=quiet3d + ["Time integration/End time=3", "Output/Interval=0.05",
                            "Time integration/Steady tolerance=0", "Output/Wall shear stress/Enabled=false"]),
        # Thesis Section 3.12.1, Fig. 3.6 and Table 3.2: F_max, a/b = 1, Ca = 0.25, lambda = 1, to
        # tau = 12 (past the maximum, tau ~ 9-11), every N_E with every N_GL.
        dict(name="tether2d_fmax", app=tether, deck=t2d, ranks="1", grid="product", qoi="summary:max.tether_force",
             history=["tether_force", "tether_force_y"], 
             refine=points + ":points",
             knob=[points + "=128,64,256,320,512", gauss + "=6,5,8,12"],
             set=quiet2d + ["Time integration/End time=12", "Output/Interval=0.25"]),
        # The same with the cell released and tethered 0.1 above the wall instead of 0.005: the
        # lubrication film under the cell is then resolved from 128 points on (docs/tether2d-results.md),
        # and F_max converges.
        dict(name="tether2d_fmax_gap0.1", app=tether, deck=t2d, ranks="1", grid="axes",
             qoi="summary:max.tether_force", refine=points + ":points",
             knob=[points + "=128,64,256,512"],
             set=quiet2d + ["Time integration/End time=12", "Output/Interval=0.25", "Cell/Lowest point height=0.1",
                            "Tether/Anchor height=0.1"]),
        # lambda = 5: the GMRES tolerance against D12 at t = 1 (level 2), 1e-12 the reference.
        dict(name="gmres_lambda5", app=cell3d, deck=lac, ranks="2", grid="axes", qoi="metrics:D12",
             refine=None, knob=["Solver/Tolerance=1e-3,1e-4,1e-5,1e-6,1e-8,1e-12"],
             set=quiet3d + ["Flow/Viscosity ratio=5", level + "=2", "Time integration/End time=1",
                            "Output/Interval=0.25", "Time integration/Steady tolerance=0"]),
    ]


def run_all(args):
    results = {}
    for st in studies(args.build, args.quick):
        if args.only and st["name"] not in args.only.split(","):
            continue
        ns = argparse.Namespace(app=st["app"], deck=st["deck"], out=os.path.join(args.runs, st["name"]),
                                knob=st["knob"], set=st["set"], grid=st["grid"], block=st.get("block", []),
                                ranks=st["ranks"], history=st.get("history", []),
                                qoi=st["qoi"], refine=st["refine"], exact=None, name=st["name"],
                                timeout=args.timeout)
        t0 = time.monotonic()
        print(f"== {st['name']} (load {loadavg():.2f})", flush=True)
        rows, meta = sweep(ns)
        meta["seconds"] = time.monotonic() - t0
        results[st["name"]] = (rows, meta)
    return results


def check(results, runs):
    bad = []
    # The extrapolation itself, on q = 1 + 3 h^2 (exact: 1, order 2) and q = 2 - h^1.5.
    for qs, exact, order in (([(h, 1 + 3 * h * h) for h in (0.4, 0.2, 0.1)], 1.0, 2.0),
                             ([(h, 2 - h ** 1.5) for h in (1.0, 0.5, 0.25)], 2.0, 1.5),
                             ([(1 / n, 3 + 5 * n ** -1.45) for n in (128, 256, 320, 512)], 3.0, 1.45)):
        q_inf, p = richardson(qs)
        # Bisection to round-off in p: q_inf and p to ~1e-12 (the fits are exact).
        if p is None or abs(q_inf - exact) > 1e-10 or abs(p - order) > 1e-9:
            bad.append(f"Richardson extrapolation gave {q_inf} (order {p}) for {exact} (order {order})")
    # Three runs that happen to fit, and a coarser fourth that does not: no extrapolation.
    _, p = richardson([(1.0, 1.0), (0.5, 1.5), (0.25, 1.4), (0.125, 1.37)])
    if p is not None:
        bad.append(f"Richardson accepted a triple that its coarser fourth run contradicts (order {p})")
    for name, (rows, meta) in results.items():
        good = [r for r in rows if math.isfinite(r["rel_error"])]
        if len(good) < 2:
            bad.append(f"{name}: {len(good)} runs with a finite error")
        for suffix in ("_pareto.png", "_orders.png", ".csv"):
            p = os.path.join(runs, name, name + suffix)
            if not os.path.exists(p) or os.path.getsize(p) < 2000 and suffix != ".csv":
                bad.append(f"{name}: {p} missing or empty")
        with open(os.path.join(runs, name, name + ".csv")) as f:
            n = len(list(csv.DictReader(f)))
        if n != len(rows):
            bad.append(f"{name}: {n} CSV rows for {len(rows)} runs")
    for b in bad:
        print("CHECK FAILED:", b)
    print(f"accuracy-cost check: {len(results)} studies, {len(bad)} problems")
    return not bad


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = p.add_subparsers(dest="cmd", required=True)
    s = sub.add_parser("sweep")
    s.add_argument("--app", required=True)
    s.add_argument("--deck", required=True)
    s.add_argument("--out", required=True)
    s.add_argument("--name", default="sweep")
    s.add_argument("--knob", action="append", default=[], required=True)
    s.add_argument("--set", action="append", default=[])
    s.add_argument("--grid", choices=["product", "axes", "mixed", "blocks"], default="product")
    s.add_argument("--block", action="append", default=[])
    s.add_argument("--ranks", default="1")
    s.add_argument("--qoi", default="metrics:D12")
    s.add_argument("--refine")
    s.add_argument("--exact", type=float)
    s.add_argument("--timeout", type=float, default=3600)
    a = sub.add_parser("all")
    a.add_argument("--build", required=True)
    a.add_argument("--runs", default=os.path.join(ROOT, "out/accuracy-cost"))
    a.add_argument("--quick", action="store_true")
    a.add_argument("--only", help="comma-separated study names")
    a.add_argument("--report", help="write the markdown report here (figures next to it)")
    a.add_argument("--targets", help="a bench_targets.py JSON result to include in the report")
    a.add_argument("--kernels", help="a bench_kernels (Google Benchmark) JSON output to include in the report")
    a.add_argument("--check", action="store_true")
    a.add_argument("--timeout", type=float, default=1800)
    args = p.parse_args()
    if args.cmd == "sweep":
        sweep(args)
        return 0
    t0 = time.monotonic()
    results = run_all(args)
    if args.report:
        sys.path.insert(0, HERE)
        import importlib
        report = importlib.import_module("accuracy_cost_report")
        report.write(args.report, results, args, time.monotonic() - t0)
    ok = check(results, args.runs) if args.check else True
    if args.check:
        for path, what in ((args.targets, "bench_targets JSON"), (args.report, "report")):
            if path and not os.path.exists(path):
                print(f"CHECK FAILED: the {what} {path} is missing")
                ok = False
    print(f"== accuracy-cost done in {time.monotonic() - t0:.0f} s (exit status {0 if ok else 1})")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
