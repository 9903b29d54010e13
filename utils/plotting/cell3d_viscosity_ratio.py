#!/usr/bin/python3
"""The viscosity-ratio study (docs/cell3d-viscosity-ratio-results.md): the regime of each
cell3d run (tank-treading, swinging or tumbling), its mean inclination, velocities and wall
stress, and the cost of the lambda != 1 solve, against lambda, Ca and the height.

Every cell3d run found under the folders given is read (metrics.csv, deck.xml, summary.json).
Only the outputs after --transient count. The regime criterion, on the inclination theta of
the profile's long axis in the shear plane (inclination_deg, in (-90, 90]) and the membrane's
rigid rotation rate omega_z (omega_z, the least-squares rotation of the node velocities):

  tumbling       theta passes through the velocity-gradient direction (+-90 deg): the long
                 axis turns over, and the shape turns with the membrane (turning ratio
                 mean(d theta/dt) / mean(omega_z) near 1);
  swinging       theta stays between the flow and the gradient directions and oscillates with
                 a peak-to-peak amplitude (mean of its maxima less mean of its minima) of at
                 least --swing-threshold degrees (1 by default), while the membrane turns about the shape
                 (turning ratio near 0);
  tank-treading  the same with a smaller oscillation: a steady inclination.

A run that stopped before its end time (summary status other than "finished") is marked as
such and kept out of the trends.

Writes into --out
  cell3d_viscosity_ratio_table.md, cell3d_viscosity_ratio_table.csv   one row per run
  cell3d_viscosity_ratio_phase_diagram.png   regime against lambda and Ca, per law and height
  cell3d_viscosity_ratio_inclination.png     mean inclination (bars: half the swing) and D12 vs lambda
  cell3d_viscosity_ratio_velocities.png      u_slip, migration velocity u_lift and omega_z vs lambda
  cell3d_viscosity_ratio_histories.png       theta(t) (unwrapped) of the Skalak cell at the
                                             smallest and largest Ca, one line per lambda
  cell3d_viscosity_ratio_cost.png            GMRES iterations per velocity evaluation, the time
                                             of one velocity evaluation over lambda = 1's and
                                             the wall seconds per step against lambda

Usage: cell3d_viscosity_ratio.py --out FIGDIR [--transient T] RUNDIR_OR_PARENT...
       cell3d_viscosity_ratio.py --self-test   (the criterion on synthetic inclinations)
"""
import argparse
import math
import os
import sys

import numpy as np

TANK_TREADING, SWINGING, TUMBLING, STOPPED = "tank-treading", "swinging", "tumbling", "stopped"


# --- the regime criterion --------------------------------------------------------------------

def unwrapped_inclination(theta_deg):
    """theta (degrees, defined modulo 180) made continuous: a jump of more than 90 degrees
    between outputs is a pass through +-90."""
    theta = np.radians(2.0 * np.asarray(theta_deg, dtype=float))
    return np.degrees(np.unwrap(theta)) / 2.0


def oscillation(theta):
    """Peak-to-peak amplitude of an oscillating signal: the mean of its interior maxima less
    the mean of its interior minima; 0 without both (a monotone relaxation does not swing)."""
    slope = np.sign(np.diff(theta))
    turns = np.nonzero(slope[1:] * slope[:-1] < 0)[0] + 1
    maxima = [theta[i] for i in turns if slope[i - 1] > 0]
    minima = [theta[i] for i in turns if slope[i - 1] < 0]
    if not maxima or not minima:
        return 0.0
    return float(np.mean(maxima) - np.mean(minima))


def classify(t, theta_deg, omega_z, swing_threshold=1.0):
    """The regime of one run from its outputs after the transient.

    Returns a dict: regime, the peak-to-peak swing of theta (degrees, oscillation()), the mean inclination (degrees, of the wrapped angle; nan when tumbling), the
    net turn of the long axis (degrees, positive clockwise as the shear turns it) and the
    turning ratio mean(d theta/dt) / mean(omega_z)."""
    t = np.asarray(t, dtype=float)
    wrapped = np.asarray(theta_deg, dtype=float)
    omega = np.asarray(omega_z, dtype=float)
    if t.size < 3:
        raise ValueError("fewer than three outputs after the transient")
    theta = unwrapped_inclination(wrapped)
    turn = theta[0] - theta[-1]
    duration = t[-1] - t[0]
    mean_omega = float(np.mean(omega))
    ratio = math.radians(-turn / duration) / mean_omega if mean_omega != 0.0 else float("nan")
    passes = int(np.count_nonzero(np.abs(np.diff(wrapped)) > 90.0))
    swing = oscillation(theta)
    if passes > 0:
        regime, mean_theta = TUMBLING, float("nan")
    else:
        regime = SWINGING if swing >= swing_threshold else TANK_TREADING
        mean_theta = float(np.mean(wrapped))
    return dict(regime=regime, swing=swing, mean_theta=mean_theta, turn=float(turn), ratio=ratio)


