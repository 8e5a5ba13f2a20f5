#!/usr/bin/env python3
"""Table of the fuselage study runs (scripts/validate_fuselage_studies.sh; docs/studies.md §2).

Reads every run folder under OUT (summary.json, forces.csv, probes.csv) and prints one
Markdown row per run: particles, fluid steps, solid sub-steps per fluid step, wall time and
threads, status, leaked water particles, the momentum error (the largest |R| of the
momentum balance against its largest term, summary.json "momentum_balance"), the peak vertical force and its time, the vertical
impulse, the force late in the entry (mean Fy over 20-50 ms), the largest step-to-step
oscillation of Fy (rms about its 1 ms moving average, worst 5 ms window), the largest equivalent strain
of each part with its angle from the keel, the largest keel deflection, the ovalisation at
the end, and the energy residual relative to the largest term.
Usage: scripts/fuselage_study_table.py OUT
"""
import bisect
import csv
import json
import math
import os
import sys

CENTRE = (1.5, 2.3)  # the shipped fuselage cases' section centre (reference configuration)


def read_csv(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    head = rows[0]
    data = [[float(v) for v in r] for r in rows[1:] if r]
    return head, data


def column(head, name):
    for i, h in enumerate(head):
        if h == name or h.startswith(name + " ["):
            return i
    return None


def keel_angle(x, y):
    """Angle from the keel about the section centre, degrees, anticlockwise (app/keel_angle.h)."""
    a = math.degrees(math.atan2(x - CENTRE[0], -(y - CENTRE[1])))
    return a % 360.0


def reference_position(run_dir, body, particle):
    """Position of a body particle in the run's first VTK frame (t = 0: the reference)."""
    import vtk  # python3-vtk9 (a test package)
    r = vtk.vtkXMLPolyDataReader()
    r.SetFileName(os.path.join(run_dir, "vtk", body + "_00000.vtp"))
    r.Update()
    return r.GetOutput().GetPoint(particle)[:2]


def row(out, name):
    d = os.path.join(out, name)
    s = json.load(open(os.path.join(d, "summary.json")))
    body = "fuselage"
    fh, fd = read_csv(os.path.join(d, "forces.csv"))
    t = [r[0] for r in fd]
    fy = [r[column(fh, body + " Fy")] for r in fd]
    k = max(range(len(fy)), key=lambda i: abs(fy[i]))
    impulse = sum(0.5 * (fy[i] + fy[i - 1]) * (t[i] - t[i - 1]) for i in range(1, len(t)))
    # Step-to-step oscillation: rms of Fy about its centred 1 ms moving average, and the
    # largest such rms over 5 ms windows with the window's start (docs/studies.md §2).
    osc = []
    for w0 in range(0, int(1e3 * t[-1]) + 1, 5):
        idx = [j for j in range(len(t)) if w0 * 1e-3 <= t[j] < (w0 + 5) * 1e-3]
        if len(idx) < 10:
            continue
        res = []
        for j in idx:
            lo, hi = bisect.bisect_left(t, t[j] - 5e-4), bisect.bisect_right(t, t[j] + 5e-4)
            res.append(fy[j] - sum(fy[lo:hi]) / (hi - lo))
        osc.append((math.sqrt(sum(x * x for x in res) / len(res)), w0))
    osc_max = max(osc) if osc else (float("nan"), 0)
    late = [fy[i] for i in range(len(t)) if 0.02 <= t[i] <= 0.05]
    late_mean = sum(late) / len(late) if late else float("nan")
    ph, pd = read_csv(os.path.join(d, "probes.csv"))
    kc = column(ph, "keel")
    keel = max((r[kc] for r in pd), key=abs) if kc is not None else float("nan")
    dv, dh = column(ph, "oval_dDv"), column(ph, "oval_dDh")
    oval = (pd[-1][dv], pd[-1][dh]) if dv is not None else (float("nan"),) * 2
    sc, fl = column(ph, "column_shortening"), column(ph, "floor_midspan")
    col = max((r[sc] for r in pd), key=abs) if sc is not None else None
    flo = max((r[fl] for r in pd), key=abs) if fl is not None else None
    parts = []
    for b in s.get("parts", []):
        if b["body"] != body:
            continue
        for p in b["parts"]:
            if p.get("particles", 0) == 0 or "peak_equivalent_strain" not in p:
                continue
            if "peak_angle_deg" in p:
                angle = p["peak_angle_deg"] % 360.0
            else:  # runs before summary.json had it: the particle's position at t = 0
                try:
                    angle = keel_angle(*reference_position(d, body, p["peak_particle"]))
                except ImportError:  # no VTK reader: the current position (approximate)
                    angle = keel_angle(*p["peak_position_m"])
            parts.append("%s %.2e at %.0f° (%.1f ms)" % (
                p["name"], p["peak_equivalent_strain"], angle, 1e3 * p["peak_time_s"]))
    steps = s.get("fluid_steps", 0)
    sub = s.get("solid_substeps", 0) / steps if steps else float("nan")
    e = s.get("energy_balance", {})
    # The momentum balance's largest |R| (x or y) against its largest term (README "Momentum
    # balance"); "–" for runs from before summary.json had it.
    mo = s.get("momentum_balance", {}).get("max_abs_residual_relative")
    mom = "%.1e" % max(abs(v) for v in mo) if mo else "–"
    return [
        name, s.get("status", "?"), "%d / %d" % (s["particles"]["fluid"], s["particles"][body]),
        "%d" % steps, "%.0f" % sub, "%.0f s (%d)" % (s.get("wall_seconds", 0), s.get("threads", 0)),
        "%d" % s.get("leaked_particles", -1), mom, "%.1f kN/m at %.2f ms" % (fy[k] / 1e3, 1e3 * t[k]),
        "%.2f" % impulse, "%.2f" % (late_mean / 1e3),
        "%.1f (%d-%d ms)" % (osc_max[0] / 1e3, osc_max[1], osc_max[1] + 5), "%.1f" % (1e3 * keel),
        "%.1f / %.1f" % (1e3 * oval[0], 1e3 * oval[1]),
        "%.2f" % (1e3 * col) if col is not None else "–",
        "%.2f" % (1e3 * flo) if flo is not None else "–",
        "<br>".join(parts), "%.1f %%" % (100 * e.get("residual_relative", float("nan"))),
    ]


def main():
    out = sys.argv[1]
    names = sorted(n for n in os.listdir(out)
                   if os.path.isfile(os.path.join(out, n, "summary.json"))
                   and os.path.isfile(os.path.join(out, n, "forces.csv")))
    head = ["run", "status", "water / structure particles", "fluid steps", "sub-steps per step",
            "wall (threads)", "leaked", "momentum error", "peak Fy", "impulse Fy [N s/m]", "mean Fy 20-50 ms [kN/m]", "largest Fy oscillation rms [kN/m] (window)",
            "max keel deflection [mm]", "end ΔD vertical / horizontal [mm]",
            "max column shortening [mm]", "max floor mid-span deflection [mm]",
            "peak equivalent strain per part, angle from the keel", "energy residual"]
    print("| " + " | ".join(head) + " |")
    print("|" + "---|" * len(head))
    for n in names:
        try:
            print("| " + " | ".join(row(out, n)) + " |")
        except (OSError, KeyError, ValueError, IndexError) as err:
            print("| %s | unreadable: %s |" % (n, err))


if __name__ == "__main__":
    main()
