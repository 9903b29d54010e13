#!/usr/bin/python3
"""Writes a twocell3d deck of N cells placed at random above the wall.

  random_suspension.py -t DECK -n N -s SEED -o FILE [-x X] [-z Z] [-y H] [-g G] [-l LEVEL]
                       [-S Sphere|Spheroid|Ellipsoid|Biconcave] [-T TRIES]
                       [-e "List/Key=value"]... [--build DIR]

The cells fill the box -X/2 < x < X/2, 0 < y < H, -Z/2 < z < Z/2 above the wall y = 0 (lengths
in cell radii a): every cell lies inside it, its surface at least G above the wall and at least
G from every other cell's. The cells are drawn one by one, uniformly over the positions left,
by rejection sampling: a cell that finds no place in T draws stops the writer with a message
(the box is too small for N cells at that gap). Shapes other than spheres are placed by their
bounding sphere (the largest semi-axis, or the disc radius), so their gaps are at least G.

Everything but the cells comes from DECK (flow, wall, time integration, outputs, ...); every
cell takes the keys of DECK's 'Cells/Cell 0' with its own 'Center', and --level and --shape
when given; --set applies last. The same arguments and seed give the same deck. Debian's
/usr/bin/python3, standard library only.
"""
import argparse
import math
import os
import random
import shlex
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import deck_writer  # noqa: E402

SCRIPT = "utils/decks/random_suspension.py"
APP = "twocell3d"


class Box:
    def __init__(self, x, z, height):
        self.x, self.z, self.height = x, z, height

    def describe(self):
        return f"{self.x:g} x {self.height:g} x {self.z:g} (x, y, z)"


def number(x):
    """A coordinate as the deck holds it: four decimals, no negative zero."""
    return float(f"{x:.4f}") + 0.0


def place(count, radius, gap, box, seed, tries):
    """Centres of COUNT cells of bounding radius RADIUS in BOX, surfaces G apart and G above the wall."""
    low = (-box.x / 2 + radius, radius + gap, -box.z / 2 + radius)
    high = (box.x / 2 - radius, box.height - radius, box.z / 2 - radius)
    if any(h < l for l, h in zip(low, high)):
        raise deck_writer.DeckError(
            f"the box {box.describe()} cannot hold one cell of radius {radius:g} {gap:g} above the wall: "
            f"make it at least {2 * radius:g} wide and {2 * radius + gap:g} high")
    rng = random.Random(seed)
    reach = 2 * radius + gap
    centres = []
    for k in range(count):
        for _ in range(tries):
            c = tuple(number(rng.uniform(l, h)) for l, h in zip(low, high))
            if all(math.dist(c, o) >= reach for o in centres):
                centres.append(c)
                break
        else:
            fraction = count * 4 / 3 * math.pi * radius ** 3 / (box.x * box.z * box.height)
            raise deck_writer.DeckError(
                f"cannot place cell {k} of {count} after {tries} tries: the box {box.describe()} is too small "
                f"for {count} cells of radius {radius:g} with surface gaps of {gap:g} (volume fraction "
                f"{fraction:.2f}); enlarge the box (--box-x, --box-z, --height), lower --cells or --gap")
    return centres


def template_cell(deck):
    """The template's 'Cells/Cell 0' entries, and the deck with every 'Cell k' removed."""
    cells = deck.items.get("Cells")
    if not cells or cells[0] != "list" or "Cell 0" not in cells[1]:
        raise deck_writer.DeckError("the template has no 'Cells/Cell 0' to copy the cells' keys from")
    entries = cells[1]
    cell = entries["Cell 0"][1]
    for name in [n for n in entries if n.startswith("Cell ")]:
        del entries[name]
    return cell


def cell_value(cell, key, default):
    entry = cell.get(key)
    return entry[2] if entry and entry[0] == "value" else default


def bounding_radius(cell, shape):
    """The radius of a sphere about the centre that holds the cell (before any rotation)."""
    if shape in ("Spheroid", "Ellipsoid"):
        axes = cell_value(cell, "Semi-axes", "{1, 1, 1}").strip("{} ").split(",")
        return max(float(a) for a in axes)
    return float(cell_value(cell, "Radius", "1"))


def flatten(items, prefix=""):
    """The deck's assignments in order, as (path, text)."""
    out = []
    for name, entry in items.items():
        if entry[0] == "list":
            out += flatten(entry[1], prefix + name + "/")
        else:
            out.append((prefix + name, entry[2]))
    return out


