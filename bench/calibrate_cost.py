#!/usr/bin/env python3
"""Per-particle costs of the cost model (src/app/cost_model.h, issue 13 item 5), measured.

Runs every case given (default: the shipped cases) for a few fluid steps on one thread with
`slamsph run --max-steps K`, reads the run's phase split (summary.json "time_split_s",
src/app/phase_times.h) and the particle and pair counts `slamsph check` prints, and fits the
constants of the model in src/app/cost_model.h by least squares on the relative error:

  water    fluid_rates = steps c_pair(N_water) N_ff (c_pair log-linear in N_water between
           its values at 3 200 and 166 500 water particles: the pair pass leaves the caches);  fluid_integration + step_limit +
           checks_and_zone = steps c_water N_water
  lists    neighbour_lists = rebuilds c_rebuild (N_water + N_contact) (the per-step
           displacement check is small: a separate per-step term fitted negative)
  contact  contact = steps c_cpair (N_fc + N_cf) with water,
           every phase but the sub-steps = steps c_dry N_contact without
  solid    solid_substeps = Σ_b (c_sub substeps_b + c_call N_b steps + c_jc N_b substeps_b):
           c_sub = c_lane N_b where the pair loops run in lanes, c_pair P_b where scalar (P_b
           the body's pair entries, printed by `slamsph check` per particle); c_lane, c_pair
           and c_call from the SVK cases, c_jc (the Johnson–Cook law's elastic path, little
           yield in 60 steps) from the Johnson–Cook bodies (median). The sub-step costs of
           wet cases include solid_wet_factor (cost_model.h): divide by it before taking
           them as the body-alone constants (session 20 took them from benchmarks and the
           probe instead: docs/validation.md §6 "Cost model")

Then it prints, for each case, the measured phase times against the fitted model. Time is
CPU time: each phase's share of a 1-thread run's wall time times the run's CPU time
(summary.json "cpu_seconds"), which a busy machine inflates less than wall time; still,
run it on an idle machine where possible (the load average before each run is printed). Usage:

  bench/calibrate_cost.py BUILD/slamsph [--steps K] [--repeat R] [--save F] [CASE.toml ...]
  bench/calibrate_cost.py BUILD/slamsph --load F      (refit saved measurements)
"""
import argparse
import json
import math
import os
import re
import statistics
import subprocess
import sys
import tempfile

N_SMALL, N_LARGE = 3200.0, 166500.0  # CostConstants::water_n_small / water_n_large
HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
SHIPPED = [
    "cases/still_water.toml",
    "cases/dam_break.toml",
    "bench/dam_break_peer.toml",
    "cases/cylinder_constant_speed.toml",
    "cases/wedge_constant_speed.toml",
    "cases/greenhow_lin_free_fall.toml",
    "cases/rigid_cylinder_entry.toml",
    "cases/elastic_cylinder_entry.toml",
    "cases/elastic_gate.toml",
    "cases/oscillating_plate.toml",
    "cases/tension_bar.toml",
    "cases/johnson_cook_bar.toml",
    "cases/johnson_cook_notched.toml",
    "cases/skin_ring_reduced.toml",
    "cases/fuselage/skin_cylinder.toml",
    "cases/fuselage/skin_L_floor_column.toml",
    "cases/fuselage/elastic_plastic_I_floor_column.toml",
]


def check(slamsph, case):
    r = subprocess.run([slamsph, "check", case], capture_output=True, text=True)
    out = r.stdout + r.stderr
    m = re.search(r"predicted: (\d+) water and (\d+) contact particles \((\d+) water and "
                  r"(\d+) contact pairs listed\)", out)
    if not m:
        sys.exit(f"{case}: no prediction in 'slamsph check' output:\n{out}")
    # (particles, Johnson–Cook?, pair entries per particle, pair loops in lanes?)
    elastic = [(int(a), law == "johnson_cook", float(q), loops == "in lanes")
               for a, q, loops, law in re.findall(
                   r"body \S+: (\d+) particles, elastic, (\S+) pairs per particle, .*?"
                   r"\(pair loops (in lanes|scalar)\), law (\S+)", out)]
    return dict(water=int(m.group(1)), contact=int(m.group(2)), wpairs=int(m.group(3)),
                cpairs=int(m.group(4)), elastic=elastic)


