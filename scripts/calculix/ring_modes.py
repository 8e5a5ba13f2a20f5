#!/usr/bin/env python3
"""Exact plane-strain in-plane modes of a free ring with CalculiX (ccx *FREQUENCY): the
reference of the dry ring-mode verification (tests/verification/test_app_ring_modes.cpp,
docs/validation.md §5). Thin-ring theory neglects shear and rotary inertia; this is the
continuum the SPH ring discretises.

usage: scripts/calculix/ring_modes.py OUT.csv [WORKDIR]
Writes r_over_h, n, f_ccx (fine mesh), f_ccx_coarse (half the elements each way), f_thin.
"""
import math
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ccx_mesh  # noqa: E402

E, NU, RHO, H = 67.5e9, 0.34, 2700.0, 0.003  # the paper's aluminium skin (§4.2), 3 mm


def thin_ring(n, R):
    D = E * H**3 / (12 * (1 - NU**2))
    return n * (n * n - 1) / (2 * math.pi * R * R) * math.sqrt(D / (RHO * H * (n * n + 1)))


def ccx_modes(r_over_h, n_radial, n_theta, workdir):
    R = r_over_h * H
    mesh, _ = ccx_mesh.ring_mesh(R - H / 2, R + H / 2, n_radial, n_theta)
    job = f"ring_{r_over_h:g}_{n_radial}x{n_theta}"
    f_low = 0.05 * thin_ring(2, R)  # shift below n = 2: skips the three rigid modes
    step = ["*STEP", "*FREQUENCY", f"16, {f_low:.6g}", "*END STEP"]
    ccx_mesh.write_inp(os.path.join(workdir, job + ".inp"), mesh,
                       {"E": E, "nu": NU, "rho": RHO}, step)
    freqs = sorted(f for f in ccx_mesh.eigenfrequencies(ccx_mesh.run_ccx(workdir, job))
                   if f > f_low)
    # Ovalling modes come in degenerate pairs (cos nθ, sin nθ): n = 2 is the first pair,
    # n = 3 the second.
    return {2: freqs[0], 3: freqs[2]}, (freqs[0], freqs[1], freqs[2], freqs[3])


def main():
    out = sys.argv[1]
    workdir = sys.argv[2] if len(sys.argv) > 2 else os.path.join(os.path.dirname(out), "ccx_ring")
    os.makedirs(workdir, exist_ok=True)
    rows = []
    for r_over_h in (20, 100):
        n_theta = int(12 * r_over_h)  # element arc length ~ h/2 on the mid-surface
        fine, pairs = ccx_modes(r_over_h, 4, n_theta, workdir)
        coarse, _ = ccx_modes(r_over_h, 2, n_theta // 2, workdir)
        for a, b in ((0, 1), (2, 3)):
            if abs(pairs[a] / pairs[b] - 1) > 1e-4:
                raise SystemExit(f"R/h {r_over_h}: modes are not in pairs: {pairs}")
        for n in (2, 3):
            rows.append((r_over_h, n, fine[n], coarse[n], thin_ring(n, r_over_h * H)))
    with open(out, "w") as f:
        f.write("# scripts/calculix/ring_modes.py: free ring, plane strain, E 67.5 GPa, nu 0.34, "
                "rho 2700, h 3 mm; CPE8 4 x 12R/h elements (coarse: 2 x 6R/h)\n")
        f.write("r_over_h,n,f_ccx,f_ccx_coarse,f_thin\n")
        for r in rows:
            f.write(f"{r[0]},{r[1]},{r[2]:.6f},{r[3]:.6f},{r[4]:.6f}\n")
    for r in rows:
        print(f"R/h {r[0]} n {r[1]}: ccx {r[2]:.4f} Hz (coarse {r[3]:.4f}), thin ring {r[4]:.4f} "
              f"Hz, thin-ring error {100 * (r[4] / r[2] - 1):+.3f} %")


if __name__ == "__main__":
    main()