def assignments(template, *, cells, seed, gap, box, level=None, shape=None, tries=10000, overrides=()):
    """The deck as (path, text) in order: the template without its cells, then the CELLS placed
    ones, then OVERRIDES ("List/Key=value")."""
    deck = deck_writer.Deck.read(None, template)
    cell = template_cell(deck)
    shape = shape or cell_value(cell, "Shape", "Sphere")
    radius = bounding_radius(cell, shape)
    for key in ("Cells/Minimum gap", "Wall/Minimum gap"):
        parts = key.split("/")
        held = deck.items.get(parts[0], ("list", {}))[1].get(parts[1])
        if held and float(held[2]) >= gap:
            raise deck_writer.DeckError(f"gap {gap:g} is not above the template's '{key}' = {held[2]}: "
                                        "the app would reject the cells placed")
    result = flatten(deck.items)
    for k, centre in enumerate(place(cells, radius, gap, box, seed, tries)):
        path = f"Cells/Cell {k}/"
        values = dict(flatten(cell))
        values["Shape"] = shape
        values["Center"] = deck_writer.text_of(list(centre))
        if level is not None:
            values["Mesh level"] = str(level)
        result += [(path + key, text) for key, text in values.items()]
    for override in overrides:
        key, eq, value = override.partition("=")
        if not eq or not key.strip():
            raise deck_writer.DeckError(f"'{override}': expected \"List/Sub/Key=value\"")
        result.append((key.strip(), value))
    return result


def command_line(template, cells, seed, gap, box, level, shape, tries, overrides, output):
    """The command that writes the deck again, in short options (an XML comment cannot hold "--")."""
    words = [SCRIPT, "-t", template, "-n", str(cells), "-s", str(seed), "-g", f"{gap:g}",
             "-x", f"{box.x:g}", "-z", f"{box.z:g}", "-y", f"{box.height:g}"]
    words += ["-l", str(level)] if level is not None else []
    words += ["-S", shape] if shape else []
    words += ["-T", str(tries)] if tries != 10000 else []
    for override in overrides:
        words += ["-e", override]
    return shlex.join(words + ["-o", output])


def describe(cells, seed, gap, box, command):
    """The deck's comment: what it holds and the command that writes it."""
    return (f"{cells} cells placed at random (seed {seed}) in a {box.describe()} box above the wall,\n"
            f"     surfaces at least {gap:g} a apart and above the wall. Written by\n     {command}")


def main(argv=None):
    parser = argparse.ArgumentParser(
        prog=SCRIPT, description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog="\n".join(__doc__.split("\n")[7:]))
    parser.add_argument("-t", "--template", required=True, metavar="DECK", help="twocell3d deck with a 'Cells/Cell 0'")
    parser.add_argument("-n", "--cells", required=True, type=int, metavar="N")
    parser.add_argument("-s", "--seed", required=True, type=int, metavar="S")
    parser.add_argument("-g", "--gap", type=float, default=0.25, help="smallest surface gap, cell-cell and cell-wall "
                        "(default 0.25)")
    parser.add_argument("-x", "--box-x", type=float, default=16.0, help="box length along the flow (default 16)")
    parser.add_argument("-z", "--box-z", type=float, default=10.0, help="box width across the flow (default 10)")
    parser.add_argument("-y", "--height", type=float, default=5.0, help="box height above the wall (default 5)")
    parser.add_argument("-l", "--level", type=int, help="mesh level of every cell (default: the template's)")
    parser.add_argument("-S", "--shape", choices=["Sphere", "Spheroid", "Ellipsoid", "Biconcave"],
                        help="shape of every cell (default: the template's)")
    parser.add_argument("-T", "--tries", type=int, default=10000, help="draws per cell before giving up (default 10000)")
    parser.add_argument("-e", "--set", action="append", default=[], metavar="List/Key=value", dest="assignments")
    parser.add_argument("--build", default=os.path.join(deck_writer.ROOT, "build"), help="build directory")
    parser.add_argument("-o", "--output", required=True, metavar="FILE")
    args = parser.parse_args(argv)
    try:
        if args.cells < 1:
            raise deck_writer.DeckError(f"--cells {args.cells}: give at least 1 cell")
        if args.gap <= 0:
            raise deck_writer.DeckError(f"--gap {args.gap:g}: give a gap > 0")
        box = Box(args.box_x, args.box_z, args.height)
        schema = deck_writer.Schema.from_build(APP, args.build)
        deck = deck_writer.Deck(schema)
        for path, text in assignments(args.template, cells=args.cells, seed=args.seed, gap=args.gap, box=box,
                                      level=args.level, shape=args.shape, tries=args.tries,
                                      overrides=args.assignments):
            deck.set(path, text)
        command = command_line(args.template, args.cells, args.seed, args.gap, box, args.level, args.shape,
                               args.tries, args.assignments, args.output)
        deck.write(args.output, deck_writer.comment_safe(describe(args.cells, args.seed, args.gap, box, command)))
        print(f"random_suspension: {args.cells} cells in {args.output}")
    except deck_writer.DeckError as e:
        sys.exit(f"random_suspension: error: {e}")

if __name__ == "__main__":
    main()
