#!/usr/bin/python3
"""A capsule under a pulsatile shear rate k(t) = 1 + A sin(omega t), omega = 2 pi / T
(Flow/Shear rate/Form = Pulsatile, docs/cell3d-pulsatile-results.md): amplitude and phase lag
of D12(t) and u_slip(t) relative to k(t), and the mean migration against the steady run of the
same mean shear.

Every cell3d run found under the folders given is read (metrics.csv, deck.xml). For each
pulsatile run, D12 and u_slip over the last whole periods after --transient are fitted by
least squares with

    s(t) = m + c (t - t_mid) + a sin(omega t) + b cos(omega t) = m + ... + R sin(omega t - phi)

(the linear term c takes up the slow drift of a migrating cell; --no-trend drops it).
R = sqrt(a^2 + b^2) is the amplitude and phi = atan2(-b, a) the phase lag behind k(t), in
(-180, 180] degrees: 0 for a response in phase with k, positive when it lags. The relative
amplitude is (R / m) / A: 1 for a response proportional to k. The steady run (Form = Steady,
same capillary number and start height) gives the membrane relaxation time tau, the time its
D12 takes to reach 1 - 1/e of its first maximum, and the mean rise velocity over the same
window, (y_c(t2) - y_c(t1)) / (t2 - t1), that each pulsatile run's is compared with. A
Kelvin-Voigt membrane (one relaxation time tau) would lag by atan(omega tau) with the
relative amplitude s / sqrt(1 + (omega tau)^2), s the quasi-static d ln D12 / d ln k (1 for
a response proportional to k); the table gives tan(phi) / omega (that element's tau) and
(R / m) / A / cos(phi) (its s) for each run, which agree between runs if one element fits.

Writes into --out
  cell3d_pulsatile_table.md, cell3d_pulsatile_table.csv   one row per run
  cell3d_pulsatile_response.png   the last periods of each pulsatile run: (k - 1)/A and the
                                  normalised D12 and u_slip, (s - m - c(t - t_mid)) / R
  cell3d_pulsatile_lags.png       lags and relative amplitudes against omega tau with the
                                  Kelvin-Voigt curves; y_c(t) of every run

Usage: cell3d_pulsatile.py --out FIGDIR [--transient T] RUNDIR_OR_PARENT...
       cell3d_pulsatile.py --self-test      (the fit on synthetic signals of known phase)
"""
import argparse
import math
import os
import sys

import numpy as np


class FitError(Exception):
    """Too little of a signal to fit (less than one whole period after the transient)."""


# --- the fit ---------------------------------------------------------------------------------

def fit_harmonic(t, s, omega, trend=True):
    """Least-squares fit of s(t) = m + c (t - t_mid) + a sin(omega t) + b cos(omega t).

    Returns a dict: mean m, trend c (0 without), a, b, amplitude R = hypot(a, b), lag
    phi = atan2(-b, a) in radians (s = m + R sin(omega t - phi)), rms of the residual."""
    t = np.asarray(t, dtype=float)
    s = np.asarray(s, dtype=float)
    keep = np.isfinite(t) & np.isfinite(s)
    t, s = t[keep], s[keep]
    columns = [np.ones_like(t)]
    t_mid = 0.5 * (t.min() + t.max()) if t.size else 0.0
    if trend:
        columns.append(t - t_mid)
    columns += [np.sin(omega * t), np.cos(omega * t)]
    matrix = np.column_stack(columns)
    if t.size < matrix.shape[1] + 1:
        raise FitError(f"{t.size} samples cannot fit {matrix.shape[1]} coefficients")
    coefficients, *_ = np.linalg.lstsq(matrix, s, rcond=None)
    a, b = coefficients[-2], coefficients[-1]
    residual = s - matrix @ coefficients
    return {"mean": coefficients[0], "trend": coefficients[1] if trend else 0.0, "a": a, "b": b,
            "amplitude": math.hypot(a, b), "lag": math.atan2(-b, a), "t_mid": t_mid,
            "rms": float(np.sqrt(np.mean(residual ** 2)))}