def self_test():
    """The criterion on synthetic signals whose regime is known; returns the failures."""
    failures = []
    t = np.linspace(15.0, 30.0, 151)
    omega = np.full_like(t, -0.4)

    def expect(name, theta, regime):
        got = classify(t, theta, omega)
        if got["regime"] != regime:
            failures.append(f"{name}: {got['regime']} instead of {regime} ({got})")
        return got

    expect("steady 20 deg", np.full_like(t, 20.0) + 0.1 * np.sin(t), TANK_TREADING)
    swing = expect("swinging 10 +- 3 deg", 10.0 + 3.0 * np.sin(0.8 * t), SWINGING)
    if abs(swing["swing"] - 6.0) > 0.05 or abs(swing["mean_theta"] - 10.0) > 0.5:
        failures.append(f"swinging: swing {swing['swing']:.3f} (6), mean {swing['mean_theta']:.3f} (10)")
    expect("a slow drift is no swing", 20.0 - 0.05 * (t - 15.0), TANK_TREADING)
    # A rigid tumbler turning with omega_z: theta = -omega t wrapped into (-90, 90].
    rigid = np.degrees(-0.4 * t)
    wrapped = (rigid + 90.0) % 180.0 - 90.0
    tumble = expect("tumbling with the membrane", wrapped, TUMBLING)
    if abs(tumble["ratio"] - 1.0) > 1e-9 or abs(tumble["turn"] - math.degrees(0.4 * 15.0)) > 1e-9:
        failures.append(f"tumbling: ratio {tumble['ratio']} (1), turn {tumble['turn']} (343.8)")
    # The sign: a capsule swinging through +-45 never reaches +-90.
    expect("a large swing is not a tumble", 45.0 * np.sin(0.8 * t), SWINGING)
    return failures


# --- the runs --------------------------------------------------------------------------------

def describe(run, transient, swing_threshold):
    """One table row for a cell3d run."""
    wall = bool(run.value("Wall/Enabled", True))
    row = dict(
        directory=run.directory,
        law=run.value("Cells/Cell 0/Membrane law"), shape=run.value("Cells/Cell 0/Shape"),
        ca=float(run.value("Flow/Capillary number")), lam=float(run.value("Flow/Viscosity ratio")),
        height=float(run.value("Cells/Cell 0/Center")[1]) if wall else float("inf"),
        level=int(run.value("Cells/Cell 0/Mesh level")), status=run.summary.get("status"),
        time=float(run.summary.get("time", float("nan"))))
    steps = run.summary.get("steps", {})
    timings = run.summary.get("timings", {})
    row.update(steps=steps.get("accepted"), stiff_steps=steps.get("stiff steps", 0),
               rhs=steps.get("rhs evaluations"),
               seconds=timings.get("wall seconds (this process)", float("nan")),
               seconds_per_rhs=timings.get("seconds per rhs evaluation (this process)", float("nan")),
               # One boundary-integral velocity evaluation (the single layer and, for lambda != 1,
               # the double layer and GMRES), without the integrator's and the outputs' work.
               seconds_per_velocity=(timings.get("Boundary-integral velocity", float("nan")) /
                                     steps["rhs evaluations"] if steps.get("rhs evaluations") else float("nan")),
               volume_drift=run.summary.get("max volume drift", float("nan")))
    row["seconds_per_step"] = row["seconds"] / row["steps"] if row["steps"] else float("nan")
    table = run.table()
    keep = table["time"] >= transient
    if row["status"] != "finished" or np.count_nonzero(keep) < 3:
        row.update(regime=STOPPED, swing=float("nan"), mean_theta=float("nan"), turn=float("nan"),
                   ratio=float("nan"))
    else:
        row.update(classify(table["time"][keep], table["inclination_deg"][keep], table["omega_z"][keep],
                            swing_threshold))
    mean = (lambda name: float(np.mean(table[name][keep])) if name in table and keep.any() else float("nan"))
    row.update(D12=mean("D12"), u_slip=mean("u_slip"), u_lift=mean("u_lift"), omega_z=mean("omega_z"),
               wall_stress_max=mean("wall_stress_max"), gmres=mean("gmres_iterations"))
    row["history"] = (table["time"], table["inclination_deg"])
    return row


