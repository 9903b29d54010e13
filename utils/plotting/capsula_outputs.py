"""Reading Capsula's run outputs: the shared part of the figure scripts.

A run directory (tether2d, cell3d) holds
  deck.xml      the validated deck (every key, defaults filled in)
  summary.json  final, maximum and steady values, timings
  metrics.csv   one row per output time (cell3d: one row per cell per output time)
  <base>.h5 + <base>.xdmf   snapshots: /mesh/<m>/<block>/connectivity (mesh versions) and
                            /snapshots/<k>/<block>/{positions,node_fields,cell_fields}
(docs/tether2d.md, docs/cell3d.md). Nothing here knows a study: the figure scripts group
runs by the parameters in their deck.xml.

Debian's /usr/bin/python3 with python3-numpy, python3-h5py, python3-matplotlib.
"""
import json
import os
import shlex
import sys
import tempfile
import xml.etree.ElementTree as ET

import h5py
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "utils", "docs"))
import generated_pages  # noqa: E402 (the first line of a table of runs: command and code versions)


class OutputError(Exception):
    """A run directory that lacks a file or holds one the reader does not understand."""


# --- decks ---------------------------------------------------------------------------------

def _parameter_value(element, path):
    kind = element.get("type")
    text = element.get("value")
    if kind == "double":
        return float(text)
    if kind == "int":
        return int(text)
    if kind == "bool":
        return text.strip().lower() == "true"
    if kind == "string":
        return text
    if kind.startswith("Array("):
        items = [p.strip() for p in text.strip().strip("{}").split(",") if p.strip()]
        return [float(p) if "double" in kind else int(p) if "int" in kind else p for p in items]
    raise OutputError(f"{path}: parameter '{element.get('name')}' has an unknown type '{kind}'")


def _parameter_list(element, path):
    values = {}
    for child in element:
        if child.tag == "Parameter":
            values[child.get("name")] = _parameter_value(child, path)
        elif child.tag == "ParameterList":
            values[child.get("name")] = _parameter_list(child, path)
    return values


def read_deck(path):
    """A Teuchos XML deck as nested dicts (sublists are dicts, values typed)."""
    try:
        root = ET.parse(path).getroot()
    except (OSError, ET.ParseError) as error:
        raise OutputError(f"cannot read deck '{path}': {error}") from error
    return _parameter_list(root, path)


def deck_value(deck, key, default=None):
    """deck_value(deck, 'Flow/Capillary number'): the value at a '/'-separated key path."""
    node = deck
    for part in key.split("/"):
        if not isinstance(node, dict) or part not in node:
            return default
        node = node[part]
    return node


# --- tables and summaries --------------------------------------------------------------------

def read_table(path):
    """A metrics table (header row, then numbers) as {column: numpy array}."""
    try:
        with open(path, encoding="utf-8") as f:
            header = f.readline().strip().split(",")
            data = np.genfromtxt(f, delimiter=",", dtype=float, ndmin=2)
    except OSError as error:
        raise OutputError(f"cannot read table '{path}': {error}") from error
    if data.size == 0:
        data = np.zeros((0, len(header)))
    if data.shape[1] != len(header):
        raise OutputError(f"table '{path}' has {data.shape[1]} columns under a header of {len(header)}")
    return {name: data[:, i] for i, name in enumerate(header)}


def select_rows(table, mask):
    return {name: values[mask] for name, values in table.items()}


def read_json(path):
    try:
        with open(path, encoding="utf-8") as f:
            return json.load(f)
    except (OSError, ValueError) as error:
        raise OutputError(f"cannot read '{path}': {error}") from error


# --- snapshots -------------------------------------------------------------------------------
#
# Snapshots are read through the run's XDMF file (<base>.xdmf), the documented entry point
# that ParaView opens: it lists every output time and, for each block (a cell surface, the
# 2D contour, the wall grid), the HDF5 datasets of its topology, positions and fields. The
# reader therefore does not depend on how the HDF5 files are laid out.

class Block:
    """One block of a snapshot: positions (nodes x dim), connectivity (elements x nodes per
    element; None for a structured grid), grid_shape (structured grids), node and cell fields."""

    def __init__(self, name, topology, positions, connectivity, grid_shape, node_fields, cell_fields):
        self.name = name
        self.topology = topology
        self.positions = positions
        self.connectivity = connectivity
        self.grid_shape = grid_shape
        self.node_fields = node_fields
        self.cell_fields = cell_fields


class Snapshot:
    """One output time of a series: time and {block name: Block}, read when first used."""

    def __init__(self, xdmf_path, time, grids):
        self.path = xdmf_path
        self.time = time
        self._grids = grids
        self._blocks = None

    @property
    def blocks(self):
        if self._blocks is None:
            self._blocks = {g.get("Name"): _read_block(self.path, g) for g in self._grids}
        return self._blocks


def _data_item(xdmf_path, item):
    """The array a DataItem names ('file.h5:/path', relative to the XDMF file) or holds."""
    dims = tuple(int(d) for d in item.get("Dimensions").split())
    text = item.text.strip()
    if item.get("Format", "XML") == "HDF":
        file_name, dataset = text.split(":", 1)
        path = os.path.join(os.path.dirname(xdmf_path), file_name)
        try:
            with h5py.File(path, "r") as f:
                data = np.asarray(f[dataset])
        except (OSError, KeyError) as error:
            raise OutputError(f"{xdmf_path}: cannot read {text}: {error}") from error
    else:
        data = np.array(text.split(), dtype=float)
    return data.reshape(dims)