def last_whole_periods(t, period, transient):
    """(t1, t2, n): the window of the last n whole periods ending at the last sample and
    starting at or after `transient`; FitError if not even one fits."""
    t_end = float(np.max(t))
    n = int(math.floor((t_end - transient) / period + 1e-9))
    if n < 1:
        raise FitError(f"the run ends at t = {t_end:g}: no whole period of T = {period:g} after t = {transient:g}")
    return t_end - n * period, t_end, n


def window_mask(t, t1, t2):
    """The samples of (t1, t2]: the first phase of the window once, not twice."""
    eps = 1e-9 * max(1.0, abs(t2))
    return (t > t1 + eps) & (t <= t2 + eps)


def relaxation_time(t, d12, horizon=5.0):
    """The time D12 takes from 0 to 1 - 1/e of its largest value up to `horizon` (linear
    interpolation between outputs); NaN if it never gets there."""
    t = np.asarray(t, dtype=float)
    d12 = np.asarray(d12, dtype=float)
    early = t <= horizon
    if not np.any(early):
        return float("nan")
    target = (1.0 - math.exp(-1.0)) * np.max(d12[early])
    above = np.nonzero(d12 >= target)[0]
    if above.size == 0:
        return float("nan")
    i = above[0]
    if i == 0:
        return float(t[0])
    return float(np.interp(target, [d12[i - 1], d12[i]], [t[i - 1], t[i]]))


def kelvin_voigt(omega_tau):
    """Lag (radians) and relative amplitude of a Kelvin-Voigt element forced at omega."""
    return math.atan(omega_tau), 1.0 / math.sqrt(1.0 + omega_tau ** 2)


# --- runs --------------------------------------------------------------------------------------

def describe(run):
    form = run.value("Flow/Shear rate/Form", "Steady")
    return {"run": run, "name": os.path.basename(os.path.normpath(run.directory)), "form": form,
            "ca": run.value("Flow/Capillary number"), "h0": run.value("Cells/Cell 0/Center")[1],
            "amplitude": run.value("Flow/Shear rate/Amplitude", 0.0) if form == "Pulsatile" else 0.0,
            "period": run.value("Flow/Shear rate/Period") if form == "Pulsatile" else float("nan")}


def rise_velocity(table, t1, t2):
    """Mean dy_c/dt over [t1, t2]: the change of the centroid height over the time."""
    y1, y2 = np.interp([t1, t2], table["time"], table["y_c"])
    return (y2 - y1) / (t2 - t1)


def analyse(runs, transient, trend=True):
    """One row per pulsatile run (dict), and the steady runs' rows."""
    steady = [r for r in runs if r["form"] == "Steady"]
    rows = []
    for r in runs:
        if r["form"] != "Pulsatile":
            continue
        m = r["run"].table()
        omega = 2.0 * math.pi / r["period"]
        t1, t2, n = last_whole_periods(m["time"], r["period"], transient)
        w = window_mask(m["time"], t1, t2)
        d12 = fit_harmonic(m["time"][w], m["D12"][w], omega, trend)
        slip = fit_harmonic(m["time"][w], m["u_slip"][w], omega, trend)
        row = dict(r, omega=omega, t1=t1, t2=t2, periods=n, d12=d12, slip=slip,
                   rise=rise_velocity(m, t1, t2), tau=float("nan"), steady_rise=float("nan"),
                   steady_d12=float("nan"))
        ref = [s for s in steady if s["ca"] == r["ca"] and s["h0"] == r["h0"]]
        if ref:
            sm = ref[0]["run"].table()
            row["tau"] = relaxation_time(sm["time"], sm["D12"])
            if sm["time"].max() >= t2 - 1e-9:
                row["steady_rise"] = rise_velocity(sm, t1, t2)
                row["steady_d12"] = float(np.mean(sm["D12"][window_mask(sm["time"], t1, t2)]))
        rows.append(row)
    return sorted(rows, key=lambda x: x["period"]), steady


def degrees(x):
    return math.degrees(x)


