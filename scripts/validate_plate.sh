#!/usr/bin/env bash
# Oscillating cantilever plate (Gray et al. 2001; validation README §5): runs
# cases/oscillating_plate.toml (or with --dx DX) and prints the tip frequency and amplitude
# against thin-plate theory (3.94 Hz, V_f c0/omega = 23.06 mm). Plot: OUT/plate_tip.png.
# Usage: scripts/validate_plate.sh [DX=0.0016666666666666668] [OUT=results/oscillating_plate]
set -euo pipefail
cd "$(dirname "$0")/.."
dx=${1:-0.0016666666666666668}
out=${2:-results/oscillating_plate}
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target slamsph -j"$(nproc)" >/dev/null
./build/slamsph run cases/oscillating_plate.toml --dx "$dx" --out "$out" --overwrite --threads 1 --quiet
python3 - "$out" <<'PY'
import csv, sys
rows = list(csv.reader(open(f"{sys.argv[1]}/probes.csv")))
c = rows[0].index("tip_y [m]")
t = [float(r[0]) for r in rows[1:]]
y = [float(r[c]) for r in rows[1:]]
z = [t[k] + (t[k + 1] - t[k]) * y[k] / (y[k] - y[k + 1])
     for k in range(1, len(y) - 1) if (y[k] > 0) != (y[k + 1] > 0)]
f = (len(z) - 1) / 2 / (z[-1] - z[0])
print("frequency %.3f Hz (theory 3.94 Hz: %+.1f %%), amplitude %.2f mm (V_f c0/omega = 23.06 mm)"
      % (f, 100 * (f / 3.94 - 1), 1000 * max(abs(v) for v in y)))
PY
