#!/usr/bin/python3
"""Checks utils/decks/random_suspension.py on the decks it writes: the number of cells, the gaps
between cells and above the wall, the box, a seed's reproducibility, and the message of a request
no box can hold. Usage: check_random_suspension.py ROOT BUILD WORKDIR"""
import itertools
import math
import os
import subprocess
import sys
import xml.etree.ElementTree as ET

root, build, work = sys.argv[1:4]
script = os.path.join(root, "utils", "decks", "random_suspension.py")
template = os.path.join(root, "input", "twocell3d", "demo.xml")
failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAILED:", what)


def generate(name, cells, seed, *extra):
    """Writes WORK/NAME/deck.xml from there (the deck's comment names the output as given)."""
    os.makedirs(os.path.join(work, name), exist_ok=True)
    output = os.path.join(work, name, "deck.xml")
    result = subprocess.run(["/usr/bin/python3", script, "-t", template, "-n", str(cells), "-s", str(seed),
                             "-g", "0.3", "-x", "12", "-z", "8", "-y", "5", "-l", "1", "--build", build,
                             "-o", "deck.xml", *extra], capture_output=True, text=True,
                            cwd=os.path.join(work, name))
    return result, output


def centres(path):
    cells = [c for c in ET.parse(path).getroot().iter("ParameterList") if c.get("name", "").startswith("Cell ")]
    out = []
    for cell in cells:
        values = {p.get("name"): p.get("value") for p in cell.iter("Parameter")}
        out.append(tuple(float(v) for v in values["Center"].strip("{}").split(",")))
        check(values.get("Mesh level") == "1", f"{path}: {cell.get('name')} has mesh level 1")
    return out


result, first = generate("seed3", 8, 3)
check(result.returncode == 0, f"the generator runs: {result.stderr.strip()}")
placed = centres(first)
check(len(placed) == 8, f"8 cells written ({len(placed)})")
for a, b in itertools.combinations(placed, 2):
    check(math.dist(a, b) >= 2.3, f"centres {a} and {b} at least 2 + gap apart")
for c in placed:
    check(c[1] >= 1.3, f"cell at {c} at least the gap above the wall")
    check(abs(c[0]) <= 5 and abs(c[2]) <= 3 and c[1] <= 4, f"cell at {c} inside the box")
again, second = generate("seed3-again", 8, 3)
with open(first, "rb") as f, open(second, "rb") as g:
    check(f.read() == g.read(), "the same seed writes the same deck")
other, third = generate("seed4", 8, 4)
check(centres(third) != placed, "another seed places the cells elsewhere")
crowded, _ = generate("never", 60, 3)
check(crowded.returncode != 0 and "cannot place cell" in crowded.stderr and "too small for 60 cells" in crowded.stderr,
      f"60 cells in the box are refused with a message: {crowded.stderr.strip()}")
check(not os.path.exists(os.path.join(work, "never", "deck.xml")), "a refused request writes no deck")
print(f"random_suspension checks: {len(failures)} failures")
sys.exit(1 if failures else 0)
