#!/usr/bin/python3
#------------------------------------------------------------------------------
# Reads the fill series of a case as ParaView would, with VTK's own readers
# (Debian's python3-vtk9: vtkXMLDataParser for the .pvd collection,
# vtkXMLPolyDataReader for the frames and the glyph, vtkTensorGlyph for the
# pellets' true shape), and checks it against the run:
#
#   fillSeriesCheck.py CASE WRITEINTERVAL DELTAT
#
# - fill.pvd is a VTK Collection of DataSets with increasing times: the
#   first outer interval end, every multiple of writeInterval the run
#   reached, and the run's last time (summary simulatedTime);
# - every frame parses with no VTK error, holds the arrays of fillSeries.H,
#   its TimeValue is the collection's time, its pellet count never falls,
#   and the last frame holds the summary's pellets;
# - the last frame's centres and quaternions are those of pellets.csv;
# - the Tensor Glyph of pellet.vtp with the orientation tensor (Extract
#   Eigenvalues off, as fillSeries.H tells a ParaView user) puts every
#   vertex of every pellet where pellets.csv's pose puts it.
# Prints ok/FAIL per check; exits 1 on any failure.
#------------------------------------------------------------------------------
import math
import os
import re
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

case, writeInterval, deltaT = sys.argv[1], float(sys.argv[2]), \
    float(sys.argv[3])
out = os.path.join(case, "postProcessing", "rbdPackBed")
fill = os.path.join(out, "fill")
failed = False


def check(name, ok):
    global failed
    print(("ok: " if ok else "FAIL: ") + name)
    failed = failed or not ok
    return ok


class errors:
    """Counts the errors and warnings a VTK object reports."""
    def __init__(self, obj):
        self.n = 0
        for e in ("ErrorEvent", "WarningEvent"):
            obj.AddObserver(e, self)

    def __call__(self, obj, event):
        self.n += 1


def readPolyData(path):
    r = vtk.vtkXMLPolyDataReader()
    e = errors(r)
    r.SetFileName(path)
    r.Update()
    return r.GetOutput(), e.n == 0 and r.GetOutput() is not None


def summaryValue(key):
    with open(os.path.join(out, "summary")) as f:
        m = re.search(r"^%s\s+(\S+);" % key, f.read(), re.M)
    return m.group(1) if m else None


# The collection, with VTK's XML parser
p = vtk.vtkXMLDataParser()
pe = errors(p)
p.SetFileName(os.path.join(fill, "fill.pvd"))
parsed = p.Parse() == 1 and pe.n == 0
root = p.GetRootElement() if parsed else None
check("fill.pvd parses (vtkXMLDataParser)", root is not None)
if root is None:
    sys.exit(1)
coll = root.FindNestedElementWithName("Collection")
sets = [coll.GetNestedElement(i)
        for i in range(coll.GetNumberOfNestedElements())] if coll else []
check("fill.pvd: a VTKFile of type Collection with DataSets",
      root.GetAttribute("type") == "Collection" and len(sets) > 0
      and all(s.GetName() == "DataSet" for s in sets))
times = [float(s.GetAttribute("timestep")) for s in sets]
files = [s.GetAttribute("file") for s in sets]

T = float(summaryValue("simulatedTime"))
n = int(summaryValue("pellets"))
# Frames: the first outer interval end, the multiples of writeInterval,
# the end
expected = {round(deltaT, 9)}
k = 1
while k*writeInterval <= T + 1e-9:
    expected.add(round(k*writeInterval, 9))
    k += 1
expected.add(round(T, 9))
expected = sorted(expected)
check("%d frames at the expected times (first interval, every %g s, the "
      "end at %g s), increasing" % (len(expected), writeInterval, T),
      len(times) == len(expected)
      and all(abs(a - b) < 1e-9 for a, b in zip(times, expected)))

# Every frame
arrays = {"id": 1, "velocity": 3, "omega": 3, "asleep": 1, "contacts": 1,
          "quaternion": 4, "orientation": 9}
allRead = True
allArrays = True
allTimes = True
counts = []
last = None
for t, f in zip(times, files):
    pd, ok = readPolyData(os.path.join(fill, f))
    allRead = allRead and ok
    if not ok:
        continue
    ptd = pd.GetPointData()
    for a, nc in arrays.items():
        arr = ptd.GetArray(a)
        allArrays = allArrays and arr is not None \
            and arr.GetNumberOfComponents() == nc \
            and arr.GetNumberOfTuples() == pd.GetNumberOfPoints()
    tv = pd.GetFieldData().GetArray("TimeValue")
    allTimes = allTimes and tv is not None and abs(tv.GetValue(0) - t) < 1e-9
    counts.append(pd.GetNumberOfPoints())
    last = pd
