#!/usr/bin/env python3
"""The cost model's prediction against the run (issue 13 item 5: within 30 % for every case).

For each case: `slamsph check CASE --threads T` (the prediction, with this machine's factors
measured by its built-in probes, src/app/cost_model.h), then `slamsph run CASE --threads T`
with VTK off, to the case's end time or to --end-time; prints the predicted and measured
fluid steps, solid sub-steps, neighbour rebuilds, wall time of the time stepping (summary.json
wall_seconds; the process's wall time with start-up and plots in brackets), the solid phase
and (1 thread) CPU time, and the relative error of the stepping's wall time. The machine
should be idle: the prediction is for an idle machine of this kind (the load average before
each run is printed). Usage:

  bench/predict_vs_run.py BUILD/slamsph [--threads T ...] [--end-time S] [--set KEY=VALUE ...]
                          [--repeat N] [CASE.toml ...]

With --repeat N each case is predicted and run N times in turn and the medians are printed (the
error is that of the medians; the single errors follow in brackets): on the shared 2-core
machines of this kind two consecutive 2-thread runs of a small case differ by up to 1.35x
(docs/validation.md §6 "Cost model", session 18), and the probes of `slamsph check` by as
much.

Cases default to the shipped ones (bench/calibrate_cost.py's list). Results go to a
temporary folder that is removed afterwards.
"""
import argparse
import json
import os
import re
import resource
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from calibrate_cost import ROOT, SHIPPED  # noqa: E402


def predict(slamsph, case, threads, extra):
    r = subprocess.run([slamsph, "check", case, "--threads", str(threads)] + extra,
                       capture_output=True, text=True)
    out = r.stdout + r.stderr
    if r.returncode != 0:
        sys.exit(f"{case}: 'slamsph check' failed:\n{out}")
    steps = re.search(r"(\d+) fluid steps, (\d+) neighbour rebuilds", out)
    wall = re.search(r"predicted wall time .*?: (\S+) s on 1 thread, (\S+) s on (\d+) threads? "
                     r"\(solid sub-steps (\S+) s", out)
    cpu = re.search(r"predicted CPU time on 1 thread: (\S+) s", out)
    machine = re.search(r"machine: (.*?) of the calibration", out)
    subs = sum(int(n) for n in re.findall(r"(\d+) sub-steps per fluid step", out))
    if not (steps and wall and cpu):
        sys.exit(f"{case}: no prediction in 'slamsph check' output:\n{out}")
    return dict(steps=int(steps.group(1)), rebuilds=int(steps.group(2)),
                substeps_per_step=subs,
                wall=float(wall.group(1)) if threads == 1 else float(wall.group(2)),
                solid=float(wall.group(4)),
                cpu=float(cpu.group(1)),
                machine="/".join(re.findall(r"x([0-9.]+)", machine.group(1))) if machine
                else "not probed")


def measure(slamsph, case, threads, extra, out):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.monotonic()
    r = subprocess.run([slamsph, "run", case, "--threads", str(threads), "--exact-threads",
                        "--out", out, "--overwrite", "--quiet", "--set", "output.vtk=false"]
                       + extra, capture_output=True, text=True)
    wall = time.monotonic() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if r.returncode != 0:
        sys.exit(f"{case}: run failed ({r.returncode}):\n{r.stdout}{r.stderr}")
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return dict(wall=wall, cpu=cpu, summary=s)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("slamsph")
    ap.add_argument("cases", nargs="*")
    ap.add_argument("--threads", type=int, nargs="+", default=[2])
    ap.add_argument("--end-time", type=float, help="run (and predict) to this time [s]")
    ap.add_argument("--keep", metavar="DIR",
                    help="copy each run's summary.json to DIR/<case>_<threads>t.json")
    ap.add_argument("--repeat", type=int, default=1, help="predictions and runs per case (medians)")
    ap.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                    help="a case override for both the prediction and the run")
    a = ap.parse_intermixed_args()
    cases = a.cases or [os.path.join(ROOT, c) for c in SHIPPED]
    extra = ["--end-time", str(a.end_time)] if a.end_time else []
    for kv in a.set:
        extra += ["--set", kv]
    print("| case | threads | machine factors (water/sub-step/set-up) | fluid steps pred / run | sub-steps pred / run "
          "| rebuilds pred / run | wall pred / run stepping (process) [s] | error | solid phase pred / run [s] "
          "| CPU pred (1 thread) / run [s] | load before |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as tmp:
        for case in cases:
            for t in a.threads:
                load = open("/proc/loadavg").read().split()[0]
                ps, ms = [], []
                for _ in range(max(1, a.repeat)):
                    ps.append(predict(a.slamsph, case, t, extra))
                    ms.append(measure(a.slamsph, case, t, extra, os.path.join(tmp, "run")))
                s = ms[-1]["summary"]
                steps, subs = s["fluid_steps"], s["solid_substeps"]
                rebuilds = s["neighbour_rebuilds"]
                if a.keep:
                    os.makedirs(a.keep, exist_ok=True)
                    stem = os.path.splitext(os.path.basename(case))[0]
                    with open(os.path.join(a.keep, f"{stem}_{t}t.json"), "w") as f:
                        json.dump(s, f, indent=1)
                # The model predicts the time stepping (summary.json wall_seconds), not the
                # start-up (particles, lists) or the plots at the end (the process column).
                stepping = median([m["summary"]["wall_seconds"] for m in ms])
                solid = median([m["summary"]["time_split_s"]["solid_substeps"] for m in ms])
                wall = median([p["wall"] for p in ps])
                err = (wall - stepping) / stepping
                singles = ""
                if len(ms) > 1:
                    singles = " (" + ", ".join(
                        f"{100 * (p['wall'] - m['summary']['wall_seconds']) / m['summary']['wall_seconds']:+.0f}"
                        for p, m in zip(ps, ms)) + ")"
                p = ps[-1]
                name = os.path.relpath(case, ROOT) + "".join(f" {kv}" for kv in a.set)
                pred_subs = p["substeps_per_step"] * p["steps"]
                print(f"| {name} | {t} | {', '.join(q['machine'] for q in ps)} | {p['steps']} / {steps} | "
                      f"{pred_subs} / {subs} | {p['rebuilds']} / {rebuilds} | "
                      f"{wall:.3g} / {stepping:.3g} ({median([m['wall'] for m in ms]):.3g}) | "
                      f"{100 * err:+.0f} %{singles} | "
                      f"{median([q['solid'] for q in ps]):.3g} / {solid:.3g} | "
                      f"{median([q['cpu'] for q in ps]):.3g} / {median([m['cpu'] for m in ms]):.3g} | {load} |",
                      flush=True)


def median(xs):
    xs = sorted(xs)
    n = len(xs)
    return xs[n // 2] if n % 2 else 0.5 * (xs[n // 2 - 1] + xs[n // 2])


if __name__ == "__main__":
    main()
