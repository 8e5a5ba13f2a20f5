#!/usr/bin/env bash
# Notched plane-strain Al 2024-T3 specimen pulled until it breaks (issue 11 "Failure";
# docs/validation.md "Johnson–Cook notched specimen"): the long version of
# tests/verification/test_app_johnson_cook_notched.cpp at the case's own resolution.
#  1. the test at dx = 0.25 mm and ±1 m/s grips: the first failed particle's Johnson–Cook
#     damage integral of its own (triaxiality, rate) history against 1, where it fails against
#     where the triaxiality peaks, and the energy balance against the grips' work;
#  2. `slamsph run cases/johnson_cook_notched.toml`: failure.csv, summary.json "failures" and
#     energy.csv (the recorder's clamp_work column and residual).
# Usage: scripts/validate_notched.sh [OUT=results/johnson_cook_notched]
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-results/johnson_cook_notched}
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target slamsph test_app_johnson_cook_notched -j"$(nproc)" >/dev/null
SLAMSPH_NOTCHED_DX=0.00025 SLAMSPH_NOTCHED_V=1.0 SLAMSPH_NOTCHED_AFTER=2e-6 \
  ./build/tests/test_app_johnson_cook_notched || true
./build/slamsph run cases/johnson_cook_notched.toml --out "$out" --overwrite --threads 1 --quiet
python3 - "$out" <<'PY'
import csv, json, sys
out = sys.argv[1]
rows = list(csv.reader(open(f"{out}/failure.csv")))
h = rows[0]
print(f"failure.csv: {len(rows) - 1} failed particles; first at t = {float(rows[1][0]) * 1e6:.2f} us,",
      ", ".join(f"{k} {rows[1][i]}" for i, k in enumerate(h) if k.split(" [")[0] in
                ("x", "y", "triaxiality", "plastic_strain_rate", "equivalent_plastic_strain")))
e = list(csv.reader(open(f"{out}/energy.csv")))
eh = e[0]
cw = eh.index("specimen clamp_work [J/m]")
rs = eh.index("specimen residual [J/m]")
t_fail = float(rows[1][0])
before = [r for r in e[1:] if float(r[0]) < t_fail]
w = float(before[-1][cw])
print(f"energy.csv: grips' work {w:.5g} J/m at the first failure, max |residual| before it "
      f"{max(abs(float(r[rs])) for r in before):.3g} J/m "
      f"({max(abs(float(r[rs])) for r in before) / w:.2%}); at the end {float(e[-1][cw]):.5g} J/m, "
      f"residual {float(e[-1][rs]):.3g} J/m ({float(e[-1][rs]) / float(e[-1][cw]):.2%})")
s = json.load(open(f"{out}/summary.json"))
print("summary.json failures:", json.dumps(s.get("failures")))
PY