check("every frame read by vtkXMLPolyDataReader without error", allRead)
check("every frame has id, velocity, omega, asleep, contacts, quaternion "
      "and orientation, one per pellet", allArrays)
check("every frame's TimeValue is its time in fill.pvd", allTimes)
check("pellet counts never fall, the last frame holds the bed's %d" % n,
      len(counts) > 0 and counts[-1] == n
      and all(a <= b for a, b in zip(counts, counts[1:])))
shape = last.GetFieldData().GetAbstractArray("shape")
check("field data shape = %s" % summaryValue("shape"),
      shape is not None and shape.GetValue(0) == summaryValue("shape"))

# The last frame against pellets.csv
csv = np.loadtxt(os.path.join(out, "pellets.csv"), delimiter=",",
                 skiprows=1, usecols=(0, 2, 3, 4, 5, 6, 7, 8), ndmin=2)
x = vtk_to_numpy(last.GetPoints().GetData())
ids = vtk_to_numpy(last.GetPointData().GetArray("id"))
q = vtk_to_numpy(last.GetPointData().GetArray("quaternion"))
dp = last.GetFieldData().GetArray("pelletDiameter").GetValue(0)
check("last frame: ids 0..n-1 as in pellets.csv",
      len(ids) == len(csv) and (ids == csv[:, 0]).all())
dx = np.abs(x - csv[:, 1:4]).max() if len(x) == len(csv) else math.inf
dq = np.abs(q - csv[:, 4:8]).max() if len(q) == len(csv) else math.inf
check("last frame: centres = pellets.csv (largest difference %.2g m)" % dx,
      dx <= 1e-10)
check("last frame: quaternions = pellets.csv (largest difference %.2g)" % dq,
      dq <= 1e-10)
asleep = vtk_to_numpy(last.GetPointData().GetArray("asleep"))
contacts = vtk_to_numpy(last.GetPointData().GetArray("contacts"))
check("last frame of a settled bed: every pellet touches something "
      "(contacts %d to %d, mean %.2f)"
      % (contacts.min(), contacts.max(), contacts.mean()),
      contacts.min() >= 1 and contacts.max() <= 12)
print("    asleep in the last frame: %d of %d" % (asleep.sum(), len(asleep)))

# The glyph: pellet.vtp posed by the orientation tensor
glyph, ok = readPolyData(os.path.join(fill, "pellet.vtp"))
check("pellet.vtp read by vtkXMLPolyDataReader, a closed triangle surface",
      ok and glyph.GetNumberOfCells() > 0
      and glyph.GetNumberOfCells() == 2*(glyph.GetNumberOfPoints() - 2))
tg = vtk.vtkTensorGlyph()
tge = errors(tg)
tg.SetInputData(last)
tg.SetSourceData(glyph)
tg.SetInputArrayToProcess(0, 0, 0, 0, "orientation")
tg.ExtractEigenvaluesOff()
tg.ColorGlyphsOff()
tg.Update()
posed = vtk_to_numpy(tg.GetOutput().GetPoints().GetData())
body = vtk_to_numpy(glyph.GetPoints().GetData())


def rotation(w, a, b, c):
    return np.array([
        [1 - 2*(b*b + c*c), 2*(a*b - w*c), 2*(a*c + w*b)],
        [2*(a*b + w*c), 1 - 2*(a*a + c*c), 2*(b*c - w*a)],
        [2*(a*c - w*b), 2*(b*c + w*a), 1 - 2*(a*a + b*b)]])


want = np.concatenate(
    [body @ rotation(*r[4:8]).T + r[1:4] for r in csv]) if len(csv) else []
err = np.abs(posed - want).max() if len(posed) == len(want) else math.inf
# The tensor has 7 digits and the glyph's points are single precision
# (1.5e-8 m at z = 0.25 m): 1e-5 dp; a transposed tensor is off by ~dp
check("Tensor Glyph (Extract Eigenvalues off) of pellet.vtp puts every "
      "pellet's vertices at pellets.csv's pose (largest difference "
      "%.2g dp)" % (err/dp), tge.n == 0 and err <= 1e-5*dp)

sys.exit(1 if failed else 0)
