#!/usr/bin/env bash
# Static plane-strain structures against CalculiX (issue 10 item 6; docs/validation.md §5):
# the T-joint in three-point bending and with its web bent sideways, the plain ring and the
# stiffened ring (fuselage builder) under diametral compression, at several layer counts, against tests/verification/data/ccx_static.csv. With --ccx the reference is
# first regenerated with scripts/calculix/static_cases.py (needs calculix-ccx) into
# OUT/ccx_static.csv and compared with the stored one. Runs resume (OUT/runs.csv).
# Usage: scripts/validate_static.sh [OUT=results/static] [--ccx]
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-results/static}
mkdir -p "$out"
if [ "${2:-}" = "--ccx" ]; then
  python3 scripts/calculix/static_cases.py "$out/ccx_static.csv" "$out/ccx"
  diff <(grep -v '^#' "$out/ccx_static.csv") <(grep -v '^#' tests/verification/data/ccx_static.csv) &&
    echo "CalculiX reference reproduced exactly"
fi
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target test_app_static_structures -j"$(nproc)" >/dev/null
runs="$out/runs.csv"
[ -f "$runs" ] || echo "case,layers,particles,q1,sph1,ccx1,q2,sph2,ccx2,seconds" >"$runs"
for c in ${STATIC_CASES:-t_joint:4 t_joint:6 t_joint:8 t_joint:12 t_joint_lateral:4 t_joint_lateral:6 t_joint_lateral:8 t_joint_lateral:12 ring:2 ring:3 ring:4 ring:6 stiffened_ring:2 stiffened_ring:4}; do
  IFS=: read -r name L <<<"$c"
  if grep -q "^$name,$L," "$runs"; then continue; fi
  SLAMSPH_STATIC_CASE=$name SLAMSPH_STATIC_LAYERS=$L ./build/tests/test_app_static_structures \
    --gtest_also_run_disabled_tests --gtest_filter='StaticStructures.DISABLED_OneRun' |
    grep '^csv,' | cut -d, -f2- | tee -a "$runs"
done
python3 - "$runs" <<'PY'
import csv, sys
print("| case | layers | particles | quantity | SPH [m] | CalculiX [m] | error | quantity | SPH [m] | CalculiX [m] | error | wall [s] |")
print("|" + " --- |" * 12)
for r in csv.DictReader(open(sys.argv[1])):
    e1 = 100 * (float(r["sph1"]) / float(r["ccx1"]) - 1)
    if float(r["ccx2"]) != 0.0:
        e2 = 100 * (float(r["sph2"]) / float(r["ccx2"]) - 1)
        q2 = f"{r['q2']} | {float(r['sph2']):.4e} | {float(r['ccx2']):.4e} | {e2:+.2f} %"
    else:
        q2 = "– | – | – | –"
    print(f"| {r['case']} | {r['layers']} | {r['particles']} | {r['q1']} | {float(r['sph1']):.4e} | "
          f"{float(r['ccx1']):.4e} | {e1:+.2f} % | {q2} | {r['seconds']} |")
PY
