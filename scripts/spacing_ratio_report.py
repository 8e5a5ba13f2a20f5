#!/usr/bin/env python3
"""Post-processing of scripts/validate_spacing_ratio.sh (Python standard library only).

Reads OUT/r<ratio>/forces.csv of the constant-speed cylinder runs
(cases/cylinder_constant_speed.toml with body[1].spacing_ratio = ratio) and prints, per
ratio, the impulse I = integral of Cs d(s/D) over s/D 0.02-0.25 (the converged quantity of
docs/validation.md §1), the peak Cs, the mean Cs over s/D 0.02-0.1 and 0.1-0.25, and each
one's relative difference to ratio 1. Writes OUT/spacing_ratio.csv.
Definitions as scripts/slamming_convergence.py: s = V (t - t0), t0 = 3 dx / V (dx the
water's spacing), Cs = F / (rho V^2 R).
Exit status 1 if any ratio's impulse differs from ratio 1's by more than TOL (default 0.035:
measured +2.3 to +3.1 % at D/dx = 40 and +0.4 to +0.7 % at D/dx = 20, docs/model.md §4); also
prints the spread of the impulse among the ratios >= 2 (0.8 % at D/dx = 40).
Usage: spacing_ratio_report.py OUT V D DX [TOL]
"""
import csv
import os
import sys

out, V, D, DX = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4])
TOL = float(sys.argv[5]) if len(sys.argv) > 5 else 0.035
R, RHO = D / 2, 1000.0


def load(ratio):
    rows = list(csv.reader(open(os.path.join(out, "r%s" % ratio, "forces.csv"))))
    col = rows[0].index("cylinder Fy [N/m]")
    t0 = 3 * DX / V
    sd = [V * (float(r[0]) - t0) / D for r in rows[1:]]
    cs = [float(r[col]) / (RHO * V * V * R) for r in rows[1:]]
    return sd, cs


def integral(sd, cs, a, b):
    acc = 0.0
    for k in range(len(sd) - 1):
        lo, hi = max(sd[k], a), min(sd[k + 1], b)
        if hi <= lo:
            continue
        w = sd[k + 1] - sd[k]
        fa = cs[k] + (cs[k + 1] - cs[k]) * (lo - sd[k]) / w
        fb = cs[k] + (cs[k + 1] - cs[k]) * (hi - sd[k]) / w
        acc += 0.5 * (fa + fb) * (hi - lo)
    return acc


ratios = sorted((d[1:] for d in os.listdir(out)
                 if d.startswith("r") and os.path.isfile(os.path.join(out, d, "forces.csv"))),
                key=float)
if "1" not in ratios:
    sys.exit("no ratio-1 run in " + out)
table = []
for r in ratios:
    sd, cs = load(r)
    if sd[-1] < 0.25:
        print("r%s: run ends at s/D = %.3f < 0.25, skipped" % (r, sd[-1]))
        continue
    table.append({"ratio": r, "impulse": integral(sd, cs, 0.02, 0.25),
                  "early": integral(sd, cs, 0.02, 0.1) / 0.08,
                  "late": integral(sd, cs, 0.1, 0.25) / 0.15,
                  "peak": max(c for s, c in zip(sd, cs) if s <= 0.25)})
ref = next(t for t in table if t["ratio"] == "1")
bad = False
with open(os.path.join(out, "spacing_ratio.csv"), "w") as f:
    f.write("ratio,impulse_002_025,rel_impulse,mean_cs_002_01,rel_early,mean_cs_01_025,rel_late,"
            "peak_cs,rel_peak\n")
    print("ratio  impulse(0.02-0.25)  rel     <Cs>(0.02-0.1)  rel     <Cs>(0.1-0.25)  rel     "
          "peak Cs  rel")
    for t in table:
        rel = {k: t[k] / ref[k] - 1 for k in ("impulse", "early", "late", "peak")}
        bad = bad or abs(rel["impulse"]) > TOL
        f.write("%s,%.6f,%.5f,%.5f,%.5f,%.5f,%.5f,%.5f,%.5f\n" % (
            t["ratio"], t["impulse"], rel["impulse"], t["early"], rel["early"], t["late"],
            rel["late"], t["peak"], rel["peak"]))
        print("%-6s %.5f             %+.4f  %.4f          %+.4f  %.4f          %+.4f  %.3f    %+.4f" % (
            t["ratio"], t["impulse"], rel["impulse"], t["early"], rel["early"], t["late"],
            rel["late"], t["peak"], rel["peak"]))
fine = [t["impulse"] for t in table if float(t["ratio"]) >= 2]
if len(fine) > 1:
    print("spread of the impulse among ratios >= 2: %.2f %%" % (100 * (max(fine) / min(fine) - 1)))
print("tolerance on the impulse vs ratio 1: %.1f %% -> %s" % (100 * TOL, "FAIL" if bad else "ok"))
sys.exit(1 if bad else 0)
