#!/usr/bin/env bash
# Dam break (Martin & Moyce geometry, a = 0.5 m; validation README §2) at a/dx = 25 (CI's
# resolution), 50 (the shipped case) and 100: the surge-front error against Martin & Moyce
# 1952 and Koshizuka & Oka 1996 for T <= 2.5, and the start-up delay (in T) after which the
# front matches best (`best_start_delay_T` in summary.json; a diagnostic, docs/validation.md
# §3). Table: OUT/convergence.csv; plot: OUT/surge_front_convergence.png.
# Usage: scripts/validate_dam_break.sh [THREADS=2] [OUT=results/validation_dam_break]
set -euo pipefail
cd "$(dirname "$0")/.."
threads=${1:-2}
out=${2:-results/validation_dam_break}
mkdir -p "$out"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target slamsph -j"$(nproc)" >/dev/null
for spec in "25 0.02" "50 0.01" "100 0.005"; do
  set -- $spec
  ./build/slamsph run cases/dam_break.toml --dx "$2" --out "$out/a_dx$1" --overwrite --threads "$threads" \
    --quiet 2>/dev/null
done

python3 - "$out" <<'PY'
import json, sys
out = sys.argv[1]
rows = ["a/dx,MM max [-],MM rms [-],MM at T [-],MM best delay T [-],MM max after delay [-],"
        "KO max [-],KO rms [-],KO best delay T [-],KO max after delay [-],wall [s]"]
for n in (25, 50, 100):
    s = json.load(open(f"{out}/a_dx{n}/summary.json"))
    mm, ko = s["validation"]["Martin & Moyce 1952"], s["validation"]["Koshizuka & Oka 1996"]
    m, r = "front_max_relative_error_T_le_2.5", "front_rms_relative_error_T_le_2.5"
    a = "front_max_relative_error_T_le_2.5_after_delay"
    rows.append(f"{n},{mm[m]:.4f},{mm[r]:.4f},{mm['at_T']},{mm['best_start_delay_T']:.2f},{mm[a]:.4f},"
                f"{ko[m]:.4f},{ko[r]:.4f},{ko['best_start_delay_T']:.2f},{ko[a]:.4f},"
                f"{s['wall_seconds']:.1f}")
open(f"{out}/convergence.csv", "w").write("\n".join(rows) + "\n")
print("\n".join(rows))
PY
cat > "$out/surge_front_convergence.gp" <<'GP'
set terminal pngcairo size 1000,650
set output 'surge_front_convergence.png'
set datafile separator ','
set xlabel 'T = t sqrt(2g/a)'
set ylabel 'Z = x/a'
set grid
set key left top
s = sqrt(2 * 9.81 / 0.5)
set xrange [0:3]
$mm << EOD
0.41,1.11
0.84,1.23
1.19,1.44
1.43,1.67
1.63,1.89
1.82,2.11
1.97,2.33
2.20,2.56
2.32,2.78
2.50,3.00
2.64,3.22
2.82,3.44
2.96,3.67
EOD
$ko << EOD
0,1
0.381,1.111
0.769,1.252
1.153,1.505
1.537,1.892
1.935,2.241
2.323,2.615
2.719,3.003
3.096,3.624
EOD
plot 'a_dx25/probes.csv' every ::1 using ($1*s):($2/0.5) with lines title 'a/dx = 25', \
     'a_dx50/probes.csv' every ::1 using ($1*s):($2/0.5) with lines title 'a/dx = 50', \
     'a_dx100/probes.csv' every ::1 using ($1*s):($2/0.5) with lines title 'a/dx = 100', \
     $mm using 1:2 with points pt 7 title 'Martin and Moyce 1952', \
     $ko using 1:2 with points pt 5 title 'Koshizuka and Oka 1996'
GP
(cd "$out" && gnuplot surge_front_convergence.gp)
echo "wrote $out/convergence.csv and $out/surge_front_convergence.png"
