"""Reads a run's snapshots.xdmf with both of ParaView's XDMF readers, the legacy XDMFReader
(Xdmf2: the reader the ParaView docs send users to offers it, and it is `XDMFReader` in
paraview.simple) and Xdmf3ReaderT (the XDMF3 reader that keeps the grids as named blocks),
at every snapshot time, and checks that each reader gives
every grid of the file with every attribute the file declares: as many tuples as the grid has
points (Center="Node") or cells (Center="Cell"), with the values of the HDF5 dataset the
attribute names (to round-off: the reader converts nothing, so 0 differences are expected;
1e-12 relative leaves room for a float printed and parsed).

Usage: pvpython check_xdmf_readers.py RUN_DIR/snapshots.xdmf
Prints one line per reader and a summary "xdmf readers: N arrays checked, M problems"; exit 1
on a problem. Run with Debian's paraview (pvpython); h5py from python3-h5py.
"""
import os
import re
import sys
import xml.etree.ElementTree as ElementTree

import h5py
import numpy as np
from paraview import servermanager, simple
from vtkmodules.numpy_interface import dataset_adapter
from vtkmodules.vtkCommonDataModel import vtkCompositeDataSet, vtkDataObjectTreeIterator

TOLERANCE = 1e-12


def declared_grids(path):
    """{time: {grid name: [(attribute, center, "file.h5:/dataset")]}} as the XDMF declares them."""
    root = ElementTree.parse(path).getroot()
    steps = {}
    for step in root.iter("Grid"):
        if step.get("CollectionType") != "Spatial":
            continue
        time = float(step.find("Time").get("Value"))
        grids = {}
        for grid in step.findall("Grid"):
            grids[grid.get("Name")] = [(a.get("Name"), a.get("Center"), a.find("DataItem").text.strip())
                                       for a in grid.findall("Attribute")]
        steps[time] = grids
    return steps


def leaves(data):
    """{grid name: dataset} of a (nested) multiblock (the readers add "[k]" to a grid's name
    at the k-th time)."""
    found = {}
    iterator = vtkDataObjectTreeIterator()
    iterator.SetDataSet(data)
    iterator.VisitOnlyLeavesOn()
    iterator.InitTraversal()
    while not iterator.IsDoneWithTraversal():
        name = iterator.GetCurrentMetaData().Get(vtkCompositeDataSet.NAME())
        found[re.sub(r"\[[0-9]+\]$", "", name or "")] = iterator.GetCurrentDataObject()
        iterator.GoToNextItem()
    return found


def hdf5_values(folder, reference):
    file_name, dataset = reference.split(":", 1)
    with h5py.File(os.path.join(folder, file_name), "r") as f:
        return np.asarray(f[dataset][()], dtype=float)


def check_reader(label, reader, steps, folder):
    """The problems of one reader at every time; and the number of arrays it checked."""
    problems = []
    checked = 0
    for time, grids in sorted(steps.items()):
        reader.UpdatePipeline(time)
        blocks = leaves(servermanager.Fetch(reader))
        for name, attributes in grids.items():
            block = blocks.get(name)
            if block is None:
                problems.append(f"{label}: t = {time:g}: no grid '{name}' (read: {sorted(blocks)})")
                continue
            for attribute, center, reference in attributes:
                on_nodes = center == "Node"
                arrays = block.GetPointData() if on_nodes else block.GetCellData()
                count = block.GetNumberOfPoints() if on_nodes else block.GetNumberOfCells()
                array = arrays.GetArray(attribute)
                checked += 1
                if array is None or array.GetNumberOfTuples() != count:
                    tuples = "no array" if array is None else f"{array.GetNumberOfTuples()} tuples"
                    problems.append(f"{label}: t = {time:g}: '{name}' {center} array '{attribute}': {tuples} "
                                    f"for {count} {'points' if on_nodes else 'cells'}")
                    continue
                expected = hdf5_values(folder, reference).reshape(count, -1)
                values = np.asarray(dataset_adapter.vtkDataArrayToVTKArray(array), dtype=float).reshape(count, -1)
                scale = max(1.0, float(np.max(np.abs(expected)))) if expected.size else 1.0
                if values.shape != expected.shape or np.max(np.abs(values - expected)) > TOLERANCE * scale:
                    problems.append(f"{label}: t = {time:g}: '{name}' array '{attribute}' differs from {reference}")
    return problems, checked


def main():
    if len(sys.argv) != 2 or sys.argv[1] in ("-h", "--help"):
        print(__doc__.strip())
        return 0 if len(sys.argv) == 2 else 2
    path = os.path.abspath(sys.argv[1])
    steps = declared_grids(path)
    if not steps or not any(grids for grids in steps.values()):
        print(f"xdmf readers: {path} declares no grids")
        return 1
    readers = {"legacy XDMFReader": simple.XDMFReader(FileNames=[path]),
               "Xdmf3ReaderT": simple.Xdmf3ReaderT(FileName=[path])}
    readers["legacy XDMFReader"].PointArrayStatus = readers["legacy XDMFReader"].GetProperty(
        "PointArrayInfo")[::2]
    readers["legacy XDMFReader"].CellArrayStatus = readers["legacy XDMFReader"].GetProperty("CellArrayInfo")[::2]
    problems = []
    total = 0
    for label, reader in readers.items():
        found, checked = check_reader(label, reader, steps, os.path.dirname(path))
        print(f"{label}: {checked} arrays at {len(steps)} times, {len(found)} problems")
        problems += found
        total += checked
    for problem in problems:
        print(problem)
    print(f"xdmf readers: {total} arrays checked, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