def _read_block(xdmf_path, grid):
    topology = grid.find("Topology")
    kind = topology.get("TopologyType")
    connectivity = None
    grid_shape = None
    if kind.endswith("SMesh"):
        grid_shape = tuple(int(d) for d in topology.get("Dimensions").split())
    else:
        connectivity = _data_item(xdmf_path, topology.find("DataItem")).astype(int)
    positions = _data_item(xdmf_path, grid.find("Geometry").find("DataItem"))
    positions = positions.reshape(-1, positions.shape[-1])
    node_fields, cell_fields = {}, {}
    for attribute in grid.findall("Attribute"):
        target = cell_fields if attribute.get("Center") == "Cell" else node_fields
        target[attribute.get("Name")] = _data_item(xdmf_path, attribute.find("DataItem"))
    return Block(grid.get("Name"), kind, positions, connectivity, grid_shape, node_fields, cell_fields)


def read_series(xdmf_path):
    """The snapshots of a series in time order (their data is read when first used)."""
    try:
        root = ET.parse(xdmf_path).getroot()
    except (OSError, ET.ParseError) as error:
        raise OutputError(f"cannot read '{xdmf_path}': {error}") from error
    collection = root.find("Domain/Grid")
    snapshots = []
    if collection is None:
        return snapshots
    for step in collection.findall("Grid"):
        time = float(step.find("Time").get("Value"))
        grids = step.findall("Grid") if step.get("GridType") == "Collection" else [step]
        snapshots.append(Snapshot(xdmf_path, time, grids))
    return snapshots


# --- runs ------------------------------------------------------------------------------------

class Run:
    """A run directory, its deck and summary read at once, the rest on demand."""

    def __init__(self, directory):
        self.directory = directory
        self.deck = read_deck(os.path.join(directory, "deck.xml"))
        self.summary = read_json(os.path.join(directory, "summary.json"))
        self._tables = {}

    def value(self, key, default=None):
        return deck_value(self.deck, key, default)

    def table(self, name="metrics.csv"):
        if name not in self._tables:
            self._tables[name] = read_table(os.path.join(self.directory, name))
        return self._tables[name]

    def snapshots(self, base):
        """The snapshots of <base>.xdmf in time order ('snapshots' for cell3d, 'contour' or
        'preparation' for tether2d); [] when the run wrote none."""
        path = os.path.join(self.directory, base + ".xdmf")
        return read_series(path) if os.path.exists(path) else []

    def last_snapshot(self, base):
        series = self.snapshots(base)
        return series[-1] if series else None

    def __repr__(self):
        return f"Run({self.directory!r})"


def find_runs(roots, application=None):
    """Every run directory (one holding deck.xml and summary.json) under the given roots,
    optionally only those of one application ('tether2d', 'cell3d')."""
    if isinstance(roots, str):
        roots = [roots]
    runs = []
    for root in roots:
        for directory, _, files in sorted(os.walk(root)):
            if "deck.xml" in files and "summary.json" in files:
                run = Run(directory)
                if application is None or run.summary.get("application", application) == application:
                    runs.append(run)
    return runs


# --- figures ---------------------------------------------------------------------------------

def write_markdown_table(path, lines, runs):
    """Writes the Markdown table `lines` of `runs` to `path` (atomically) under the line that
    names the command that wrote it, the code it ran in and the code versions of the runs
    (docs/developer-guide.md, "Generated pages")."""
    args = [os.path.relpath(a, ROOT) if os.path.isabs(a) and a.startswith(ROOT + os.sep) else a for a in sys.argv[1:]]
    command = shlex.join(["/usr/bin/python3", os.path.relpath(os.path.abspath(sys.argv[0]), ROOT)] + args)
    header = (generated_pages.header_line(command, ROOT)[:-1] + "; the runs ran "
              + generated_pages.run_versions(run.summary for run in runs) + ".")
    with open(path + ".tmp", "w", encoding="utf-8") as f:
        f.write(header + "\n\n" + "\n".join(lines) + "\n")
    os.replace(path + ".tmp", path)


def use_agg():
    """Draw without a display (CI, ssh)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    plt.rcParams.update({
        "figure.dpi": 110, "savefig.dpi": 110, "font.size": 9, "axes.titlesize": 9,
        "legend.fontsize": 8, "legend.frameon": False, "axes.grid": False,
        "lines.linewidth": 1.3, "figure.constrained_layout.use": True,
    })
    return plt


def save_figure(fig, folder, name):
    """Writes folder/name (PNG) atomically (a temporary file, then a rename) and closes the
    figure; returns the path."""
    os.makedirs(folder, exist_ok=True)
    path = os.path.join(folder, name)
    handle, temporary = tempfile.mkstemp(prefix=".tmp-", suffix=".png", dir=folder)
    os.close(handle)
    try:
        fig.savefig(temporary, format="png", bbox_inches="tight")
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(temporary, 0o666 & ~umask)  # mkstemp makes it private; a figure is not
        os.replace(temporary, path)
    finally:
        if os.path.exists(temporary):
            os.remove(temporary)
    import matplotlib.pyplot as plt
    plt.close(fig)
    print(f"wrote {path}")
    return path


def label_number(value):
    """0.25 -> '0.25', 1.0 -> '1', 2.5 -> '2.5': parameter values in legends."""
    return f"{value:g}"


def log_axis_at(ax, values):
    """A logarithmic x axis with ticks labelled at the given parameter values (Ca)."""
    from matplotlib.ticker import FixedLocator, FuncFormatter, NullLocator
    ax.set_xscale("log")
    ax.xaxis.set_major_locator(FixedLocator(sorted(set(values))))
    ax.xaxis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
    ax.xaxis.set_minor_locator(NullLocator())