def setting_of(row):
    return "unbounded" if math.isinf(row["height"]) else f"h/a = {row['height']:g}"


def settings_in(rows):
    """Settings in the order of the figures' columns: unbounded first, then the heights from
    the highest down (towards the wall)."""
    heights = sorted({r["height"] for r in rows}, reverse=True)
    return [("unbounded" if math.isinf(h) else f"h/a = {h:g}", h) for h in heights]


COLUMNS = ["setting", "law", "shape", "ca", "lam", "regime", "mean_theta", "swing", "turn", "ratio",
           "D12", "u_slip", "u_lift", "omega_z", "wall_stress_max", "gmres", "steps", "stiff_steps",
           "seconds", "seconds_per_step", "seconds_per_rhs", "seconds_per_velocity", "cost_vs_lambda1", "volume_drift", "level", "status", "time"]


def add_cost_ratios(rows):
    """Each run's seconds per velocity evaluation over those of the lambda = 1 run of the same
    setting, law, shape and Ca (both measured in one study, side by side)."""
    for row in rows:
        same = [r for r in rows if r["lam"] == 1.0 and r["height"] == row["height"] and
                r["law"] == row["law"] and r["shape"] == row["shape"] and r["ca"] == row["ca"]]
        base = same[0]["seconds_per_velocity"] if same else float("nan")
        row["cost_vs_lambda1"] = row["seconds_per_velocity"] / base if base else float("nan")


def text(value):
    if isinstance(value, float):
        return "" if math.isnan(value) else f"{value:.4g}"
    return "" if value is None else str(value)


def write_tables(rows, folder, co, runs):
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, "cell3d_viscosity_ratio_table.csv"), "w", encoding="utf-8") as f:
        f.write(",".join(COLUMNS) + "\n")
        for row in rows:
            f.write(",".join(text(row[c] if c != "setting" else setting_of(row)) for c in COLUMNS) + "\n")
    shown = ["setting", "law", "shape", "ca", "lam", "regime", "mean_theta", "swing", "ratio", "D12",
             "u_slip", "u_lift", "omega_z", "wall_stress_max", "gmres", "steps", "stiff_steps", "seconds_per_step",
             "cost_vs_lambda1"]
    path = os.path.join(folder, "cell3d_viscosity_ratio_table.md")
    co.write_markdown_table(path, ["| " + " | ".join(shown) + " |", "|" + "---|" * len(shown)]
                            + ["| " + " | ".join(text(row[c] if c != "setting" else setting_of(row)) for c in shown) + " |"
                               for row in rows], runs)
    print(f"wrote {path}")


# --- figures ---------------------------------------------------------------------------------

MARKERS = {TANK_TREADING: ("o", "tab:blue"), SWINGING: ("^", "tab:green"), TUMBLING: ("s", "tab:red"),
           STOPPED: ("x", "black")}


def law_rows(rows):
    """The oblate runs grouped by law (the spherical control is shown in the tables only)."""
    laws = sorted({r["law"] for r in rows if r["shape"] != "Sphere"}, key=lambda law: law != "Skalak")
    return [(law, [r for r in rows if r["law"] == law and r["shape"] != "Sphere"]) for law in laws]


