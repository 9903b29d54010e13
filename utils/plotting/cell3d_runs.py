"""What the 3D figure scripts share: a cell3d run's parameters read from its deck, the study
groups of thesis Chapter 5, and cuts and shadows of the quadratic surface mesh."""
import numpy as np

import capsula_outputs as co

SNAPSHOT_BASE = "snapshots"  # cell3d writes snapshots.xdmf (docs/cell3d.md)


class CellRun:
    """A single-cell cell3d run and the parameters the Chapter 5 figures are drawn over."""

    def __init__(self, run):
        self.run = run
        cell = "Cells/Cell 0/"
        self.ca = run.value("Flow/Capillary number")
        self.c = run.value(cell + "Area dilation C")
        self.law = run.value(cell + "Membrane law")
        self.prestress = run.value(cell + "Prestress")
        self.wall = run.value("Wall/Enabled")
        self.fixed = run.value(cell + "Fixed height")
        self.height0 = run.value(cell + "Center")[1]
        self.radius = run.value(cell + "Radius")
        self.threshold = run.value("Output/Wall shear stress/Threshold", 1.05)

    def metrics(self, cell=0):
        table = self.run.table()
        return co.select_rows(table, table["cell"] == cell)

    def steady_or_final(self, key):
        """The value at steady state if the run reached it, else the last output's."""
        cells = self.run.summary.get("cells") or []
        if cells:
            entry = cells[0]
            for part in ("steady", "final"):
                if isinstance(entry.get(part), dict) and key in entry[part]:
                    return entry[part][key]
        return self.metrics()[key][-1]

    def snapshots(self):
        return self.run.snapshots(SNAPSHOT_BASE)

    def last_snapshot(self):
        return self.run.last_snapshot(SNAPSHOT_BASE)

    def describe(self):
        return (f"Ca = {co.label_number(self.ca)}, C = {co.label_number(self.c)}, "
                f"prestress = {co.label_number(100 * self.prestress)}%")


def cell_runs(roots):
    return [CellRun(r) for r in co.find_runs(roots, "cell3d")
            if [k for k in r.value("Cells", {}) if k.startswith("Cell ")] == ["Cell 0"]]


# The two families of Chapter 5, as in panels a) and b) of its figures.
def family_a(runs):
    """C = 2.5, prestress 5%, over Ca."""
    return [r for r in runs if r.c == 2.5 and abs(r.prestress - 0.05) < 1e-12]


def family_b(runs):
    """Ca = 0.9, no prestress, over C."""
    return [r for r in runs if r.ca == 0.9 and r.prestress == 0.0]


def released(runs):
    return [r for r in runs if r.wall and not r.fixed]


def fixed_height(runs):
    return [r for r in runs if r.wall and r.fixed]


def unbounded(runs):
    return [r for r in runs if not r.wall]


# --- the surface mesh --------------------------------------------------------------------------

def flat_triangles(block):
    """The 6-node triangles (v0, v1, v2, m01, m12, m20) split into 4 flat ones each:
    an array (4 E, 3, 3) of corner coordinates."""
    p = block.positions
    c = block.connectivity
    v0, v1, v2, m01, m12, m20 = (p[c[:, k]] for k in range(6))
    pieces = [(v0, m01, m20), (m01, v1, m12), (m20, m12, v2), (m01, m12, m20)]
    return np.concatenate([np.stack(t, axis=1) for t in pieces], axis=0)


def plane_cut(triangles, axis, level):
    """Segments (n, 2, 3) where the flat triangles cross the plane x[axis] = level."""
    d = triangles[:, :, axis] - level
    segments = []
    for tri, dist in zip(triangles, d):
        points = []
        for i, j in ((0, 1), (1, 2), (2, 0)):
            if (dist[i] < 0.0) != (dist[j] < 0.0):
                s = dist[i] / (dist[i] - dist[j])
                points.append(tri[i] + s * (tri[j] - tri[i]))
        if len(points) == 2:
            segments.append(points)
    return np.array(segments).reshape(-1, 2, 3)


def centroid(block):
    """The area-weighted centre of the flat triangles (enough to centre a picture)."""
    tri = flat_triangles(block)
    area = 0.5 * np.linalg.norm(np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]), axis=1)
    return (tri.mean(axis=1) * area[:, None]).sum(axis=0) / area.sum()


def convex_outline(points):
    """The convex hull (closed, counter-clockwise) of 2D points, by Andrew's monotone chain:
    the outline of a convex cell's shadow."""
    pts = sorted(set(map(tuple, np.round(np.asarray(points, dtype=float), 12))))
    if len(pts) < 3:
        return np.array(pts)

    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    def chain(sequence):
        hull = []
        for p in sequence:
            while len(hull) >= 2 and cross(hull[-2], hull[-1], p) <= 0.0:
                hull.pop()
            hull.append(p)
        return hull

    lower, upper = chain(pts), chain(reversed(pts))
    hull = lower[:-1] + upper[:-1]
    return np.array(hull + hull[:1])


def rigid_sphere_slip(h_over_a):
    """Goldman, Cox & Brenner (1967) far field, thesis eq 2.10: U_slip / k a = 5/16 (a/h)^2."""
    return 5.0 / 16.0 / np.asarray(h_over_a) ** 2