def table_lines(rows, steady):
    header = ["run", "T", "omega", "omega tau", "window", "D12 mean", "D12 amp", "D12 rel amp",
              "D12 lag deg", "KV lag deg", "KV rel amp", "D12 tau from lag", "D12 rel amp / cos(lag)", "u_slip mean", "u_slip rel amp", "u_slip lag deg",
              "rise", "steady rise", "rise / steady", "steady D12 mean"]
    body = []
    for r in rows:
        wt = r["omega"] * r["tau"]
        kv_lag, kv_amp = kelvin_voigt(wt) if math.isfinite(wt) else (float("nan"), float("nan"))
        d, s = r["d12"], r["slip"]
        ratio = r["rise"] / r["steady_rise"] if r["steady_rise"] else float("nan")
        body.append([r["name"], f"{r['period']:g}", f"{r['omega']:.4g}", f"{wt:.3g}",
                     f"{r['t1']:g}-{r['t2']:g} ({r['periods']} T)",
                     f"{d['mean']:.4f}", f"{d['amplitude']:.4f}", f"{d['amplitude'] / d['mean'] / r['amplitude']:.3f}",
                     f"{degrees(d['lag']):.1f}", f"{degrees(kv_lag):.1f}", f"{kv_amp:.3f}",
                     f"{math.tan(d['lag']) / r['omega']:.3f}",
                     f"{d['amplitude'] / d['mean'] / r['amplitude'] / math.cos(d['lag']):.3f}",
                     f"{s['mean']:.4f}", f"{s['amplitude'] / s['mean'] / r['amplitude']:.3f}",
                     f"{degrees(s['lag']):.1f}", f"{r['rise']:.5f}", f"{r['steady_rise']:.5f}",
                     f"{ratio:.3f}", f"{r['steady_d12']:.4f}"])
    return header, body


def write_tables(rows, steady, out, co, runs):
    header, body = table_lines(rows, steady)
    os.makedirs(out, exist_ok=True)
    md = os.path.join(out, "cell3d_pulsatile_table.md")
    co.write_markdown_table(md, ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
                            + ["| " + " | ".join(line) + " |" for line in body], runs)
    csv = os.path.join(out, "cell3d_pulsatile_table.csv")
    with open(csv + ".tmp", "w", encoding="utf-8") as f:
        f.write(",".join(h.replace(" ", "_") for h in header) + "\n")
        for line in body:
            f.write(",".join(x.replace(",", ";") for x in line) + "\n")
    os.replace(csv + ".tmp", csv)
    print(f"wrote {md}")
    print(f"wrote {csv}")
    with open(md, encoding="utf-8") as f:
        sys.stdout.write(f.read())


# --- figures -----------------------------------------------------------------------------------

def normalised(fit, t, s):
    return (s - fit["mean"] - fit["trend"] * (t - fit["t_mid"])) / fit["amplitude"]


def response_figure(rows, out, plt, co):
    fig, axes = plt.subplots(len(rows), 1, figsize=(7.0, 2.4 * len(rows)), squeeze=False)
    for ax, r in zip(axes[:, 0], rows):
        m = r["run"].table()
        shown = min(r["periods"], 2)
        w = window_mask(m["time"], r["t2"] - shown * r["period"], r["t2"])
        w[np.nonzero(w)[0][0] - 1] = True  # the window's first phase too, for a closed curve
        t = m["time"][w]
        phase = (t - r["t2"] + shown * r["period"]) / r["period"]
        ax.plot(phase, np.sin(r["omega"] * t), color="0.4", ls="--", label="(k - 1) / A")
        ax.plot(phase, normalised(r["d12"], t, m["D12"][w]), color="C0", marker=".", ms=3,
                label=f"D12: lag {degrees(r['d12']['lag']):.0f} deg")
        ax.plot(phase, normalised(r["slip"], t, m["u_slip"][w]), color="C3", marker=".", ms=3,
                label=f"u_slip: lag {degrees(r['slip']['lag']):.0f} deg")
        ax.set_xlabel(f"t / T after t = {r['t2'] - shown * r['period']:g}")
        ax.set_ylabel("normalised")
        ax.set_title(f"T = {r['period']:g} (omega tau = {r['omega'] * r['tau']:.2g}), A = {r['amplitude']:g}")
        ax.legend(loc="upper right", ncol=3)
        ax.set_ylim(-1.6, 1.9)
    return co.save_figure(fig, out, "cell3d_pulsatile_response.png")