def phase_diagram(rows, folder, plt, co):
    groups, settings = law_rows(rows), settings_in(rows)
    fig, axes = plt.subplots(len(groups), len(settings), figsize=(3.2 * len(settings), 2.8 * len(groups)),
                             squeeze=False, sharex=True, sharey=True)
    for i, (law, members) in enumerate(groups):
        for j, (name, height) in enumerate(settings):
            ax = axes[i][j]
            for regime, (marker, colour) in MARKERS.items():
                chosen = [r for r in members if r["height"] == height and r["regime"] == regime]
                if chosen:
                    ax.scatter([r["lam"] for r in chosen], [r["ca"] for r in chosen], marker=marker, s=60,
                               color=colour, label=regime)
            co.log_axis_at(ax, [r["lam"] for r in rows])
            ax.set_yscale("log")
            ax.set_yticks(sorted({r["ca"] for r in rows}), [f"{c:g}" for c in sorted({r["ca"] for r in rows})])
            ax.minorticks_off()
            ax.set_title(f"{law}, {name}")
            if i == len(groups) - 1:
                ax.set_xlabel("viscosity ratio lambda")
            if j == 0:
                ax.set_ylabel("Ca")
    from matplotlib.lines import Line2D
    handles = [Line2D([], [], ls="none", marker=marker, color=colour, ms=7, label=regime)
               for regime, (marker, colour) in MARKERS.items()]
    # Between the lambda = 0.2 and 1 columns, where no marker is.
    axes[0][0].legend(handles=handles, loc="center left", bbox_to_anchor=(0.07, 0.6), fontsize=7)
    co.save_figure(fig, folder, "cell3d_viscosity_ratio_phase_diagram.png")


def trend_figure(rows, folder, plt, co, name, panels):
    """One row of panels per quantity, one column per setting; lines per Ca (Skalak solid,
    neo-Hookean dashed), only runs that finished; tumbling runs drawn as open markers."""
    settings = settings_in(rows)
    cas = sorted({r["ca"] for r in rows})
    colours = dict(zip(cas, ["tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple"]))
    fig, axes = plt.subplots(len(panels), len(settings), figsize=(3.2 * len(settings), 2.5 * len(panels)),
                             squeeze=False, sharex=True)
    for i, (key, label, walls_only) in enumerate(panels):
        for j, (setting, height) in enumerate(settings):
            ax = axes[i][j]
            if walls_only and math.isinf(height):
                ax.set_axis_off()
                continue
            for law, members in law_rows(rows):
                for ca in cas:
                    line = sorted((r for r in members if r["height"] == height and r["ca"] == ca and
                                   r["regime"] != STOPPED), key=lambda r: r["lam"])
                    if not line:
                        continue
                    x = [r["lam"] for r in line]
                    y = [r[key] for r in line]
                    style = "-" if law == "Skalak" else "--"
                    ax.plot(x, y, style, color=colours[ca], label=f"{law}, Ca = {ca:g}")
                    for r in line:
                        ax.plot(r["lam"], r[key], MARKERS[r["regime"]][0], color=colours[ca],
                                mfc="none" if r["regime"] == TUMBLING else colours[ca], ms=4)
                    if key == "mean_theta":
                        ax.errorbar(x, y, yerr=[r["swing"] / 2 for r in line], fmt="none", ecolor=colours[ca],
                                    capsize=2, lw=0.8)
            co.log_axis_at(ax, [r["lam"] for r in rows])
            ax.set_title(setting, fontsize=8)
            if i == len(panels) - 1:
                ax.set_xlabel("viscosity ratio lambda")
            ax.set_ylabel(label)
    # The legend goes into the first panel drawn (the unbounded column has no slip panel).
    drawn = [ax for ax in axes.flat if ax.axison and ax.get_legend_handles_labels()[0]]
    if drawn:
        drawn[0].legend(fontsize=6)
    co.save_figure(fig, folder, name)


def histories_figure(rows, folder, plt, co):
    settings = settings_in(rows)
    cas = sorted({r["ca"] for r in rows})
    shown = [cas[0], cas[-1]] if len(cas) > 1 else cas
    fig, axes = plt.subplots(len(shown), len(settings), figsize=(3.2 * len(settings), 2.6 * len(shown)),
                             squeeze=False, sharex=True)
    lams = sorted({r["lam"] for r in rows})
    cmap = plt.get_cmap("viridis")
    for i, ca in enumerate(shown):
        for j, (setting, height) in enumerate(settings):
            ax = axes[i][j]
            for k, lam in enumerate(lams):
                for r in rows:
                    if (r["height"], r["ca"], r["lam"], r["law"], r["shape"]) == (height, ca, lam, "Skalak", "Spheroid"):
                        t, theta = r["history"]
                        ax.plot(t, unwrapped_inclination(theta), color=cmap(k / max(1, len(lams) - 1)),
                                label=f"lambda = {lam:g}")
            ax.set_title(f"Skalak, Ca = {ca:g}, {setting}")
            if i == len(shown) - 1:
                ax.set_xlabel("time (1/k)")
            if j == 0:
                ax.set_ylabel("inclination, unwrapped (deg)")
    axes[0][0].legend(fontsize=6)
    co.save_figure(fig, folder, "cell3d_viscosity_ratio_histories.png")


