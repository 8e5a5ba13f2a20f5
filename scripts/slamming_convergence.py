#!/usr/bin/env python3
"""Post-processing of scripts/validate_slamming.sh (Python standard library only).

Reads OUT/d<D/dx>_c<c0/V>/forces.csv of the constant-speed cylinder runs and
OUT/references.csv (build/slamming_references), writes tables and a plot, prints a report.

Definitions (docs/validation.md §1):
  s = V (t - t0), t0 = 3 dx / V the geometric contact time (the case starts the lowest
  point 3 dx above the free surface); Cs = F / (rho V^2 R).
  Filter: Cs at s/D = q is the mean of the raw Cs(t) over s/D in [q - 0.005, q + 0.005]
  (time average, trapezoidal). The window is fixed in s, so it is the same physical filter
  at every dx: 1 mm of submergence = 0.43 ms = 2.3 acoustic times R V / c0^2 at c0/V = 15.
  Impulse: I = integral of Cs d(s/D) over s/D 0.02-0.25 (= impulse / (rho V R D)), and
  over 0.02-0.15, where the exact-circle Wagner and modified Logvinovich curves exist.
  Values at s/D beyond the first tank echo (s/D = 1.2 m V / ((c0 + V) D), minus the
  filter half-width) are not reported.
  Observed order p = ln(|f1 - f2| / |f2 - f3|) / ln 2 (f3 finest, refinement ratio 2);
  Roache's GCI of the finest grid = Fs |f3 - f2| / |f3| / (2^p - 1): Fs = 1.25 with
  p = min(p_obs, 2) if the three values are monotone and p_obs >= 0.5; otherwise Fs = 3
  with p = 1 (flagged 'lo': monotone but p_obs < 0.5; 'nm': not monotone).
  Peak: the largest raw F, reported as a range over every run with its s/D, dx/s*
  (s* = R V^2 / c0^2, the end of the acoustic stage) and Mach number V/c0.
"""
import csv
import math
import os
import sys

out, V, D = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
R, RHO = D / 2, 1000.0
HALF = 0.005
STATIONS = [0.01, 0.025, 0.05, 0.1, 0.2, 0.3]
WINDOW = (0.02, 0.25)
WINDOW2 = (0.02, 0.15)  # where every 2D theory is defined (exact-circle Wagner: s/D <= 0.18)
TANK = 1.2  # m: floor and side-wall echo path (cases/cylinder_constant_speed.toml)


def load(tag):
    ddx, mach = (int(x) for x in tag[1:].split("_c"))
    rows = list(csv.reader(open(os.path.join(out, tag, "forces.csv"))))
    col = rows[0].index("cylinder Fy [N/m]")
    dx, c0 = D / ddx, mach * V
    t0 = 3 * dx / V
    sd = [V * (float(r[0]) - t0) / D for r in rows[1:]]
    cs = [float(r[col]) / (RHO * V * V * R) for r in rows[1:]]
    echo = TANK * V / ((c0 + V) * D)
    return {"tag": tag, "ddx": ddx, "mach": mach, "dx": dx, "c0": c0, "sd": sd, "cs": cs,
            "echo": echo}


def mean_over(run, lo, hi):
    sd, cs = run["sd"], run["cs"]
    if hi > run["echo"] or hi > sd[-1] or lo < sd[0]:
        return float("nan")
    acc = 0.0
    for k in range(len(sd) - 1):
        a, b = max(sd[k], lo), min(sd[k + 1], hi)
        if b <= a:
            continue
        # trapezoid of the linear interpolant on [a, b]
        w = sd[k + 1] - sd[k]
        fa = cs[k] + (cs[k + 1] - cs[k]) * (a - sd[k]) / w
        fb = cs[k] + (cs[k + 1] - cs[k]) * (b - sd[k]) / w
        acc += 0.5 * (fa + fb) * (b - a)
    return acc / (hi - lo)


def filtered(run, q):
    return mean_over(run, q - HALF, q + HALF)


def impulse(run, w=WINDOW):
    return mean_over(run, *w) * (w[1] - w[0])


def impulse2(run):
    return impulse(run, WINDOW2)


def peak(run):
    k = max(range(len(run["cs"])), key=lambda i: run["cs"][i])
    s_star = R * V * V / run["c0"] ** 2
    return run["cs"][k], run["sd"][k], run["dx"] / s_star, V / run["c0"]


def gci(f1, f2, f3):
    """f1 coarsest ... f3 finest; returns (p_obs, GCI_fine, flag)."""
    if any(math.isnan(x) for x in (f1, f2, f3)):
        return float("nan"), float("nan"), "na"
    e21, e32 = f2 - f1, f3 - f2
    eps = abs(e32) / abs(f3)
    if e32 == 0.0:
        return float("inf"), 0.0, ""
    p = math.log(abs(e21) / abs(e32)) / math.log(2) if e21 != 0 else float("nan")
    if e21 * e32 > 0:  # monotone
        if p >= 0.5:
            return p, 1.25 * eps / (2 ** min(p, 2.0) - 1), ""
        return p, 3.0 * eps, "lo"
    return p, 3.0 * eps, "nm"


