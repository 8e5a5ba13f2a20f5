#!/usr/bin/env bash
# Water coarser than the structure (issue 10 item 2; docs/model.md §4, "Bodies finer than the
# water"): the rigid cylinder of cases/cylinder_constant_speed.toml (D = 0.2 m, 2.33 m/s,
# c0/V = 15) at D/dx = DDX (default 40) with the cylinder r = 1, 2, 4, 8 times finer than the
# water (case key body[1].spacing_ratio). Post-processing (scripts/spacing_ratio_report.py):
# the impulse over s/D 0.02-0.25, the mean Cs over 0.02-0.1 and 0.1-0.25 and the peak Cs per
# ratio and their differences to r = 1; exit status 1 if an impulse differs by more than TOL
# (default 0.035). Runs already completed in OUT are reused. Usage:
#   scripts/validate_spacing_ratio.sh [THREADS=2] [OUT=results/validation_spacing_ratio]
#   DDX=20 RATIOS="1 2 4" TOL=0.01 scripts/validate_spacing_ratio.sh ...
# Measured (1 thread, shared machine): D/dx = 40, r = 1, 2, 4, 8: 83, 89, 31, 48 s.
set -euo pipefail
cd "$(dirname "$0")/.."
threads=${1:-2}
out=${2:-results/validation_spacing_ratio}
ddx=${DDX:-40}
ratios=${RATIOS:-1 2 4 8}
tol=${TOL:-0.035}
mkdir -p "$out"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target slamsph -j2 >/dev/null
V=2.33
D=0.2
dx=$(python3 -c "print($D / $ddx)")
cy=$(python3 -c "print(0.7 + 3 * $D / $ddx)")       # lowest point 3 dx above the free surface
te=$(python3 -c "print(3 * $D / $ddx / $V + 0.026)")  # contact time + 26 ms (s/D = 0.30)
for r in $ratios; do
  tag="r$r"
  if [[ -f "$out/$tag/summary.json" ]] && grep -q '"status": "completed"' "$out/$tag/summary.json"; then
    continue
  fi
  echo "run $tag (water dx = $dx m, cylinder dx = $dx / $r) ..."
  t_start=$SECONDS
  ./build/slamsph run cases/cylinder_constant_speed.toml --set "numerics.dx=$dx" \
    --set "body[1].spacing_ratio=$r" --set "body[1].shape.centre=[0.6, $cy]" \
    --set "numerics.end_time=$te" --set output.vtk=false \
    --out "$out/$tag" --overwrite --threads "$threads" --quiet
  echo "  $tag: $((SECONDS - t_start)) s"
done
python3 scripts/spacing_ratio_report.py "$out" "$V" "$D" "$dx" "$tol"