def check_trends(rows):
    """What every run set must show, whatever its mesh and length: a viscous interior deforms
    less (mean D12 at the smallest lambda above that at the largest, for each setting, law
    and Ca of the oblate cell), and a spherical capsule tank-treads. Prints one line; returns
    whether both hold."""
    groups = {}
    for r in rows:
        if r["shape"] != "Sphere" and r["regime"] != STOPPED:
            groups.setdefault((r["height"], r["law"], r["ca"]), []).append(r)
    pairs = [(min(g, key=lambda r: r["lam"]), max(g, key=lambda r: r["lam"]))
             for g in groups.values() if len({r["lam"] for r in g}) > 1]
    falls = sum(low["D12"] > high["D12"] for low, high in pairs)
    spheres = [r for r in rows if r["shape"] == "Sphere"]
    steady = sum(r["regime"] == TANK_TREADING for r in spheres)
    print(f"cell3d_viscosity_ratio: D12 falls from the smallest to the largest lambda in {falls} of "
          f"{len(pairs)} groups; {steady} of {len(spheres)} spherical capsules tank-tread")
    return bool(pairs) and falls == len(pairs) and steady == len(spheres)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", help="folder for the tables and PNG files")
    parser.add_argument("--transient", type=float, default=15.0,
                        help="judge the regime on the outputs after this time (default 15)")
    parser.add_argument("--swing-threshold", type=float, default=1.0,
                        help="peak-to-peak inclination (degrees) from which a run swings (default 1)")
    parser.add_argument("--self-test", action="store_true", help="check the criterion on synthetic signals")
    parser.add_argument("--check-trends", action="store_true",
                        help="exit 1 unless D12 falls with lambda and the spherical capsules tank-tread")
    parser.add_argument("runs", nargs="*", help="cell3d run directories or folders holding them")
    args = parser.parse_args(argv)
    if args.self_test:
        failures = self_test()
        for failure in failures:
            print(failure)
        print(f"cell3d_viscosity_ratio self-test: {len(failures)} failures")
        return 1 if failures else 0
    if not args.out or not args.runs:
        parser.error("give --out FIGDIR and at least one run folder (or --self-test)")
    import capsula_outputs as co
    runs = co.find_runs(args.runs, "cell3d")
    rows = [describe(r, args.transient, args.swing_threshold) for r in runs]
    if not rows:
        print("cell3d_viscosity_ratio: no cell3d runs found", file=sys.stderr)
        return 1
    rows.sort(key=lambda r: (-r["height"], r["shape"] != "Spheroid", r["law"] != "Skalak", r["ca"], r["lam"]))
    add_cost_ratios(rows)
    write_tables(rows, args.out, co, runs)
    plt = co.use_agg()
    phase_diagram(rows, args.out, plt, co)
    trend_figure(rows, args.out, plt, co, "cell3d_viscosity_ratio_inclination.png",
                 [("mean_theta", "mean inclination (deg)", False), ("D12", "mean D12", False)])
    trend_figure(rows, args.out, plt, co, "cell3d_viscosity_ratio_velocities.png",
                 [("u_slip", "slip velocity u_slip / k a", True), ("u_lift", "migration u_lift / k a", True),
                  ("omega_z", "membrane rotation omega_z / k", False)])
    histories_figure(rows, args.out, plt, co)
    trend_figure(rows, args.out, plt, co, "cell3d_viscosity_ratio_cost.png",
                 [("gmres", "GMRES iterations per solve", False),
                  ("cost_vs_lambda1", "time per velocity / lambda = 1", False),
                  ("seconds_per_step", "wall seconds per step", False)])
    counts = {regime: sum(r["regime"] == regime for r in rows) for regime in MARKERS}
    print("cell3d_viscosity_ratio: regimes: " + ", ".join(f"{k} {v}" for k, v in counts.items()))
    stopped = [r for r in rows if r["regime"] == STOPPED]
    for r in stopped:
        print(f"cell3d_viscosity_ratio: {r['directory']} stopped at t = {r['time']:g} ({r['status']})")
    trends = check_trends(rows)
    return 1 if args.check_trends and not trends else 0


if __name__ == "__main__":
    sys.exit(main())