tags = sorted((t for t in os.listdir(out) if t.startswith("d") and "_c" in t
               and os.path.exists(os.path.join(out, t, "summary.json"))),
              key=lambda t: tuple(int(x) for x in t[1:].split("_c")))
runs = {t: load(t) for t in tags}
refs_rows = [r for r in csv.reader(l for l in open(os.path.join(out, "references.csv"))
                                   if not l.startswith("#"))]
ref_names = refs_rows[0][1:]
ref_sd = [float(r[0]) for r in refs_rows[1:]]
ref = {n: [float(r[i + 1]) if r[i + 1] else float("nan") for r in refs_rows[1:]]
       for i, n in enumerate(ref_names)}


def ref_at(name, q):  # the references filtered with the same window, for like-with-like
    vals = [c for s, c in zip(ref_sd, ref[name]) if q - HALF - 1e-12 <= s <= q + HALF + 1e-12]
    if not vals or any(math.isnan(v) for v in vals) or q - HALF < 0:
        return ref[name][min(range(len(ref_sd)), key=lambda i: abs(ref_sd[i] - q))]
    return sum(vals) / len(vals)


def ref_impulse(name, w=WINDOW):
    acc, n = 0.0, 0
    for s, c in zip(ref_sd, ref[name]):
        if w[0] <= s <= w[1]:
            if math.isnan(c):
                return float("nan")
            acc += c
            n += 1
    return acc / n * (w[1] - w[0])


def fmt(x, nd=3):
    return "n/a" if x is None or (isinstance(x, float) and math.isnan(x)) else f"{x:.{nd}f}"


lines = []
say = lines.append
say(f"runs: {', '.join(tags)}")
say(f"filter: mean over s/D +-{HALF}; impulse window s/D {WINDOW[0]}-{WINDOW[1]}")

# ---- per-run table ------------------------------------------------------------------
with open(os.path.join(out, "runs.csv"), "w") as fh:
    fh.write("D/dx,c0/V," + ",".join(f"Cs(s/D={q})" for q in STATIONS) +
             ",impulse Cs d(s/D) 0.02-0.25,impulse 0.02-0.15,peak Cs,peak s/D,dx/s*,Mach,echo s/D,wall [s],fluid steps\n")
    for t in tags:
        r = runs[t]
        summ = open(os.path.join(out, t, "summary.json")).read()
        wall = summ.split('"wall_seconds": ')[1].split(",")[0]
        steps = summ.split('"fluid_steps": ')[1].split(",")[0]
        pk = peak(r)
        fh.write(f"{r['ddx']},{r['mach']}," + ",".join(fmt(filtered(r, q), 4) for q in STATIONS) +
                 f",{fmt(impulse(r), 5)},{fmt(impulse2(r), 5)},{pk[0]:.4f},{pk[1]:.4f},{pk[2]:.2f},{pk[3]:.4f},"
                 f"{r['echo']:.3f},{wall},{steps}\n")
say("\nper run (runs.csv):")
say(open(os.path.join(out, "runs.csv")).read().rstrip())

# ---- dx convergence at c0/V = 15 ----------------------------------------------------
series = sorted((runs[t] for t in tags if runs[t]["mach"] == 15), key=lambda r: r["ddx"])
conv_rows = []
if len(series) >= 3:
    c, m, f = series[-3:]
    say(f"\nconvergence in dx at c0/V = 15, grids D/dx = {c['ddx']}, {m['ddx']}, {f['ddx']}:")
    quantities = [(f"Cs(s/D={q})", (lambda r, q=q: filtered(r, q))) for q in STATIONS]
    quantities.append(("impulse 0.02-0.25", impulse))
    quantities.append(("impulse 0.02-0.15", impulse2))
    head = "quantity,D/dx=%d,D/dx=%d,D/dx=%d,observed order,GCI fine [%%],flag," % (
        c["ddx"], m["ddx"], f["ddx"]) + ",".join(ref_names)
    with open(os.path.join(out, "convergence.csv"), "w") as fh:
        fh.write(head + "\n")
        for name, fn in quantities:
            v = [fn(r) for r in (c, m, f)]
            p, g, flag = gci(*v)
            if name.startswith("Cs"):
                q = float(name.split("=")[1].rstrip(")"))
                refs = [ref_at(n, q) for n in ref_names]
            elif name.endswith("0.15"):
                refs = [ref_impulse(n, WINDOW2) for n in ref_names]
            else:
                refs = [ref_impulse(n) for n in ref_names]
            row = [name] + [fmt(x, 4) for x in v] + [fmt(p, 2), fmt(100 * g, 1), flag] + \
                [f"{fmt(x, 3)} ({fmt(100 * (v[2] / x - 1), 0) if x and not math.isnan(x) else 'n/a'} %)"
                 for x in refs]
            fh.write(",".join(row) + "\n")
            conv_rows.append(row)
    say(open(os.path.join(out, "convergence.csv")).read().rstrip())

