#!/usr/bin/env python3
"""Force oscillation of an elastic body under dual time stepping (docs/studies.md,
"Force oscillation of the skin-stringer sections").

  force_oscillation_report.py RUN [BODY]    per 1 ms window of RUN/forces.csv: mean Fy, rms of
      Fy minus its centred 1 ms moving average, the dominant frequency f of that deviation
      (2-18 kHz), the fluid step rate 1/dt and 1/dt - f (constant when the signal is the
      fluid-step sample of a faster structural motion), then the body's dissipated energy
      and energy residual from RUN/energy.csv, and the peaks of Fy raw and through centred
      moving averages of 0.25 and 1 ms (the filter to read the slamming force with).
  force_oscillation_report.py --modes PROBES.csv COLUMN [COLUMN2 RATIO]
      amplitude peaks (1-100 kHz) of a probe column of a dry modal run, optionally of
      COLUMN - RATIO * COLUMN2 (cancels a mode whose shape ratio is RATIO).
Pure Python (no numpy): a direct Fourier sum on the recorded times.
"""
import bisect
import csv
import math
import sys


def load(path, col):
    with open(path) as fh:
        rows = csv.reader(fh)
        head = next(rows)
        i = head.index(col)
        t, y = [], []
        for r in rows:
            t.append(float(r[0]))
            y.append(float(r[i]))
    return t, y


def moving_average(t, y, width):
    out = []
    for k in range(len(t)):
        lo = bisect.bisect_left(t, t[k] - width / 2)
        hi = bisect.bisect_right(t, t[k] + width / 2)
        out.append(sum(y[lo:hi]) / (hi - lo))
    return out


def amplitude(t, s, f):
    c = sum(v * math.cos(2 * math.pi * f * ti) for v, ti in zip(s, t))
    q = sum(v * math.sin(2 * math.pi * f * ti) for v, ti in zip(s, t))
    return 2 * math.hypot(c, q) / len(s)


def peaks(t, s, f0, f1, df):
    m = sum(s) / len(s)
    s = [v - m for v in s]
    a = [(f, amplitude(t, s, f)) for f in [f0 + i * df for i in range(int((f1 - f0) / df))]]
    p = [a[i] for i in range(1, len(a) - 1) if a[i][1] > a[i - 1][1] and a[i][1] >= a[i + 1][1]]
    return sorted(p, key=lambda q: -q[1])


def forces(run, body):
    t, y = load(run + "/forces.csv", body + " Fy [N/m]")
    avg = moving_average(t, y, 1e-3)
    print("window [ms]   mean Fy  rms dev   f [kHz]  1/dt [kHz]  1/dt-f [kHz]   (N/m)")
    w0 = 0.0
    while w0 < t[-1] - 1e-3:
        idx = [k for k in range(len(t)) if w0 <= t[k] < w0 + 1e-3]
        dev = [y[k] - avg[k] for k in idx]
        rms = math.sqrt(sum(d * d for d in dev) / len(dev))
        f = peaks([t[k] for k in idx], dev, 2000.0, 18000.0, 50.0)[0][0]
        rate = (len(idx) - 1) / (t[idx[-1]] - t[idx[0]])
        mean = sum(y[k] for k in idx) / len(idx)
        print(f"{w0 * 1e3:4.0f}-{w0 * 1e3 + 1:<4.0f}  {mean:9.0f} {rms:8.0f}  {f / 1e3:7.2f}"
              f"  {rate / 1e3:9.2f}  {(rate - f) / 1e3:11.2f}")
        w0 += 1e-3
    with open(run + "/energy.csv") as fh:
        rows = list(csv.reader(fh))
    head = rows[0]
    di = head.index(body + " dissipated [J/m]")
    ri = head.index(body + " residual [J/m]")
    print("energy.csv: t [ms], dissipated, residual [J/m]:",
          "; ".join(f"{float(r[0]) * 1e3:.1f} {float(r[di]):.2f} {float(r[ri]):.2f}"
                    for r in rows[1:]))
    for width in (0.0, 2.5e-4, 1e-3):
        z = moving_average(t, y, width) if width > 0 else y
        early = max(z[k] for k in range(len(t)) if t[k] < 5e-3)
        late = max((z[k], t[k]) for k in range(len(t)) if t[k] >= 5e-3)
        print(f"Fy through a centred {width * 1e3:.2f} ms moving average: peak before 5 ms "
              f"{early:.0f} N/m, after {late[0]:.0f} N/m at {late[1] * 1e3:.2f} ms")


def modes(path, col, col2=None, ratio=0.0):
    t, y = load(path, col)
    if col2:
        _, y2 = load(path, col2)
        y = [a - ratio * b for a, b in zip(y, y2)]
    print(col if not col2 else f"{col} - {ratio} {col2}", "peaks [kHz: amplitude]:",
          ", ".join(f"{f / 1e3:.2f}: {a:.3g}" for f, a in peaks(t, y, 1000.0, 1e5, 250.0)[:6]))


if __name__ == "__main__":
    a = sys.argv[1:]
    if a and a[0] == "--modes" and len(a) in (3, 5):
        modes(a[1], a[2], *(a[3:4] + [float(x) for x in a[4:5]]))
    elif len(a) in (1, 2):
        forces(a[0], a[1] if len(a) == 2 else "fuselage")
    else:
        sys.exit(__doc__)