def lags_figure(rows, steady, out, plt, co):
    fig, axes = plt.subplots(1, 3, figsize=(11.0, 3.4))
    wt = np.array([r["omega"] * r["tau"] for r in rows])
    finite = wt[np.isfinite(wt)]
    if finite.size:
        x = np.geomspace(max(finite.min() / 5, 1e-2), finite.max() * 5, 100)
        axes[0].plot(x, np.degrees(np.arctan(x)), color="0.5", ls="--", label="Kelvin-Voigt atan(omega tau)")
        axes[1].plot(x, 1 / np.sqrt(1 + x ** 2), color="0.5", ls="--", label="Kelvin-Voigt 1/sqrt(1 + (omega tau)^2)")
        scale = np.mean([r["d12"]["amplitude"] / r["d12"]["mean"] / r["amplitude"] / math.cos(r["d12"]["lag"])
                         for r in rows])
        axes[1].plot(x, scale / np.sqrt(1 + x ** 2), color="C0", ls=":",
                     label=f"the same times s = {scale:.2f} (D12's mean rel amp / cos(lag))")
    x_of = wt if finite.size == wt.size else np.array([r["omega"] for r in rows])
    xlabel = "omega tau" if finite.size == wt.size else "omega"
    axes[0].plot(x_of, [degrees(r["d12"]["lag"]) for r in rows], "o", color="C0", label="D12")
    axes[0].plot(x_of, [degrees(r["slip"]["lag"]) for r in rows], "s", color="C3", label="u_slip")
    axes[1].plot(x_of, [r["d12"]["amplitude"] / r["d12"]["mean"] / r["amplitude"] for r in rows], "o",
                 color="C0", label="D12")
    axes[1].plot(x_of, [r["slip"]["amplitude"] / r["slip"]["mean"] / r["amplitude"] for r in rows], "s",
                 color="C3", label="u_slip")
    for ax, label in zip(axes[:2], ["phase lag behind k(t) (deg)", "relative amplitude (R / mean) / A"]):
        ax.set_xscale("log")
        ax.set_xlabel(xlabel)
        ax.set_ylabel(label)
    axes[0].legend(loc="upper left")
    axes[1].legend(loc="lower left")
    axes[0].axhline(0, color="0.8", lw=0.8)
    for s in steady:
        m = s["run"].table()
        axes[2].plot(m["time"], m["y_c"], color="k", label="steady")
    for r, colour in zip(rows, ["C1", "C2", "C4", "C5"]):
        m = r["run"].table()
        axes[2].plot(m["time"], m["y_c"], color=colour, label=f"T = {r['period']:g}")
    axes[2].set_xlabel("t (1 / k_mean)")
    axes[2].set_ylabel("centroid height y_c / a")
    axes[2].legend()
    return co.save_figure(fig, out, "cell3d_pulsatile_lags.png")


# --- self-test -----------------------------------------------------------------------------------

