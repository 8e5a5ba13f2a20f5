#!/usr/bin/env bash
# The paper's case (§4.1; docs/validation.md §3), reported like with like: the shipped elastic
# cylinder entry (and its rigid twin) start 3 dx above the water at the free-fall speed that
# gives 2.33 m/s at the surface; slamsph's report (summary.json "validation",
# slamming_cs.csv, slamming_coefficient.png, entry_velocity.png) takes t0 = the geometric
# contact time and Cs = F/(rho V(t)^2 R) against s(t)/D from the body's path.
#  1. resolution study dx = 10, 5, 2.5 mm (the start gap kept at 3 dx, the speed at contact
#     at 2.33 m/s), h = 1.38 dx: peak (value, s/D, Cs, dx/s*, Mach) and mean Cs over s/D
#     0.05-0.25 and 0.05-0.15 against each reference, observed order and GCI (Roache, Fs 1.25
#     if monotone, else 3) of the means;
#  2. h = 1.3 dx against 1.38 at dx = 5 mm (the slamming force at the paper's h/dx);
#  3. the rigid twin at dx = 5 mm; the dual time stepping against one global step;
#  4. the tank echo: dx = 5 mm with a 0.1 m absorbing zone along the floor and both side
#     walls against the bare tank, max |F_zone - F_bare| and max F per window of t - t0.
# Usage: scripts/validate_cylinder.sh [THREADS=2] [OUT=results/validation_cylinder]
set -euo pipefail
cd "$(dirname "$0")/.."
threads=${1:-2}
out=${2:-results/validation_cylinder}
mkdir -p "$out"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target slamsph -j2 >/dev/null

run() {  # tag case dx [--set ...]
  local tag=$1 case_file=$2 dx=$3
  shift 3
  if [[ -f "$out/$tag/summary.json" ]] && grep -q '"status": "completed"' "$out/$tag/summary.json"; then
    return
  fi
  local cy v
  cy=$(python3 -c "print(0.5 + 3 * $dx)")
  v=$(python3 -c "print((2.33**2 - 2 * 9.81 * 3 * $dx) ** 0.5)")
  local t_start=$SECONDS
  ./build/slamsph run "$case_file" --dx "$dx" --set "body[1].shape.centre=[0.5,$cy]" \
    --set "body[1].velocity=[0,-$v]" --set output.vtk=false "$@" --out "$out/$tag" --overwrite \
    --threads "$threads" --quiet
  echo "$tag: $((SECONDS - t_start)) s wall"
}
el=cases/elastic_cylinder_entry.toml
run dx10 "$el" 0.01
run dx5 "$el" 0.005
run dx2.5 "$el" 0.0025
run dx5_h1.3 "$el" 0.005 --set numerics.h_over_dx=1.3
run dx5_global "$el" 0.005 --set numerics.dual_time_stepping=false
run rigid_dx5 cases/rigid_cylinder_entry.toml 0.005
run dx5_zone "$el" 0.005 --set fluid.absorbing_zone.left=0.1 --set fluid.absorbing_zone.right=0.1 \
  --set fluid.absorbing_zone.bottom=0.1

python3 - "$out" <<'PY'
import json, math, sys
out = sys.argv[1]
S = {t: json.load(open(f"{out}/{t}/summary.json")) for t in
     ["dx10", "dx5", "dx2.5", "dx5_h1.3", "dx5_global", "rigid_dx5"]}
def window(s, lo, hi):
    return next(w for w in s["validation"]["mean_Cs"] if w["s_over_D_range"] == [lo, hi])
def gci(f1, f2, f3):  # f1 finest; refinement ratio 2
    e21, e32 = f1 - f2, f2 - f3
    if e21 * e32 > 0 and e21 != 0:
        p = math.log(e32 / e21) / math.log(2)
        return p, 1.25 * abs(e21 / f1) / (2 ** p - 1)
    return float("nan"), 3.0 * abs(e21 / f1)
print("run        | V(t0) | peak N/m | t-t0 ms | s/D    | Cs    | dx/s* | Mach  | mean Cs .05-.25 | mean Cs .05-.15 | wall s")
for t, s in S.items():
    v, pk = s["validation"], s["validation"]["peak"]
    print(f"{t:10s} | {v['speed_at_contact_m_per_s']:.3f} | {pk['force_N_per_m']:8.0f} | "
          f"{1e3 * pk['t_minus_t0_s']:7.2f} | {pk['s_over_D']:.4f} | {pk['Cs']:.3f} | "
          f"{pk['dx_over_acoustic_depth']:5.1f} | {pk['mach']:.3f} | {window(s, .05, .25)['Cs']:.4f} | "
          f"{window(s, .05, .15)['Cs']:.4f} | {s['wall_seconds']:.0f}")
