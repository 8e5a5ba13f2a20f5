#!/usr/bin/env bash
# A ring half immersed in water, vibrating in its n = 2 mode (issue 10 item 6, issue 9;
# docs/validation.md §5; set-up and reference in tests/verification/test_app_wet_ring.cpp):
# wet frequency against the potential-flow Rayleigh–Ritz estimate, with suction (default
# fluid.cavitation_pressure) and with the old clamp p* >= 0, with gravity (floating ring,
# hydrostatic water) and without (water at zero pressure), at two water spacings, plus the
# dry ring and checks of c0, tank size and amplitude. Runs resume (OUT/runs.csv).
# Usage: scripts/validate_wet_ring.sh [OUT=results/wet_ring]
#   WET_CASES="name:VAR=value,VAR=value ..." overrides the list (VAR without SLAMSPH_WET_RING_).
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-results/wet_ring}
mkdir -p "$out"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target test_app_wet_ring -j"$(nproc)" >/dev/null
default="dry:WATER=0 g1_suction:GRAVITY=1 g1_clamp:GRAVITY=1,CAVITATION=0
g0_suction:GRAVITY=0 g0_clamp:GRAVITY=0,CAVITATION=0
g1_suction_dx5:GRAVITY=1,DX=0.005 g1_clamp_dx5:GRAVITY=1,CAVITATION=0,DX=0.005
g0_suction_dx5:GRAVITY=0,DX=0.005 g1_suction_c160:GRAVITY=1,C0=160
g1_suction_tank:GRAVITY=1,HALF_WIDTH=0.6,DEPTH=0.6 g0_suction_amp04:GRAVITY=0,AMPLITUDE=0.4
g0_suction_amp0025:GRAVITY=0,AMPLITUDE=0.025"
runs="$out/runs.csv"
[ -f "$runs" ] || echo "name,dx,c0,half_width,depth,water,gravity,cavitation,fluid,ring,f,f_dry,f_ritz,extrema,steps,substeps,leaked,max_wall_speed,seconds" >"$runs"
for c in ${WET_CASES:-$default}; do
  name=${c%%:*}
  vars=${c#*:}
  if grep -q "^$name," "$runs"; then continue; fi
  envs=()
  IFS=, read -ra kv <<<"$vars"
  for v in "${kv[@]}"; do envs+=("SLAMSPH_WET_RING_$v"); done
  line=$(env "${envs[@]}" ./build/tests/test_app_wet_ring --gtest_also_run_disabled_tests \
    --gtest_filter='WetRing.DISABLED_OneRun' | grep '^csv,' | cut -d, -f2-)
  echo "$name,$line" | tee -a "$runs"
done
python3 - "$runs" <<'PY'
import csv, sys
print("| run | dx [m] | c0 [m/s] | gravity | p_cav [Pa] | f [Hz] | vs Ritz | vs dry theory | fluid | steps | sub-steps | leaked | wall [s] |")
print("|" + " --- |" * 13)
for r in csv.DictReader(open(sys.argv[1])):
    f, fr, fd = float(r["f"]), float(r["f_ritz"]), float(r["f_dry"])
    print(f"| {r['name']} | {r['dx']} | {r['c0']} | {r['gravity']} | {r['cavitation']} | {f:.3f} | "
          f"{100 * (f / fr - 1):+.1f} % | {100 * (f / fd - 1):+.1f} % | {r['fluid']} | {r['steps']} | "
          f"{r['substeps']} | {r['leaked']} | {r['seconds']} |")
PY
