#!/usr/bin/python3
"""Reads a run's VTK output back, independently of the writer: every file listed in the two .pvd
collections with VTK's own XML reader (vtkmodules from Debian's python3-paraview, which YADE
brings; python3-vtk9 would conflict with it), and checks each frame against the run's state.json
(positions, radii, velocities of the final frame) and its summary (ball counts, times).
Usage: read_vtk.py RUN_DIR DT float32|float64     exit 0 when everything agrees, 1 with the reason
otherwise. float64: the final frame equals state.json bit for bit; float32: it equals state.json's
numbers rounded to the nearest float32 — and each ball takes 48 bytes of the appended data."""
import json
import os
import struct
import sys
import xml.etree.ElementTree as ET

run, dt, precision = sys.argv[1], float(sys.argv[2]), sys.argv[3]
state = json.load(open(os.path.join(run, "state.json")))
summary = json.load(open(os.path.join(run, "summary.json")))
try:
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
except ImportError:
    print("FAIL: VTK's Python modules are missing (apt-get install python3-paraview)")
    sys.exit(1)
REAL_BYTES = 8 if precision == "float64" else 4
BALL_BYTES = 11 * REAL_BYTES + 4  # position 3, radius, mass, velocity 3, force 3 reals; tag Int32


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def as_written(x):
    """A double as the file holds it: itself, or rounded to the nearest float32."""
    return x if precision == "float64" else struct.unpack("<f", struct.pack("<f", x))[0]


def read(path):
    """(points, {array name: rows}) of one .vtp."""
    r = vtkXMLPolyDataReader()
    r.SetFileName(path)
    r.Update()
    if r.GetErrorCode() != 0:
        fail("VTK could not read " + path)
    pd = r.GetOutput()
    pts = vtk_to_numpy(pd.GetPoints().GetData()).tolist() if pd.GetNumberOfPoints() else []
    arrays = {}
    for k in range(pd.GetPointData().GetNumberOfArrays()):
        a = pd.GetPointData().GetArray(k)
        arrays[a.GetName()] = vtk_to_numpy(a).tolist()
    # The appended data is the arrays and their byte counts alone: BALL_BYTES a ball.
    raw = open(path, "rb").read()
    data = raw[raw.index(b'<AppendedData encoding="raw">'):]
    data = data[data.index(b"_") + 1:data.rindex(b"\n </AppendedData>")]
    if len(data) != len(pts) * BALL_BYTES + 6 * 8:  # six arrays, each after its UInt64 byte count
        fail("%s: %d bytes of appended data for %d balls, expected %d" % (path, len(data), len(pts),
                                                                        len(pts) * BALL_BYTES + 48))
    return pts, arrays


frames = {}
for kind in ("balls", "walls"):
    pvd = os.path.join(run, "vtk", kind + ".pvd")
    sets = ET.parse(pvd).getroot().findall("Collection/DataSet")
    if not sets:
        fail(pvd + " lists no frames")
    for ds in sets:
        f = ds.get("file")
        step = int(f[len(kind) + 1:-4])
        if abs(float(ds.get("timestep")) - step * dt) > 1e-12 * max(1.0, step * dt):
            fail("%s: %s at time %s, expected %g" % (pvd, f, ds.get("timestep"), step * dt))
        pts, arrays = read(os.path.join(run, "vtk", f))
        for name in ("radius", "mass", "velocity", "force", "tag"):
            if name not in arrays:
                fail("%s has no array %s" % (f, name))
        frames.setdefault(kind, []).append((step, pts, arrays))

last_balls, last_walls = frames["balls"][-1], frames["walls"][-1]
if len(last_balls[1]) != summary["balls"]["mobile"] or len(last_walls[1]) != summary["balls"]["fixed"]:
    fail("final frame: %d + %d balls, the summary says %d + %d" % (len(last_balls[1]), len(last_walls[1]),
         summary["balls"]["mobile"], summary["balls"]["fixed"]))
# The final frame against state.json (another writer): same balls, same numbers to the last bit.
by_tag = {}
for kind in (last_balls, last_walls):
    for p, r, v, t in zip(kind[1], kind[2]["radius"], kind[2]["velocity"], kind[2]["tag"]):
        by_tag[int(t)] = (p, r, v)
if len(by_tag) != len(state["balls"]):
    fail("final frame has %d balls, state.json %d" % (len(by_tag), len(state["balls"])))
worst = 0.0
for tag, b in zip(sorted(by_tag), state["balls"]):  # state.json lists the balls in tag order
    p, r, v = by_tag[tag]
    worst = max(worst, max(abs(a - as_written(c)) for a, c in zip(p, b["position"])), abs(r - as_written(b["radius"])),
                max(abs(a - as_written(c)) for a, c in zip(v, b.get("velocity", [0, 0, 0]))))
if worst != 0.0:
    fail("final frame differs from state.json (%s) by %g" % (precision, worst))
# Wall loads: the forces on the wall balls sum to the summary's wall force.
wf = [sum(f[d] for f in last_walls[2]["force"]) for d in range(3)]
# (float32: each force rounded by 6e-8 of itself, a sum of many by at most that times their count.)
bound = (1e-9 if precision == "float64" else 6e-8 * len(last_walls[2]["force"])) * max(1e-12, max(abs(x) for x in wf))
if max(abs(a - b) for a, b in zip(wf, summary["wall_force"])) > bound:
    fail("wall forces sum to %s, the summary says %s" % (wf, summary["wall_force"]))
print("ok: %d + %d frames read with VTK's vtkXMLPolyDataReader; %d bytes a ball; final frame equals state.json "
      "(%s) bitwise; wall loads sum to the summary's" % (len(frames["balls"]), len(frames["walls"]), BALL_BYTES, precision))
