#!/usr/bin/python3
"""Reads a run's VTK output back, independently of the writer: every file listed in the two .pvd
collections with VTK's own XML reader (python3-vtk from python3-paraview, which YADE brings; if it
is missing, with the XML parser of the standard library), and checks each frame against the run's
state.json (positions, radii, velocities of the final frame) and its summary (ball counts, times).
Usage: read_vtk.py RUN_DIR DT     exit 0 when everything agrees, 1 with the reason otherwise."""
import json
import os
import sys
import xml.etree.ElementTree as ET

run, dt = sys.argv[1], float(sys.argv[2])
state = json.load(open(os.path.join(run, "state.json")))
summary = json.load(open(os.path.join(run, "summary.json")))
try:
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
    from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: F401 (numpy comes with VTK)
    reader_name = "VTK vtkXMLPolyDataReader"
except ImportError:
    vtkXMLPolyDataReader = None
    reader_name = "xml.etree"


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def read(path):
    """(points, {array name: rows}) of one .vtp."""
    if vtkXMLPolyDataReader:
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
        if pd.GetNumberOfVerts() != len(pts):
            fail("%s: %d vertices for %d points" % (path, pd.GetNumberOfVerts(), len(pts)))
        return pts, arrays
    root = ET.parse(path).getroot()
    piece = root.find("PolyData/Piece")
    n = int(piece.get("NumberOfPoints"))
    def values(el, comps):
        v = [float(x) for x in (el.text or "").split()]
        if len(v) != n * comps:
            fail("%s: array %s has %d values, expected %d" % (path, el.get("Name"), len(v), n * comps))
        return [v[i * comps:(i + 1) * comps] for i in range(n)] if comps > 1 else v
    pts = values(piece.find("Points/DataArray"), 3)
    arrays = {el.get("Name"): values(el, int(el.get("NumberOfComponents", "1"))) for el in piece.findall("PointData/DataArray")}
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
    worst = max(worst, max(abs(a - c) for a, c in zip(p, b["position"])), abs(r - b["radius"]),
                max(abs(a - c) for a, c in zip(v, b.get("velocity", [0, 0, 0]))))
if worst != 0.0:
    fail("final frame differs from state.json by %g" % worst)
# Wall loads: the forces on the wall balls sum to the summary's wall force.
wf = [sum(f[d] for f in last_walls[2]["force"]) for d in range(3)]
if max(abs(a - b) for a, b in zip(wf, summary["wall_force"])) > 1e-9 * max(1e-12, max(abs(x) for x in wf)):
    fail("wall forces sum to %s, the summary says %s" % (wf, summary["wall_force"]))
print("ok: %d + %d frames read with %s; final frame equals state.json bitwise; wall loads sum to the summary's"
      % (len(frames["balls"]), len(frames["walls"]), reader_name))