for lo, hi in [(0.05, 0.25), (0.05, 0.15)]:
    f3, f2, f1 = (window(S[t], lo, hi)["Cs"] for t in ["dx10", "dx5", "dx2.5"])
    p, g = gci(f1, f2, f3)
    print(f"mean Cs s/D {lo}-{hi}: {f3:.4f} / {f2:.4f} / {f1:.4f} (dx 10/5/2.5 mm), observed order "
          f"{p:.2f}, GCI {100 * g:.1f} % at dx 2.5 mm")
    for name, o in window(S["dx2.5"], lo, hi).items():
        if isinstance(o, dict) and isinstance(o.get("Cs"), float):
            kind = "2D" if o["two_dimensional"] else "3D fit"
            print(f"  vs {name} ({kind}) {o['Cs']:.4f}: {100 * o['relative_difference']:+.1f} %")
for tag, ref in [("dx5_h1.3", "dx5"), ("dx5_global", "dx5")]:
    a, b = S[tag]["validation"], S[ref]["validation"]
    print(f"{tag} vs {ref}: peak {100 * (a['peak']['force_N_per_m'] / b['peak']['force_N_per_m'] - 1):+.2f} %, "
          f"mean Cs .05-.25 {100 * (window(S[tag], .05, .25)['Cs'] / window(S[ref], .05, .25)['Cs'] - 1):+.2f} %, "
          f"wall {S[tag]['wall_seconds']:.0f} vs {S[ref]['wall_seconds']:.0f} s")
# Tank echo: the cylinder's Fy with and without the absorbing zone, per window of t - t0.
import csv
def fy(tag):
    rows = list(csv.reader(open(f"{out}/{tag}/forces.csv")))
    k = rows[0].index("cylinder Fy [N/m]")
    t0 = json.load(open(f"{out}/{tag}/summary.json"))["validation"]["t0_geometric_contact_s"]
    return [(float(r[0]) - t0, float(r[k])) for r in rows[1:]]
bare, zone = fy("dx5"), fy("dx5_zone")
print("tank echo (dx5_zone vs dx5): window t-t0 [ms] | max |dF| [N/m] | max F bare | max F zone")
for lo, hi in [(-10, 10), (10, 15), (15, 20), (22.5, 25), (25, 30), (40, 50)]:
    pairs = [(b, z) for (tb, b), (tz, z) in zip(bare, zone) if lo <= 1e3 * tb < hi]
    if pairs:
        print(f"  {lo:5.1f}-{hi:4.1f} | {max(abs(z - b) for b, z in pairs):8.2f} | "
              f"{max(b for b, _ in pairs):7.1f} | {max(z for _, z in pairs):7.1f}")
PY

cat > "$out/convergence.gp" <<'GP'
set terminal pngcairo noenhanced size 1000,650
set output 'convergence.png'
set datafile separator ','
set xlabel 'submergence s/D [-]'
set ylabel 'Cs = F/(rho V(t)^2 R) [-]'
set grid
set xrange [0:0.45]
set yrange [0:7]
plot 'dx10/slamming_cs.csv' skip 1 using 2:5 with lines title 'dx = 10 mm', \
     'dx5/slamming_cs.csv' skip 1 using 2:5 with lines title 'dx = 5 mm', \
     'dx2.5/slamming_cs.csv' skip 1 using 2:5 with lines lw 2 title 'dx = 2.5 mm', \
     'dx5_h1.3/slamming_cs.csv' skip 1 using 2:5 with lines dt 3 title 'dx = 5 mm, h = 1.3 dx', \
     'dx2.5/slamming_cs.csv' skip 1 using 2:6 with lines dt 2 lw 2 title 'Campbell-Weynberg (3D fit)', \
     'dx2.5/slamming_cs.csv' skip 1 using 2:7 with lines dt 4 lw 2 title 'von Karman (2D)', \
     'dx2.5/slamming_cs.csv' skip 1 using 2:10 with lines dt 5 lw 2 title 'modified Logvinovich (2D)'
GP
(cd "$out" && gnuplot convergence.gp)
echo "wrote $out/convergence.png"
