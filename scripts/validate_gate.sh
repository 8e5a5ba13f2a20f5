#!/usr/bin/env bash
# Elastic gate (Antoci et al. 2007; validation README §6): runs cases/elastic_gate.toml and
# prints the peak horizontal and vertical tip displacement against the experiment
# (about 40 mm at 0.15-0.2 s; 12-14 mm). Plot: OUT/gate_tip.png.
# Usage: scripts/validate_gate.sh [THREADS=2] [OUT=results/elastic_gate]
set -euo pipefail
cd "$(dirname "$0")/.."
threads=${1:-2}
out=${2:-results/elastic_gate}
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target slamsph -j"$(nproc)" >/dev/null
./build/slamsph run cases/elastic_gate.toml --out "$out" --overwrite --threads "$threads" --quiet
python3 - "$out" <<'PY'
import csv, json, sys
out = sys.argv[1]
rows = list(csv.reader(open(f"{out}/probes.csv")))
h = rows[0]
cx, cy = h.index("gate_tip_x [m]"), h.index("gate_tip_y [m]")
d = [list(map(float, r)) for r in rows[1:]]
px = max(d, key=lambda r: r[cx])
py = max(d, key=lambda r: abs(r[cy]))
s = json.load(open(f"{out}/summary.json"))
print("peak horizontal tip displacement %.1f mm at %.3f s (experiment ~40 mm at 0.15-0.2 s: %+.0f %%)"
      % (1000 * px[cx], px[0], 100 * (px[cx] / 0.040 - 1)))
print("peak vertical tip displacement %.1f mm at %.3f s (experiment 12-14 mm)" % (1000 * py[cy], py[0]))
print("leaked particles %d, wall %.0f s on %d threads" % (s["leaked_particles"], s["wall_seconds"], s["threads"]))
PY