# ---- c0 table at the two finest resolutions ---------------------------------------
ddxs = sorted({r["ddx"] for r in runs.values() if r["mach"] != 15})
for ddx in ddxs[-2:]:
    sub = sorted((r for r in runs.values() if r["ddx"] == ddx), key=lambda r: r["mach"])
    if len(sub) < 2:
        continue
    say(f"\nsound speed at D/dx = {ddx} (Cs filtered; n/a = after the tank echo):")
    say("c0/V," + ",".join(f"s/D={q}" for q in STATIONS) + ",impulse 0.02-0.25,impulse 0.02-0.15,peak Cs (s/D)")
    for r in sub:
        pk = peak(r)
        say(f"{r['mach']}," + ",".join(fmt(filtered(r, q)) for q in STATIONS) +
            f",{fmt(impulse(r), 4)},{fmt(impulse2(r), 4)},{pk[0]:.2f} ({pk[1]:.3f})")
    spread = []
    for q in STATIONS:
        vals = [filtered(r, q) for r in sub]
        vals = [x for x in vals if not math.isnan(x)]
        if len(vals) >= 2:
            spread.append(f"s/D={q}: {100 * (max(vals) - min(vals)) / (sum(vals) / len(vals)):.1f} %")
    say("spread over c0 (max - min)/mean: " + "; ".join(spread))

# ---- peak range -------------------------------------------------------------------
pks = [(peak(r), r) for r in runs.values()]
lo = min(pks, key=lambda x: x[0][0])
hi = max(pks, key=lambda x: x[0][0])
say("\npeak Cs over all runs: %.2f (%s, s/D %.3f, dx/s* %.1f, Mach %.3f) to %.2f (%s, s/D %.3f, dx/s* %.1f, Mach %.3f)" % (
    lo[0][0], lo[1]["tag"], lo[0][1], lo[0][2], lo[0][3],
    hi[0][0], hi[1]["tag"], hi[0][1], hi[0][2], hi[0][3]))

# ---- filtered curves and the plot ---------------------------------------------------
with open(os.path.join(out, "cs_filtered.csv"), "w") as fh:
    fh.write("s/D," + ",".join(f"{t}" for t in tags) + "\n")
    q = 0.005
    while q <= 0.36 + 1e-9:
        fh.write(f"{q:.4f}," + ",".join(fmt(filtered(runs[t], q), 4) if not math.isnan(filtered(runs[t], q)) else "" for t in tags) + "\n")
        q += 0.0025
open(os.path.join(out, "report.txt"), "w").write("\n".join(lines) + "\n")
print("\n".join(lines))

gp = ["set terminal pngcairo size 1100,700 noenhanced", "set output 'cs_vs_sD.png'",
      "set datafile separator ','", "set datafile missing ''",
      "set xlabel 's/D'", "set ylabel 'Cs = F / (rho V^2 R)'", "set grid", "set xrange [0:0.36]",
      "set yrange [0:7]", "set key top right",
      "set title 'rigid cylinder at constant speed: filtered Cs (mean over s/D +-0.005) vs 2D theory and 3D experiment fit'"]
plots = []
for i, t in enumerate(tags):
    if runs[t]["mach"] == 15 or runs[t]["ddx"] == max(r["ddx"] for r in runs.values()):
        plots.append(f"'cs_filtered.csv' using 1:{i + 2} with lines lw 2 title 'SPH D/dx={runs[t]['ddx']} c0/V={runs[t]['mach']}'")
COLOURS = ["#d62728", "#000000", "#7f7f7f", "#2ca02c", "#1f3fbf"]
for i, n in enumerate(ref_names):
    dim = "3D exp. fit" if n == "Campbell-Weynberg" else "2D"
    plots.append(f"'references.csv' using 1:{i + 2} with lines dt {i + 2} lw 3 "
                 f"lc rgb '{COLOURS[i % len(COLOURS)]}' title '{n} ({dim})'")
gp.append("plot " + ", \\\n     ".join(plots))
open(os.path.join(out, "cs_vs_sD.gp"), "w").write("\n".join(gp) + "\n")
os.system(f"cd '{out}' && gnuplot cs_vs_sD.gp")
print(f"wrote {out}/runs.csv, convergence.csv, cs_filtered.csv, report.txt, cs_vs_sD.png")