def self_test():
    """The fit against signals of known mean, amplitude and phase; returns the failures."""
    failures = []

    def check(name, value, expected, tolerance):
        ok = abs(value - expected) <= tolerance
        print(f"  {'ok  ' if ok else 'FAIL'} {name}: {value:.6g} (expected {expected:.6g} +- {tolerance:g})")
        if not ok:
            failures.append(name)

    rng = np.random.default_rng(1)
    # A sampled sinusoid with a drift and noise: 20 samples per period, 3 periods, T = 5.
    for lag_deg in (-150.0, -30.0, 0.0, 45.0, 100.0, 179.0):
        period, mean, amp, drift = 5.0, 0.3, 0.05, -0.002
        omega = 2 * math.pi / period
        t = np.arange(1, 61) * period / 20 + 5.0
        s = mean + drift * (t - 10.0) + amp * np.sin(omega * t - math.radians(lag_deg))
        s = s + 1e-4 * rng.standard_normal(t.size)
        fit = fit_harmonic(t, s, omega)
        # Noise of 1e-4 on 60 samples moves the amplitude by ~2e-5 and the phase by ~0.05 deg.
        check(f"lag {lag_deg:g} deg: lag", degrees(fit["lag"]), lag_deg, 0.2)
        check(f"lag {lag_deg:g} deg: amplitude", fit["amplitude"], amp, 1e-4)
        check(f"lag {lag_deg:g} deg: mean", fit["mean"] + fit["trend"] * (10.0 - fit["t_mid"]), mean, 1e-4)
    # Without the trend term a drift leaks into the phase: the option matters.
    t = np.arange(1, 41) * 0.5 / 20
    s = 1 + 0.05 * np.sin(4 * math.pi * t) + 0.2 * t
    fit = fit_harmonic(t, s, 4 * math.pi, trend=False)
    biased = abs(degrees(fit["lag"])) > 5.0
    print(f"  {'ok  ' if biased else 'FAIL'} a drift without the trend term biases the lag: {degrees(fit['lag']):.2f} deg")
    if not biased:
        failures.append("trend")
    check("the same drift with the trend term: lag", degrees(fit_harmonic(t, s, 4 * math.pi)["lag"]), 0.0, 1e-6)
    # A Kelvin-Voigt element tau x' + x = 1 + A sin(omega t), integrated past its transient:
    # the fitted lag and relative amplitude are the closed forms.
    for tau, period in ((0.6, 0.5), (0.6, 5.0)):
        omega = 2 * math.pi / period
        dt = period / 2000
        t = np.arange(0, 20 * tau + 4 * period, dt)
        x = np.empty_like(t)
        x[0] = 0.0
        for i in range(1, t.size):  # Crank-Nicolson
            f0 = 1 + 0.5 * math.sin(omega * t[i - 1])
            f1 = 1 + 0.5 * math.sin(omega * t[i])
            x[i] = (x[i - 1] * (tau / dt - 0.5) + 0.5 * (f0 + f1)) / (tau / dt + 0.5)
        t1, t2, n = last_whole_periods(t, period, 20 * tau)
        w = window_mask(t, t1, t2)
        fit = fit_harmonic(t[w], x[w], omega)
        lag, rel = kelvin_voigt(omega * tau)
        # Crank-Nicolson with 2000 steps a period: phase error ~ (omega dt)^2 / 12, far below 0.1 deg.
        check(f"Kelvin-Voigt tau = {tau:g}, T = {period:g}: lag", degrees(fit["lag"]), degrees(lag), 0.1)
        check(f"Kelvin-Voigt tau = {tau:g}, T = {period:g}: relative amplitude",
              fit["amplitude"] / fit["mean"] / 0.5, rel, 1e-3)
    # The relaxation time of a step response x = 1 - exp(-t / tau) sampled every 0.1.
    t = np.arange(0, 5.01, 0.1)
    check("relaxation time of 1 - exp(-t / 0.7)", relaxation_time(t, 1 - np.exp(-t / 0.7)), 0.7, 0.01)
    # Too short a run is refused.
    try:
        last_whole_periods(np.linspace(0, 1, 11), 5.0, 0.0)
        print("  FAIL a run shorter than one period is refused")
        failures.append("short")
    except FitError:
        print("  ok   a run shorter than one period is refused")
    return failures


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", help="folder for the tables and PNG files")
    parser.add_argument("--transient", type=float, default=5.0,
                        help="fit only the whole periods after this time (default 5)")
    parser.add_argument("--no-trend", action="store_true", help="fit without the linear drift term")
    parser.add_argument("--self-test", action="store_true", help="check the fit on synthetic signals and exit")
    parser.add_argument("runs", nargs="*", help="cell3d run directories or folders holding them")
    args = parser.parse_args(argv)
    if args.self_test:
        failures = self_test()
        print(f"cell3d_pulsatile self-test: {len(failures)} failures")
        return 1 if failures else 0
    if not args.out or not args.runs:
        parser.error("give --out FIGDIR and at least one run folder (or --self-test)")
    import capsula_outputs as co
    runs = [describe(r) for r in co.find_runs(args.runs, "cell3d")]
    try:
        rows, steady = analyse(runs, args.transient, trend=not args.no_trend)
    except FitError as error:
        print(f"cell3d_pulsatile: {error}", file=sys.stderr)
        return 1
    if not rows:
        print("cell3d_pulsatile: no pulsatile cell3d runs found", file=sys.stderr)
        return 1
    if not steady:
        print("cell3d_pulsatile: no steady run of the same Ca and height: no tau, no migration reference",
              file=sys.stderr)
    write_tables(rows, steady, args.out, co, [r["run"] for r in runs])
    plt = co.use_agg()
    response_figure(rows, args.out, plt, co)
    lags_figure(rows, steady, args.out, plt, co)
    return 0 if steady else 1


if __name__ == "__main__":
    sys.exit(main())
