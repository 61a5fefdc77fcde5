"""Loads the XDMF sidecar of a fields file in ParaView (run by pvpython) and checks that the
arrays ParaView reads are the fields file's: the cell arrays and time steps exist, and one
value at one phase equals the one the HDF5 file holds (read independently with h5py).
Usage: pvpython fields_in_paraview.py FIELDS.xdmf FIELDS.h5
Prints one line; exit status 0 if all agree, 1 otherwise."""
import sys

import h5py
import numpy as np
from paraview import servermanager
from paraview.simple import OpenDataFile, UpdatePipeline
from vtk.numpy_interface import dataset_adapter as dsa

xdmf, fields = sys.argv[1], sys.argv[2]
reader = OpenDataFile(xdmf)
if reader is None:
    print(f"fields_in_paraview: ParaView cannot open {xdmf}")
    sys.exit(1)
times = list(reader.TimestepValues)
phase = min(3, len(times) - 1)
UpdatePipeline(time=times[phase], proxy=reader)
data = servermanager.Fetch(reader)
block = data.GetBlock(0) if data.IsA("vtkMultiBlockDataSet") else data
cells = dsa.WrapDataObject(block).CellData
problems = []
for name in ("area_fraction", "temperature", "velocity"):
    if name not in cells.keys():
        problems.append(f"no cell array {name} (has {list(cells.keys())})")
with h5py.File(fields, "r") as f:
    expected = np.asarray(f[f"/xdmf/p{phase:04d}/area_fraction"]).ravel()
    steps = len([k for k in f["/xdmf"].keys() if k.startswith("p")])
if len(times) != steps:
    problems.append(f"{len(times)} time steps, the file has {steps} phases")
if not problems:
    got = np.asarray(cells["area_fraction"]).ravel()
    k = int(np.nanargmax(expected))  # the densest cell: a value that is not 0 or NaN
    if got.shape != expected.shape or got[k] != expected[k]:
        problems.append(f"area fraction of cell {k} at phase {phase}: ParaView {got[k] if got.shape == expected.shape else got.shape}, HDF5 {expected[k]}")
if problems:
    print("fields_in_paraview: " + "; ".join(problems))
    sys.exit(1)
print(f"fields_in_paraview: ok ({len(times)} phases, area fraction {expected[k]:.6g} at "
      f"phase {phase}, cell {k})")
