#!/usr/bin/python3
"""Reads slamsph's VTK output back with VTK's own XML readers (Debian python3-vtk9), an
implementation independent of slamsph's writer, and checks what ParaView would show:
arrays, their types and component counts, tensor component names, time values in the
.pvd and in each file, and that Float32 and Float64 (zlib) runs hold the same data.

usage: vtk_readback.py SLAMSPH_BINARY WORK_DIR
Exit 0 if every check passes; prints each failure and exits 1 otherwise.
"""
import os
import subprocess
import sys
import xml.etree.ElementTree as ET

import vtk


def tuples(arr):
    """The array as a list of tuples (no numpy: python3-vtk9 does not depend on it)."""
    return [arr.GetTuple(i) for i in range(arr.GetNumberOfTuples())]


def max_abs_diff(a, b):
    return max((abs(x - y) for ta, tb in zip(tuples(a), tuples(b)) for x, y in zip(ta, tb)),
               default=0.0)


def max_abs(a):
    return max((abs(x) for t in tuples(a) for x in t), default=0.0)

CASE = """schema_version = 1
name = "readback"
[numerics]
dx = 0.02
end_time = 0.004
[numerics.domain]
min = [-0.2, -0.2]
max = [1.2, 1.2]
[fluid]
sound_speed = 20.0
[[fluid.block]]
min = [0.0, 0.0]
max = [0.4, 0.3]
[materials.rubber]
density = 1100.0
youngs_modulus = 2.0e6
poisson_ratio = 0.45
[[body]]
name = "tank"
kind = "rigid_fixed"
[body.shape]
type = "tank"
min = [0.0, 0.0]
max = [1.0, 1.0]
[[body]]
name = "block"
material = "rubber"
velocity = [0.0, -1.0]
[body.shape]
type = "rectangle"
min = [0.6, 0.4]
max = [0.8, 0.5]
[output]
interval = 0.001
"""

failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAIL:", what)


def run(binary, work, name, extra):
    out = os.path.join(work, name)
    cmd = [binary, "run", os.path.join(work, "readback.toml"), "--out", out, "--threads", "1",
           "--quiet", "--overwrite"] + extra
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        print(r.stderr)
        sys.exit("slamsph failed: " + " ".join(cmd))
    return out


def read_series(out):
    """{part name: [(time, polydata)]} from fields.pvd, read with vtkXMLPolyDataReader."""
    tree = ET.parse(os.path.join(out, "fields.pvd"))
    series = {}
    for ds in tree.getroot().iter("DataSet"):
        reader = vtk.vtkXMLPolyDataReader()
        path = os.path.join(out, ds.get("file"))
        reader.SetFileName(path)
        reader.Update()
        check(reader.GetErrorCode() == 0, "reader error on " + path)
        series.setdefault(ds.get("name"), []).append((float(ds.get("timestep")), reader.GetOutput()))
    return series


def arrays(pd):
    d = pd.GetPointData()
    return {d.GetArrayName(k): d.GetArray(k) for k in range(d.GetNumberOfArrays())}


def check_series(series, real_type):
    check(set(series) == {"fluid", "tank", "block"}, "parts %s" % sorted(series))
    times = [t for t, _ in series["fluid"]]
    check(len(times) == 5, "5 frames at interval 1 ms over 4 ms, got %d" % len(times))
    # A frame is written at the first step at or after each multiple of the interval.
    check(all(0.001 * k - 1e-12 <= t < 0.001 * k + 0.0015 for k, t in enumerate(times))
          and times == sorted(set(times)), "pvd times %s" % times)
    for name, frames in series.items():
        for t, pd in frames:
            tv = pd.GetFieldData().GetArray("TimeValue")
            check(tv is not None and abs(tv.GetValue(0) - t) < 1e-15,
                  "%s: TimeValue equals the .pvd timestep %g" % (name, t))
            check(pd.GetNumberOfPoints() > 0 and pd.GetNumberOfVerts() == pd.GetNumberOfPoints(),
                  "%s: one vertex per point" % name)
            check(pd.GetPoints().GetData().GetDataTypeAsString() == real_type,
                  "%s: points are %s" % (name, real_type))
            a = arrays(pd)
            check(a["id"].GetDataTypeAsString() == "int", "%s: ids are integers" % name)
            ids = [t[0] for t in tuples(a["id"])]
            check(len(set(ids)) == len(ids), "%s: ids distinct" % name)
    fl = arrays(series["fluid"][-1][1])
    check(set(fl) >= {"velocity", "pressure", "density", "id", "set", "crossed_solid"},
          "fluid arrays %s" % sorted(fl))
    check(fl["velocity"].GetNumberOfComponents() == 3, "velocity has 3 components")
    check(fl["pressure"].GetDataTypeAsString() == real_type, "pressure is %s" % real_type)
    rho = [t[0] for t in tuples(fl["density"])]
    check(min(rho) > 900 and max(rho) < 1100, "density near 1000 kg/m^3: %g..%g" % (min(rho), max(rho)))
    bl = arrays(series["block"][-1][1])
    for tensor in ("green_lagrange_strain", "cauchy_stress"):
        arr = bl[tensor]
        check(arr.GetNumberOfComponents() == 6, tensor + " has 6 components")
        names = [arr.GetComponentName(c) for c in range(6)]
        check(names == ["XX", "YY", "ZZ", "XY", "YZ", "XZ"], "%s component names %s" % (tensor, names))
    f = bl["deformation_gradient"]
    check(f.GetNumberOfComponents() == 4, "deformation_gradient has 4 components")
    F = tuples(f)
    check(all(abs(t[0] - 1.0) < 0.05 and abs(t[3] - 1.0) < 0.05 for t in F),
          "F close to identity early in the run")
    vy = [t[1] for t in tuples(bl["velocity"])]
    check(abs(sum(vy) / len(vy) + 1.0) < 0.2, "block falls at about 1 m/s: %g" % (sum(vy) / len(vy)))


def main():
    binary, work = sys.argv[1], sys.argv[2]
    os.makedirs(work, exist_ok=True)
    with open(os.path.join(work, "readback.toml"), "w") as f:
        f.write(CASE)
    a = read_series(run(binary, work, "f32", []))
    check_series(a, "float")
    b = read_series(run(binary, work, "f64z", ["--set", "output.vtk_precision=\"float64\"",
                                                "--set", "output.vtk_compression=\"zlib\""]))
    check_series(b, "double")
    # The same run at two precisions: the Float32 file holds the Float64 values rounded.
    for name in a:
        for (ta, pa), (tb, pb) in zip(a[name], b[name]):
            xa, xb = pa.GetPoints().GetData(), pb.GetPoints().GetData()
            check(max_abs_diff(xa, xb) <= 1e-6 * max(1.0, max_abs(xb)), name + ": points agree")
            for k, arr in arrays(pb).items():
                scale = max(1.0, max_abs(arr))
                check(max_abs_diff(arrays(pa)[k], arr) <= 1e-6 * scale,
                      "%s.%s agrees at t=%g" % (name, k, ta))
    if failures:
        print("%d checks failed" % len(failures))
        return 1
    print("vtk readback: all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
