#!/usr/bin/env pvpython
# Opens particlesToVTK's output with ParaView itself and checks it against
# the case written by tests/unit/io/writeParticleCase (same formulas):
#
#   pvpython checkVtk.py <case> <times> [nx ny nDimensions]
#
# times: comma-separated, e.g. 0,0.1,0.2. Prints one line per check and
# exits non-zero on the first failure set.
import sys

from paraview import servermanager
import paraview.simple as pv
from vtkmodules.util.numpy_support import vtk_to_numpy

failures = []


def check(what, ok, detail=""):
    print(("PASS: " if ok else "FAIL: ") + what + ("" if ok else "  " + detail))
    if not ok:
        failures.append(what)


def expected(body, t, nx, ny, nDim):
    """Points and point data as writeParticleCase computes them."""
    z = 0.1 + t if nDim == 3 else 0.0
    dp = 0.01
    if body == "water":
        n = nx*ny
        pts = [((k % nx + 0.5)*dp, (k//nx + 0.5)*dp - t, z) for k in range(n)]
        data = {
            "U": [(k/1000.0, -t, 0.0) for k in range(n)],
            "rho": [1000.0 + k + t for k in range(n)],
            "p": [(k % 7)/2.0 + t for k in range(n)],
            "flag": [k % 3 for k in range(n)],
            "id": list(range(n)),
        }
    else:
        n = (nx + 6)*3
        pts = [((k % (nx + 6) - 2.5)*dp, (k//(nx + 6) - 2.5)*dp, z)
               for k in range(n)]
        data = {"rho": [1000.0 + k for k in range(n)], "id": list(range(n))}
    return pts, data


def main():
    case = sys.argv[1]
    times = [float(t) for t in sys.argv[2].split(",")]
    nx, ny, nDim = (int(a) for a in (sys.argv[3:6] if len(sys.argv) > 5
                                     else ("20", "10", "2")))

    for body in ("water", "tank"):
        series = "%s/VTK/%s.vtp.series" % (case, body)
        reader = pv.OpenDataFile(series)
        check("%s: ParaView opens %s" % (body, series), reader is not None)
        if reader is None:
            continue
        steps = list(reader.TimestepValues)
        check("%s: TimestepValues %s" % (body, times), steps == times,
              "got %s" % steps)

        for t in times:
            reader.UpdatePipeline(t)
            poly = servermanager.Fetch(reader)
            pts, data = expected(body, t, nx, ny, nDim)
            tag = "%s at t=%g" % (body, t)
            n = poly.GetNumberOfPoints()
            check("%s: %d points" % (tag, len(pts)), n == len(pts),
                  "got %d" % n)
            check("%s: one vertex cell per point" % tag,
                  poly.GetNumberOfVerts() == n and poly.GetNumberOfCells() == n,
                  "verts %d cells %d" % (poly.GetNumberOfVerts(),
                                         poly.GetNumberOfCells()))
            pd = poly.GetPointData()
            names = sorted(pd.GetArrayName(i)
                           for i in range(pd.GetNumberOfArrays()))
            check("%s: point data %s" % (tag, sorted(data)),
                  names == sorted(data), "got %s" % names)
            if n != len(pts):
                continue

            got = vtk_to_numpy(poly.GetPoints().GetData())
            check("%s: positions bit-exact" % tag,
                  [tuple(r) for r in got.tolist()] == pts,
                  "first %s, expected %s" % (got[:2].tolist(), pts[:2]))
            for name, want in data.items():
                arr = pd.GetArray(name)
                if arr is None:
                    continue
                comps = 3 if isinstance(want[0], tuple) else 1
                check("%s: %s has %d component(s)" % (tag, name, comps),
                      arr.GetNumberOfComponents() == comps,
                      "got %d" % arr.GetNumberOfComponents())
                values = vtk_to_numpy(arr).tolist()
                if comps == 3:
                    values = [tuple(v) for v in values]
                bad = [k for k in range(len(want)) if values[k] != want[k]]
                check("%s: %s values" % (tag, name), not bad,
                      "first mismatch at %d: %s != %s" % (
                          bad[0], values[bad[0]], want[bad[0]])
                      if bad else "")
            if body == "water":
                rho = pd.GetArray("rho").GetRange()
                check("%s: rho range" % tag,
                      rho == (1000.0 + t, 1000.0 + len(pts) - 1 + t),
                      "got %s" % (rho,))
        pv.Delete(reader)

    print("%d failed" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
