#!/usr/bin/env bash
# Polygon face fill against the Cartesian staircase (issue 10 item 1; docs/validation.md
# "Wedge entry"): cases/wedge_constant_speed.toml, a rigid 30-degree wedge at a constant
# 2 m/s, with [body.shape] fill = "faces" and "cartesian" at dx = 10, 5 and 2.5 mm (half-beam
# / dx = 10, 20, 40). The apex starts 3 dx above the surface (t0 = 3 dx / V). Post-processing
# (scripts/wedge_fill_ripple.py): rms ripple about a linear fit over tau = 3-15 ms and the
# fitted force slope against Wagner's wedge value. Runs already completed in OUT are reused.
# Usage: scripts/wedge_fill_ripple.sh [THREADS=1] [OUT=results/wedge_fill_ripple]
#        DXS="0.01 0.005" scripts/wedge_fill_ripple.sh ...   # a subset of spacings
set -euo pipefail
cd "$(dirname "$0")/.."
threads=${1:-1}
out=${2:-results/wedge_fill_ripple}
dxs=${DXS:-0.01 0.005 0.0025}
mkdir -p "$out"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target slamsph -j2 >/dev/null
V=2.0
args=()
for dx in $dxs; do
  for fill in faces cartesian; do
    tag="dx${dx}_${fill}"
    t0=$(python3 -c "print(3 * $dx / $V)")
    if ! { [[ -f "$out/$tag/summary.json" ]] && grep -q '"status": "completed"' "$out/$tag/summary.json"; }; then
      ya=$(python3 -c "print(0.4 + 3 * $dx)")
      yk=$(python3 -c "import math; print(0.4 + 3 * $dx + 0.1 * math.tan(math.radians(30)))")
      yt=$(python3 -c "print(0.4 + 3 * $dx + 0.12)")
      te=$(python3 -c "print($t0 + 0.015)")
      sed -e "s/^dx = 0.005 .*/dx = $dx/" -e "s/^end_time = .*/end_time = $te/" \
        -e "s/^fill = .*/fill = \"$fill\"/" \
        -e "s/^vertices = .*/vertices = [[0.4, $ya], [0.5, $yk], [0.5, $yt], [0.3, $yt], [0.3, $yk]]/" \
        -e "s/^\[output\]/[output]\nvtk = false/" cases/wedge_constant_speed.toml > "$out/$tag.toml"
      echo "run $tag ..."
      t_start=$SECONDS
      ./build/slamsph run "$out/$tag.toml" --out "$out/$tag" --overwrite --threads "$threads" --quiet
      echo "  $tag: $((SECONDS - t_start)) s"
    fi
    args+=("$out/$tag:$t0")
  done
done
python3 scripts/wedge_fill_ripple.py "$V" 30 "${args[@]}" | tee "$out/report.csv"