def run(slamsph, case, steps, out):
    subprocess.run([slamsph, "run", case, "--max-steps", str(steps), "--threads", "1",
                    "--out", out, "--overwrite", "-q", "--set", "output.vtk=false"],
                   check=False, capture_output=True)
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def lsq(rows):
    """Least squares of y = Σ c_k x_k on the relative error: rows of (xs, y)."""
    k = len(rows[0][0])
    A = [[0.0] * k for _ in range(k)]
    b = [0.0] * k
    for xs, y in rows:
        w = 1.0 / (y * y)
        for i in range(k):
            b[i] += w * xs[i] * y
            for j in range(k):
                A[i][j] += w * xs[i] * xs[j]
    # Gaussian elimination (k <= 3)
    for i in range(k):
        for r in range(i + 1, k):
            f = A[r][i] / A[i][i]
            for c in range(i, k):
                A[r][c] -= f * A[i][c]
            b[r] -= f * b[i]
    c = [0.0] * k
    for i in reversed(range(k)):
        c[i] = (b[i] - sum(A[i][j] * c[j] for j in range(i + 1, k))) / A[i][i]
    return c


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("slamsph")
    ap.add_argument("--steps", type=int, default=60)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--save", help="write the measurements to this JSON file")
    ap.add_argument("--load", help="fit the measurements of an earlier --save, run nothing")
    ap.add_argument("cases", nargs="*")
    a = ap.parse_intermixed_args()
    cases = a.cases or [os.path.join(ROOT, c) for c in SHIPPED]
    recs = []
    if a.load:
        with open(a.load) as f:
            recs = json.load(f)
        cases = []
    with tempfile.TemporaryDirectory() as tmp:
        for case in cases:
            c = check(a.slamsph, case)
            runs = []
            for _ in range(a.repeat):
                load = os.getloadavg()[0]
                runs.append((run(a.slamsph, case, a.steps, os.path.join(tmp, "r")), load))
            s0 = runs[0][0]
            n = s0["fluid_steps"]
            if n == 0:
                continue
            # Each phase's CPU time: its share of the wall time times the run's CPU time
            # (one thread: the time the run waited for a core on a busy machine is not
            # counted, to first order in proportion to each phase).
            t = {}
            for key in s0["time_split_s"]:
                t[key] = statistics.median(
                    s["time_split_s"][key] * s["cpu_seconds"] / s["wall_seconds"]
                    for s, _ in runs)
            c.update(name=os.path.relpath(case, ROOT), steps=n, sub=s0["solid_substeps"],
                     rebuilds=s0["neighbour_rebuilds"],
                     t=t, load=max(l for _, l in runs),
                     wall=statistics.median(s["wall_seconds"] for s, _ in runs),
                     cpu=statistics.median(s["cpu_seconds"] for s, _ in runs))
            recs.append(c)
            print(f"measured {c['name']}: {n} steps, wall {c['wall']:.2f} s, CPU "
                  f"{c['cpu']:.2f} s, load "
                  f"{c['load']:.2f}", file=sys.stderr, flush=True)

    if a.save:
        with open(a.save, "w") as f:
            json.dump(recs, f, indent=1)

    def water_t(r):
        t = r["t"]
        return t["fluid_integration"] + t["step_limit"] + t["checks_and_zone"]

    wet = [r for r in recs if r["water"] > 0]
    dry = [r for r in recs if r["water"] == 0]
    el = [r for r in recs if r["elastic"] and r["sub"] > 0]
    def f_size(n):  # the log-linear weight of the large-N constant (cost_model.h)
        return min(1.0, max(0.0, math.log(n / N_SMALL) / math.log(N_LARGE / N_SMALL)))

    cp = lsq([([1e-9 * r["steps"] * r["wpairs"] * (1 - f_size(r["water"])),
                1e-9 * r["steps"] * r["wpairs"] * f_size(r["water"])], r["t"]["fluid_rates"])
              for r in wet])
    cw = lsq([([1e-9 * r["steps"] * r["water"]], water_t(r)) for r in wet])
    # summary.json's neighbour_rebuilds counts the set-up's build, which no phase times.
    cl = lsq([([1e-9 * (r["rebuilds"] - 1) * (r["water"] + r["contact"])],
               r["t"]["neighbour_lists"]) for r in wet if r["rebuilds"] > 1])
    cc = lsq([([1e-9 * r["steps"] * r["cpairs"]], r["t"]["contact"]) for r in wet])
    # Without water everything but the sub-steps is per contact particle and step: the body
    # state, the step limit, the checks, the records and the (cheap) displacement check.
    def dry_t(r):
        return sum(v for k, v in r["t"].items() if k not in ("solid_substeps", "fluid_rates"))
    cd = lsq([([1e-9 * r["steps"] * r["contact"]], dry_t(r)) for r in dry]) if dry \
        else [0.0]

    # One elastic body per shipped case: its sub-steps are the run's. SVK bodies fit the
    # sub-step (in lanes per particle, scalar per pair entry) and per-call costs; Johnson–Cook
    # bodies then their law's extra cost per particle-sub-step.
    def solid_x(r):
        nb, _, pairs, lanes = r["elastic"][0]
        sub = 1e-9 * nb * r["sub"]
        return [sub if lanes else 0.0, 0.0 if lanes else sub * pairs, 1e-9 * nb * r["steps"]]
    svk = [r for r in el if not r["elastic"][0][1]]
    jc = [r for r in el if r["elastic"][0][1]]
    rows = [(solid_x(r), r["t"]["solid_substeps"]) for r in svk]
    used = [i for i in range(3) if any(x[i] for x, _ in rows)]
    fit = lsq([([x[i] for i in used], y) for x, y in rows]) if rows else []
    cs = [0.0, 0.0, 0.0]
    for i, v in zip(used, fit):
        cs[i] = v
    def svk_model(r):
        return sum(c * x for c, x in zip(cs, solid_x(r)))
    kjc = statistics.median(
        (r["t"]["solid_substeps"] - svk_model(r)) / (1e-9 * r["elastic"][0][0] * r["sub"])
        for r in jc) if jc else 68.0
    print(f"water_pair_ns_small = {cp[0]:.2f}, water_pair_ns_large = {cp[1]:.2f}, water_ns = "
          f"{cw[0]:.1f}, rebuild_ns = {cl[0]:.1f}, contact_pair_ns = "
          f"{cc[0]:.2f}, dry_contact_ns = {cd[0]:.1f}, solid_lane_ns = {cs[0]:.1f}, solid_pair_ns = "
          f"{cs[1]:.1f}, solid_call_ns = {cs[2]:.1f}, johnson_cook_elastic_ns = {kjc:.1f}")
    print()
    print("| case | water / contact / elastic | steps | phase: measured / model [s] water, "
          "lists, contact, solid | total measured / model | load |")
    print("|---|---|---|---|---|---|")
    for r in recs:
        st = 1e-9 * r["steps"]
        fs = f_size(r["water"]) if r["water"] else 0.0
        mw = st * ((cp[0] * (1 - fs) + cp[1] * fs) * r["wpairs"] + cw[0] * r["water"]) \
            if r["water"] else 0.0
        ml = 1e-9 * max(0, r["rebuilds"] - 1) * cl[0] * (r["water"] + r["contact"]) \
            if r["water"] else 0.0
        mc = st * cc[0] * r["cpairs"] if r["water"] else st * cd[0] * r["contact"]
        ms = 0.0
        if r in el:
            ms = svk_model(r) + (1e-9 * kjc * r["elastic"][0][0] * r["sub"]
                                 if r["elastic"][0][1] else 0.0)
        meas = [water_t(r) + r["t"]["fluid_rates"], r["t"]["neighbour_lists"], r["t"]["contact"],
                r["t"]["solid_substeps"]] if r["water"] else \
            [0.0, 0.0, dry_t(r), r["t"]["solid_substeps"]]
        mod = [mw, ml, mc, ms]
        tm, tp = sum(meas), sum(mod)
        ne = sum(e[0] for e in r["elastic"])
        print(f"| {r['name']} | {r['water']} / {r['contact']} / {ne} | {r['steps']} | " +
              ", ".join(f"{x:.3g} / {y:.3g}" for x, y in zip(meas, mod)) +
              f" | {tm:.3g} / {tp:.3g} ({100 * (tp / tm - 1):+.0f} %) | {r['load']:.2f} |")


if __name__ == "__main__":
    main()
