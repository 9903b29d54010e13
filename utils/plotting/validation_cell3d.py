#!/usr/bin/python3
"""Figures of the cell3d validation (docs/validation-cell3d.md) from the runs of
utils/studies/validate-cell3d.sh:

  validation_lac2005_D12.png      D12(t) of the prestressed Skalak capsule (Ca = 1.8,
                                  alpha = 2.5%) on each mesh level, with Lac &
                                  Barthes-Biesel (2005)'s 0.547 and the thesis's 0.538
  validation_small_deformation.png  D12(t)/Ca of the neo-Hookean capsule at Ca = 0.01 on
                                  each level, with the small-deformation limit 25/12
  validation_goldman.png          slip velocity and rotation rate of the nearly rigid
                                  capsule (Ca -> 0) against h/a, with the reflection
                                  solution of Goldman, Cox & Brenner (1967)

Usage: validation_cell3d.py RUNS FIGDIR   (RUNS: the runs folder of validate-cell3d.sh, with
lac2005-L<n>/, small-L<n>/, goldman-h<h>-Ca<ca>/). A figure whose runs are missing is
skipped with a note. Debian's /usr/bin/python3 with python3-matplotlib.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_metrics(run):
    path = os.path.join(run, "metrics.csv")
    if not os.path.exists(path):
        return None
    with open(path) as handle:
        rows = list(csv.DictReader(handle))
    return {key: [float(r[key]) for r in rows] for key in rows[0]} if rows else None


def levels(runs, prefix):
    found = []
    for level in range(0, 6):
        metrics = read_metrics(os.path.join(runs, "%s-L%d" % (prefix, level)))
        if metrics:
            found.append((level, metrics))
    return found


def lac2005(runs, figdir):
    found = levels(runs, "lac2005")
    if not found:
        return "no lac2005-L<n> runs"
    fig, (ax, zoom) = plt.subplots(1, 2, figsize=(10, 4))
    for level, m in found:
        label = "level %d (%d elements)" % (level, 20 * 4 ** level)
        ax.plot(m["time"], m["D12"], label=label)
        late = [k for k, t in enumerate(m["time"]) if t >= 2.0]
        zoom.plot([m["time"][k] for k in late], [m["D12"][k] for k in late], label=label)
    for axis in (ax, zoom):
        axis.axhline(0.547, color="k", linestyle="--", label="Lac & Barthes-Biesel (2005): 0.547")
        axis.axhline(0.538, color="grey", linestyle=":", label="thesis (level 3): 0.538")
        axis.set_xlabel("k t")
        axis.set_ylabel("D12")
    ax.set_ylim(0.0, 0.6)
    zoom.set_title("plateau (2% band: 0.536-0.558)")
    zoom.set_ylim(0.52, 0.56)
    ax.set_title("Skalak C = 1, prestress 2.5%, Ca = 1.8, unbounded")
    zoom.legend(loc="lower right", fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(figdir, "validation_lac2005_D12.png"), dpi=120)
    plt.close(fig)
    return None


def small_deformation(runs, figdir):
    found = levels(runs, "small")
    if not found:
        return "no small-L<n> runs"
    fig, ax = plt.subplots(figsize=(6, 4))
    for level, m in found:
        ax.plot(m["time"], [d / 0.01 for d in m["D12"]], label="level %d" % level)
    ax.axhline(25.0 / 12.0, color="k", linestyle="--", label="small deformation: 25/12 (Ca -> 0)")
    ax.set_xlabel("k t")
    ax.set_ylabel("D12 / Ca")
    ax.set_title("Neo-Hookean capsule, Ca = 0.01, unbounded shear")
    ax.set_ylim(0.0, 2.5)
    ax.legend(loc="lower right", fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(figdir, "validation_small_deformation.png"), dpi=120)
    plt.close(fig)
    return None


def goldman(runs, figdir):
    heights, slips, omegas = [], [], []
    for h in (1.1276, 1.5431, 2.3524, 3.7622, 10.0677):
        a = read_metrics(os.path.join(runs, "goldman-h%g-Ca0.01" % h))
        b = read_metrics(os.path.join(runs, "goldman-h%g-Ca0.005" % h))
        if not a or not b:
            continue
        # Linear extrapolation to Ca = 0 from Ca = 0.01 and 0.005 (as the script's table).
        heights.append(h)
        slips.append(2.0 * b["u_slip"][-1] - a["u_slip"][-1])
        omegas.append(2.0 * b["omega_z"][-1] - a["omega_z"][-1])
    if not heights:
        return "no goldman-h<h>-Ca<ca> runs"
    fine = [1.05 + 0.05 * k for k in range(200)]
    fig, (left, right) = plt.subplots(1, 2, figsize=(9, 3.8))
    left.plot(heights, slips, "o", label="capsule, Ca -> 0")
    left.plot(fine, [5.0 / 16.0 / h ** 2 for h in fine], "k--", label="5/16 (a/h)^2 (far field)")
    left.set_xscale("log")
    left.set_yscale("log")
    left.set_xlabel("h / a")
    left.set_ylabel("u_slip / k a")
    left.legend(fontsize=8)
    right.plot(heights, [-w for w in omegas], "o", label="capsule, Ca -> 0")
    right.plot(fine, [0.5 * (1.0 - 5.0 / 16.0 / h ** 3) for h in fine], "k--",
               label="(1 - 5/16 (a/h)^3) / 2 (far field)")
    right.set_xscale("log")
    right.set_xlabel("h / a")
    right.set_ylabel("-Omega_z / k")
    right.legend(fontsize=8)
    fig.suptitle("Nearly rigid capsule near the wall (Goldman, Cox & Brenner 1967)")
    fig.tight_layout()
    fig.savefig(os.path.join(figdir, "validation_goldman.png"), dpi=120)
    plt.close(fig)
    return None


def main(argv):
    if len(argv) == 2 and argv[1] in ("-h", "--help"):
        sys.stdout.write(__doc__)
        return 0
    if len(argv) != 3:
        sys.stderr.write(__doc__)
        return 2
    runs, figdir = argv[1], argv[2]
    os.makedirs(figdir, exist_ok=True)
    for draw in (lac2005, small_deformation, goldman):
        note = draw(runs, figdir)
        if note:
            print("%s: skipped (%s)" % (draw.__name__, note))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
