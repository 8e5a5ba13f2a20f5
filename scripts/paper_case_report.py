#!/usr/bin/env python3
"""The paper's case (§4.1) reported honestly (issue 9; docs/validation.md §3). Python stdlib.

Usage: paper_case_report.py RUN_DIR REFERENCES_CSV
RUN_DIR holds forces.csv and bodies.csv of a free-falling cylinder run whose body starts
above the water (scripts/validate_cylinder.sh makes one: lowest point 3 dx above the
surface). From bodies.csv (centre of mass, mean velocity): s(t) = y_surface - (y_c - R),
V(t) = -v_y; t0 = the geometric contact time s(t0) = 0 (interpolated). Cs(t) = F(t) / (rho
V(t)^2 R) is compared with the constant-speed references at s(t)/D. Prints the velocity
history, the peak (value, s/D, t - t0), the mean Cs over s/D 0.05-0.25 against each
reference, and writes cs_actual.csv.
"""
import csv
import math
import os
import sys

run, refs_path = sys.argv[1], sys.argv[2]
RHO, R, SURF = 1000.0, 0.1, 0.4
b = list(csv.reader(open(os.path.join(run, "bodies.csv"))))
cy, cv = b[0].index("cylinder com_y [m]"), b[0].index("cylinder vel_y [m/s]")
tb = [float(r[0]) for r in b[1:]]
sb = [SURF - (float(r[cy]) - R) for r in b[1:]]
vb = [-float(r[cv]) for r in b[1:]]


def interp(xs, ys, x):
    for k in range(len(xs) - 1):
        if xs[k] <= x <= xs[k + 1]:
            return ys[k] + (ys[k + 1] - ys[k]) * (x - xs[k]) / (xs[k + 1] - xs[k])
    return float("nan")


t0 = next(tb[k] + (0 - sb[k]) * (tb[k + 1] - tb[k]) / (sb[k + 1] - sb[k])
          for k in range(len(sb) - 1) if sb[k] < 0 <= sb[k + 1])
f = list(csv.reader(open(os.path.join(run, "forces.csv"))))
col = f[0].index("cylinder Fy [N/m]")
rows = []
for r in f[1:]:
    t = float(r[0])
    s, v = interp(tb, sb, t), interp(tb, vb, t)
    if math.isnan(s) or math.isnan(v):
        continue
    rows.append((t - t0, s / (2 * R), v, float(r[col]), float(r[col]) / (RHO * v * v * R)))
with open(os.path.join(run, "cs_actual.csv"), "w") as fh:
    fh.write("t - t0 [s],s/D,V [m/s],F [N/m],Cs\n")
    for row in rows:
        fh.write(",".join(f"{x:.6g}" for x in row) + "\n")
ref_rows = [r for r in csv.reader(l for l in open(refs_path) if not l.startswith("#"))]
names = ref_rows[0][1:]
rsd = [float(r[0]) for r in ref_rows[1:]]
rcs = {n: [float(r[i + 1]) if r[i + 1] else float("nan") for r in ref_rows[1:]]
       for i, n in enumerate(names)}
pk = max(rows, key=lambda r: r[3])
print(f"t0 (geometric contact) = {1e3 * t0:.3f} ms; V(t0) = {interp(tb, vb, t0):.4f} m/s")
print("velocity history (t - t0 [ms]: V [m/s]): " + ", ".join(
    f"{ms}: {interp(tb, vb, t0 + 1e-3 * ms):.3f}" for ms in (0, 2, 5, 10, 20, 30, 40, 50)))
print(f"peak F {pk[3]:.0f} N/m at t - t0 = {1e3 * pk[0]:.2f} ms, s/D = {pk[1]:.4f}, Cs(actual V) = {pk[4]:.3f}")
sel = [r for r in rows if 0.05 <= r[1] <= 0.25]
mean_cs = sum(r[4] for r in sel) / len(sel)
print(f"mean Cs over s/D 0.05-0.25 (actual V, s): {mean_cs:.3f} ({len(sel)} samples)")
for n in names:
    vals = [interp(rsd, rcs[n], r[1]) for r in sel]
    if any(math.isnan(x) for x in vals):
        print(f"  {n}: not defined over the whole range")
        continue
    m = sum(vals) / len(vals)
    print(f"  {n}: mean {m:.3f}, SPH {100 * (mean_cs / m - 1):+.1f} %")
