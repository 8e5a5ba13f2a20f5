#!/usr/bin/env python3
"""Force ripple of a wedge entering water at constant speed (cases/wedge_constant_speed.toml).

Usage: wedge_fill_ripple.py V BETA_DEG T0_OF_RUN... where each argument after the first two is
RUN_DIR:T0 (T0 = geometric contact time of that run, s). For every run it reads forces.csv
(column "wedge Fy [N/m]") and, over tau = t - t0 in [TAU_A, TAU_B] (default 3-15 ms):
 - fits F = a + b tau by least squares (wedge theory: F linear in tau at constant speed);
 - ripple_raw = rms(F - fit) / mean(F) on the per-step force;
 - ripple_0.5ms = the same after a 0.5 ms centred moving average (keeps the staircase period
   dx/V = 2.5 ms at dx = 5 mm, removes step-to-step acoustic noise);
 - k = b / (rho V^3) against Wagner's flat-plate wedge value k_W = pi (pi / (2 tan beta))^2,
   and F(tau_b)/(rho V^3 tau_b) from the fit.
Python standard library only.
"""
import csv
import math
import os
import sys

RHO = 1000.0
TAU_A = float(os.environ.get("TAU_A", "0.003"))
TAU_B = float(os.environ.get("TAU_B", "0.015"))


def read(path):
    t, f = [], []
    with open(os.path.join(path, "forces.csv")) as fh:
        r = csv.reader(fh)
        head = next(r)
        col = head.index("wedge Fy [N/m]")
        for row in r:
            t.append(float(row[0]))
            f.append(float(row[col]))
    return t, f


def fit(x, y):
    n = len(x)
    mx, my = sum(x) / n, sum(y) / n
    sxx = sum((a - mx) ** 2 for a in x)
    sxy = sum((a - mx) * (b - my) for a, b in zip(x, y))
    b = sxy / sxx
    return my - b * mx, b


def moving_average(t, f, width):
    out = []
    j0 = j1 = 0
    s = 0.0
    for i, ti in enumerate(t):
        while j1 < len(t) and t[j1] <= ti + 0.5 * width:
            s += f[j1]
            j1 += 1
        while t[j0] < ti - 0.5 * width:
            s -= f[j0]
            j0 += 1
        out.append(s / (j1 - j0))
    return out


def metrics(t, f, t0):
    tau = [x - t0 for x in t]
    sm = moving_average(tau, f, 0.0005)
    sel = [i for i, x in enumerate(tau) if TAU_A <= x <= TAU_B]
    x = [tau[i] for i in sel]
    y = [f[i] for i in sel]
    ys = [sm[i] for i in sel]
    a, b = fit(x, y)
    mean = sum(y) / len(y)
    rms = math.sqrt(sum((yi - (a + b * xi)) ** 2 for xi, yi in zip(x, y)) / len(y)) / mean
    rms_s = math.sqrt(sum((yi - (a + b * xi)) ** 2 for xi, yi in zip(x, ys)) / len(y)) / mean
    peak_s = max(abs(yi - (a + b * xi)) / (a + b * xi) for xi, yi in zip(x, ys))
    return a, b, rms, rms_s, peak_s, len(sel)


def main():
    V = float(sys.argv[1])
    beta = math.radians(float(sys.argv[2]))
    kw = math.pi * (math.pi / (2.0 * math.tan(beta))) ** 2
    print(f"window tau = {TAU_A * 1e3:g}-{TAU_B * 1e3:g} ms; Wagner flat-plate k = {kw:.4g}")
    print("run,samples,ripple_raw,ripple_0.5ms,max_dev_0.5ms,k_fit,k_fit/k_W,"
          "F(tau_b)/(rho V^3 tau_b),intercept/F(tau_b)")
    for arg in sys.argv[3:]:
        path, t0 = arg.rsplit(":", 1)
        t, f = read(path)
        a, b, rms, rms_s, peak_s, n = metrics(t, f, float(t0))
        fb = a + b * TAU_B
        k = b / (RHO * V ** 3)
        print(f"{os.path.basename(path.rstrip('/'))},{n},{rms:.4f},{rms_s:.4f},{peak_s:.4f},"
              f"{k:.4g},{k / kw:.4f},{fb / (RHO * V ** 3 * TAU_B):.4g},{a / fb:.4f}")


if __name__ == "__main__":
    main()
