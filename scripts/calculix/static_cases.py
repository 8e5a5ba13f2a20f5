#!/usr/bin/env python3
"""Static plane-strain references computed with CalculiX for the structural verification
(tests/verification/test_app_static_structures.cpp, docs/validation.md §5). Both bodies are
free and loaded by self-equilibrated tractions, so no support condition (whose discrete
position an SPH clamp only knows to ±dx/2) enters the comparison; ccx gets the symmetry
conditions that remove the rigid modes without reactions.

  t_joint: flange 200 x 10 mm (y in [-10, 0] mm), web 10 x 60 mm on its top centre;
           rubber-like E 2 MPa, nu 0.3. Three-point bending through the joint: pressure
           P/t_w on the web's top face (down), P/2 over 10 mm at each end of the flange's
           bottom face (up), P = 0.1 N/m (small strain).
  ring:    R/h = 20, h = 3 mm aluminium (E 67.5 GPa, nu 0.34), diametral compression by a
           pressure on the outer face over +-10 deg around the top and the bottom, total
           vertical force P = 2 p R_out sin(10 deg) = 1000 N/m each side.
  stiffened_ring_L: a ring D 120 mm, skin 3 mm, with 8 "I" stringers (height 9 mm, web 3 mm,
           flange 6 x 1.5 mm, first at 22.5 deg) on the fuselage builder's grid at L skin
           layers, the same diametral compression (patch +-(k+1/2) arc steps ~ 10 deg).
  t_joint_lateral: the same T-joint with its web bent sideways by Q = 0.1 N/m on its top
           face (balanced on the flange: see t_joint_lateral()).

usage: scripts/calculix/static_cases.py OUT.csv [WORKDIR]
Writes case,quantity,value (m): see QUANTITIES below; also the coarse-mesh values (half the
elements each way), to show the reference has converged.
"""
import math
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ccx_mesh  # noqa: E402

# T-joint (SI)
TJ = dict(L=0.2, tf=0.01, tw=0.01, hw=0.06, patch=0.01, P=0.1, Q=0.1, E=2.0e6, nu=0.3,
          rho=1000.0)
# Ring (SI)
RG = dict(h=0.003, r_over_h=20.0, alpha_deg=10.0, P=1000.0, E=67.5e9, nu=0.34, rho=2700.0)


def t_joint(e, workdir, job):
    m = ccx_mesh.Mesh()
    L, tf, tw, hw, pw = TJ["L"], TJ["tf"], TJ["tw"], TJ["hw"], TJ["patch"]
    xs = [-L / 2, -L / 2 + pw, -tw / 2, tw / 2, L / 2 - pw, L / 2]
    faces = {"web_top": [], "ends": []}
    nv = round(tf / e)
    for a in range(len(xs) - 1):
        x0, x1 = xs[a], xs[a + 1]
        nu = round((x1 - x0) / e)
        grid = ccx_mesh.add_block(m, lambda u, v: (x0 + (x1 - x0) * u, -tf + tf * v), nu, nv)
        if a in (0, len(xs) - 2):  # bottom faces (S1) of the end patches
            first = len(m.elements) - nu * nv
            faces["ends"] += [first + k * nv + 1 for k in range(nu)]
    nuw, nvw = round(tw / e), round(hw / e)
    ccx_mesh.add_block(m, lambda u, v: (-tw / 2 + tw * u, hw * v), nuw, nvw)
    first = len(m.elements) - nuw * nvw
    faces["web_top"] = [first + k * nvw + nvw for k in range(nuw)]  # top faces (S3)
    m.nsets["SYM"] = [n for n, (x, y) in m.nodes.items() if abs(x) < 1e-12]
    m.nsets["FIX"] = [n for n, (x, y) in m.nodes.items() if abs(x) < 1e-12 and abs(y - hw) < 1e-12]
    P = TJ["P"]
    step = ["*STEP", "*STATIC", "*BOUNDARY", "SYM, 1, 1, 0.", "FIX, 2, 2, 0.", "*DLOAD"]
    step += [f"{el}, P3, {P / tw:.12g}" for el in faces["web_top"]]
    step += [f"{el}, P1, {P / 2 / pw:.12g}" for el in faces["ends"]]
    step += ["*NODE PRINT, NSET=NALL", "U", "*END STEP"]
    m.nsets["NALL"] = list(m.nodes)
    ccx_mesh.write_inp(os.path.join(workdir, job + ".inp"), m,
                       {"E": TJ["E"], "nu": TJ["nu"], "rho": TJ["rho"]}, step)
    u = ccx_mesh.node_displacements(ccx_mesh.run_ccx(workdir, job))

    def mean_uy(pred):
        sel = [u[n][1] for n, (x, y) in m.nodes.items() if pred(x, y)]
        return sum(sel) / len(sel)
    ends = mean_uy(lambda x, y: abs(y + tf) < 1e-12 and abs(x) > L / 2 - pw - 1e-12)
    top = mean_uy(lambda x, y: abs(y - hw) < 1e-12)
    mid = mean_uy(lambda x, y: abs(y + tf) < 1e-12 and abs(x) < 1e-12)
    root = mean_uy(lambda x, y: abs(y) < 1e-12 and abs(x) < 1e-12)
    return {"web_top_minus_ends": top - ends, "flange_mid_minus_ends": mid - ends,
            "web_top_minus_root": top - root}


def t_joint_lateral(e, workdir, job):
    """The T-joint with the web bent sideways: a shear traction Q/t_w (+x) on the web's top
    face, balanced by -Q/L on the flange's bottom face and by the couple Q (h_w + t_f) carried
    by vertical pressures on the end patches (up at +x, down at -x). Measured: the area mean
    of u_x over the web above y = t_f (clear of the joint) minus that over the flange; the
    web bends as a cantilever rooted in the joint, so the joint's compliance is in it."""
    m = ccx_mesh.Mesh()
    L, tf, tw, hw, pw = TJ["L"], TJ["tf"], TJ["tw"], TJ["hw"], TJ["patch"]
    Q = TJ["Q"]
    xs = [-L / 2, -L / 2 + pw, -tw / 2, tw / 2, L / 2 - pw, L / 2]
    nv = round(tf / e)
    ends = {}
    for a in range(len(xs) - 1):
        x0, x1 = xs[a], xs[a + 1]
        nu = round((x1 - x0) / e)
        ccx_mesh.add_block(m, lambda u, v: (x0 + (x1 - x0) * u, -tf + tf * v), nu, nv)
        if a in (0, len(xs) - 2):
            first = len(m.elements) - nu * nv
            ends[a] = [first + k * nv + 1 for k in range(nu)]
    nflange = len(m.elements)
    nuw, nvw = round(tw / e), round(hw / e)
    ccx_mesh.add_block(m, lambda u, v: (-tw / 2 + tw * u, hw * v), nuw, nvw)
    # Consistent nodal forces of a uniform edge traction on quadratic edges: 1/6, 4/6, 1/6.
    cload = {}

    def edge_traction(y, x0, x1, t):
        nodes = sorted((x, n) for n, (x, yy) in m.nodes.items()
                       if abs(yy - y) < 1e-12 and x0 - 1e-12 <= x <= x1 + 1e-12)
        for k in range(0, len(nodes) - 2, 2):
            ell = nodes[k + 2][0] - nodes[k][0]
            for j, w in ((k, 1 / 6), (k + 1, 4 / 6), (k + 2, 1 / 6)):
                cload[nodes[j][1]] = cload.get(nodes[j][1], 0.0) + w * t * ell
    edge_traction(hw, -tw / 2, tw / 2, Q / tw)
    edge_traction(-tf, -L / 2, L / 2, -Q / L)
    F = Q * (hw + tf) / (L - pw)  # the couple's vertical forces, at the patch centres
    # ccx rigid modes: u_x fixed at the web top centre, u_y at the two patch-centre bottom nodes
    # would be reactions; instead fix a statically determinate set and check the reactions
    # vanish: u_x and u_y at the web-root centre, u_y at the right patch centre.
    root = [n for n, (x, y) in m.nodes.items() if abs(x) < 1e-12 and abs(y) < 1e-12]
    right = [n for n, (x, y) in m.nodes.items()
             if abs(x - (L / 2 - pw / 2)) < 1e-12 and abs(y + tf) < 1e-12]
    m.nsets["ROOT"] = root
    m.nsets["RIGHT"] = right
    m.nsets["NALL"] = list(m.nodes)
    step = ["*STEP", "*STATIC", "*BOUNDARY", "ROOT, 1, 2, 0.", "RIGHT, 2, 2, 0.", "*CLOAD"]
    step += [f"{n}, 1, {f:.12g}" for n, f in sorted(cload.items())]
    step += ["*DLOAD"]
    step += [f"{el}, P1, {F / pw:.12g}" for el in ends[len(xs) - 2]]
    step += [f"{el}, P1, {-F / pw:.12g}" for el in ends[0]]
    step += ["*NODE PRINT, NSET=NALL", "U", "*NODE PRINT, NSET=ROOT, TOTALS=ONLY", "RF",
             "*END STEP"]
    ccx_mesh.write_inp(os.path.join(workdir, job + ".inp"), m,
                       {"E": TJ["E"], "nu": TJ["nu"], "rho": TJ["rho"]}, step)
    dat = ccx_mesh.run_ccx(workdir, job)
    u = ccx_mesh.node_displacements(dat.split(" forces (fx,fy,fz)")[0])

    def weights(elements):
        # Area weights of the nodes: the integral of N_i over an 8-node serendipity rectangle
        # is -A/12 at corners and A/3 at mid-sides (the elements here are rectangles).
        out = []
        for eid, ns in elements:
            xs_ = [m.nodes[n][0] for n in ns[:4]]
            ys_ = [m.nodes[n][1] for n in ns[:4]]
            A = (max(xs_) - min(xs_)) * (max(ys_) - min(ys_))
            out += [(n, A * w) for n, w in zip(ns, [-1 / 12] * 4 + [1 / 3] * 4)]
        return out

    def mean(ws, f):
        return sum(w * f(n) for n, w in ws) / sum(w for n, w in ws)
    flange = weights(m.elements[:nflange])
    web = weights([(eid, ns) for eid, ns in m.elements[nflange:]
                   if sum(m.nodes[n][1] for n in ns[:4]) / 4 > tf])
    return {"web_minus_flange_ux": web_relative_to_flange(
        lambda f: mean(web, f), lambda f: mean(flange, f),
        lambda n: m.nodes[n], lambda n: u[n])}


def web_relative_to_flange(web_mean, flange_mean, X, u):
    """Mean u_x of the web relative to the flange's least-squares rigid motion (translation
    and rotation about its centroid), so the measure does not depend on how the rigid modes
    are fixed (ccx: a determinate support; SPH: a free body). The same definition is in
    tests/verification/test_app_static_structures.cpp."""
    xc = flange_mean(lambda n: X(n)[0])
    yc = flange_mean(lambda n: X(n)[1])
    ux = flange_mean(lambda n: u(n)[0])
    uy = flange_mean(lambda n: u(n)[1])
    num = flange_mean(lambda n: (X(n)[0] - xc) * (u(n)[1] - uy) - (X(n)[1] - yc) * (u(n)[0] - ux))
    den = flange_mean(lambda n: (X(n)[0] - xc) ** 2 + (X(n)[1] - yc) ** 2)
    theta = num / den
    # rigid field: u_r(X) = (ux, uy) + theta (-(Y - yc), X - xc)
    return web_mean(lambda n: u(n)[0] + theta * (X(n)[1] - yc)) - ux

def ring(n_radial, n_theta, workdir, job):
    h, R = RG["h"], RG["r_over_h"] * RG["h"]
    r_in, r_out = R - h / 2, R + h / 2
    mesh, grid = ccx_mesh.ring_mesh(r_in, r_out, n_radial, n_theta)
    alpha = math.radians(RG["alpha_deg"])
    dth = 2 * math.pi / n_theta
    k_alpha = alpha / dth
    if abs(k_alpha - round(k_alpha)) > 1e-9 or n_theta % 4:
        raise SystemExit("ring mesh: patch edges must fall on element edges")
    p = RG["P"] / (2 * r_out * math.sin(alpha))
    # Element (a, b) spans theta in [b dth, (b+1) dth]; its outer face is S2 (nodes 2-3).
    loaded = []
    for b in range(n_theta):
        mid = (b + 0.5) * dth
        for centre in (math.pi / 2, 3 * math.pi / 2):
            if abs(mid - centre) < alpha:
                loaded.append((n_radial - 1) * n_theta + b + 1)
    mesh.nsets["XSYM"] = [n for n, (x, y) in mesh.nodes.items() if abs(x) < 1e-9 * R]
    mesh.nsets["YSYM"] = [n for n, (x, y) in mesh.nodes.items() if abs(y) < 1e-9 * R]
    mesh.nsets["NALL"] = list(mesh.nodes)
    step = ["*STEP", "*STATIC", "*BOUNDARY", "XSYM, 1, 1, 0.", "YSYM, 2, 2, 0.", "*DLOAD"]
    step += [f"{el}, P2, {p:.12g}" for el in loaded]
    step += ["*NODE PRINT, NSET=NALL", "U", "*END STEP"]
    ccx_mesh.write_inp(os.path.join(workdir, job + ".inp"), mesh,
                       {"E": RG["E"], "nu": RG["nu"], "rho": RG["rho"]}, step)
    u = ccx_mesh.node_displacements(ccx_mesh.run_ccx(workdir, job))
    mid_i = n_radial  # grid row of the mid-surface

    def radial(j):
        n = grid[mid_i][j % (2 * n_theta)]
        x, y = mesh.nodes[n]
        r = math.hypot(x, y)
        return (u[n][0] * x + u[n][1] * y) / r
    q = n_theta // 2  # grid columns per quarter turn (2 per element)
    return {"horizontal_diameter_change": radial(0) + radial(2 * q),
            "vertical_diameter_change": radial(q) + radial(3 * q)}


# Stiffened ring: a skin with 8 "I" stringers, the continuum the fuselage section builder
# (geometry/fuselage_section.cpp) discretises: one polar grid of n = c round(2 pi r_mid /
# (d c)) arc steps for skin and stringers, stringer webs and flanges whole numbers of arc
# steps (measured on the inner skin face) centred on the stringer angle, rows of depth d.
# The grid depends on the layer count, so the reference is computed per layer count.
SR = dict(D=0.12, t=0.003, count=8, height=0.009, web=0.003, flange=0.006, flange_t=0.0015,
          offset_deg=22.5, P=1000.0, E=67.5e9, nu=0.34, rho=2700.0)


def stiffened_ring_grid(layers):
    d = SR["t"] / layers
    r_out = SR["D"] / 2
    r_in = r_out - SR["t"]
    r_mid = r_out - SR["t"] / 2
    c = SR["count"]
    n = c * max(1, round(2 * math.pi * r_mid / (d * c)))
    dth = 2 * math.pi / n
    arc_in = r_in * dth
    m_w, m_f = round(SR["web"] / arc_in), round(SR["flange"] / arc_in)
    if m_w < 2 or m_f < m_w + 1 or (m_f - m_w) % 2:
        raise SystemExit(f"stiffened ring at {layers} layers: web {m_w}, flange {m_f} arc steps")
    rows, rows_f = round(SR["height"] / d), round(SR["flange_t"] / d)
    phase = 0.5 if m_w % 2 == 0 else 0.0
    th0 = math.radians(SR["offset_deg"])
    # Cells (r_lo, r_hi, j): angular extent th0 + (j + phase -/+ 1/2) dth.
    cells = [(r_in + k * d, r_in + (k + 1) * d, j) for k in range(layers) for j in range(n)]
    per = n // c
    for s_ in range(c):
        for q in range(rows):
            flange = q < rows_f or q >= rows - rows_f
            m = m_f if flange else m_w
            for j in range(-(m // 2), -(m // 2) + m):
                cells.append((r_in - (q + 1) * d, r_in - q * d, s_ * per + j))
    k_patch = round(math.radians(10.0) / dth - 0.5)
    alpha = (k_patch + 0.5) * dth  # patch edges on cell edges (90 deg is a cell centre)
    return dict(d=d, r_in=r_in, r_out=r_out, n=n, dth=dth, th0=th0, phase=phase, cells=cells,
                alpha=alpha, m_w=m_w, m_f=m_f, rows=rows, rows_f=rows_f)


def stiffened_ring(layers, sub, workdir, job):
    g = stiffened_ring_grid(layers)
    n, dth, th0, phase = g["n"], g["dth"], g["th0"], g["phase"]
    mesh = ccx_mesh.Mesh()
    p = SR["P"] / (2 * g["r_out"] * math.sin(g["alpha"]))
    loaded = []
    for (lo, hi, j) in g["cells"]:
        a0 = th0 + (j + phase - 0.5) * dth

        def mapping(u, v, lo=lo, hi=hi, a0=a0):
            r, a = lo + (hi - lo) * u, a0 + dth * v
            return (r * math.cos(a), r * math.sin(a))
        first = len(mesh.elements)
        ccx_mesh.add_block(mesh, mapping, sub, sub)
        if abs(hi - g["r_out"]) < 1e-12:
            mid = th0 + (j + phase) * dth
            for centre in (math.pi / 2, 3 * math.pi / 2):
                dd = math.remainder(mid - centre, 2 * math.pi)
                if abs(dd) < g["alpha"]:
                    loaded += [first + (sub - 1) * sub + b + 1 for b in range(sub)]  # S2: r = hi
    R = g["r_out"]
    mesh.nsets["XSYM"] = [k for k, (x, y) in mesh.nodes.items() if abs(x) < 1e-9 * R]
    mesh.nsets["YSYM"] = [k for k, (x, y) in mesh.nodes.items() if abs(y) < 1e-9 * R]
    mesh.nsets["NALL"] = list(mesh.nodes)
    step = ["*STEP", "*STATIC", "*BOUNDARY", "XSYM, 1, 1, 0.", "YSYM, 2, 2, 0.", "*DLOAD"]
    step += [f"{el}, P2, {p:.12g}" for el in loaded]
    step += ["*NODE PRINT, NSET=NALL", "U", "*END STEP"]
    ccx_mesh.write_inp(os.path.join(workdir, job + ".inp"), mesh,
                       {"E": SR["E"], "nu": SR["nu"], "rho": SR["rho"]}, step)
    u = ccx_mesh.node_displacements(ccx_mesh.run_ccx(workdir, job))
    r_mid = g["r_in"] + SR["t"] / 2

    def radial(th):
        x, y = r_mid * math.cos(th), r_mid * math.sin(th)
        k = min(mesh.nodes, key=lambda q: (mesh.nodes[q][0] - x) ** 2 + (mesh.nodes[q][1] - y) ** 2)
        X, Y = mesh.nodes[k]
        if math.hypot(X - x, Y - y) > 1e-9:
            raise SystemExit(f"no node on the mid-skin at {math.degrees(th)} deg")
        return (u[k][0] * X + u[k][1] * Y) / r_mid
    return {"horizontal_diameter_change": radial(0.0) + radial(math.pi),
            "vertical_diameter_change": radial(math.pi / 2) + radial(3 * math.pi / 2)}


def thin_ring_diameters():
    """Thin ring, two opposite point loads P (Roark, table 9.2 case 1): the horizontal
    diameter grows by (2/pi - 1/2) P R^3/(EI), the vertical one shrinks by (pi/4 - 2/pi)
    P R^3/(EI); plane strain EI = E h^3/(12(1-nu^2))."""
    h, R = RG["h"], RG["r_over_h"] * RG["h"]
    EI = RG["E"] * h**3 / (12 * (1 - RG["nu"] ** 2))
    c = RG["P"] * R**3 / EI
    return c * (2 / math.pi - 0.5), -c * (math.pi / 4 - 2 / math.pi)


def main():
    out = sys.argv[1]
    workdir = sys.argv[2] if len(sys.argv) > 2 else os.path.join(os.path.dirname(out) or ".",
                                                                 "ccx_static")
    os.makedirs(workdir, exist_ok=True)
    rows = []
    fine = t_joint(0.000625, workdir, "t_joint_fine")
    coarse = t_joint(0.00125, workdir, "t_joint_coarse")
    for k in fine:
        rows.append(("t_joint", k, fine[k], coarse[k]))
    fine = t_joint_lateral(0.000625, workdir, "t_joint_lateral_fine")
    coarse = t_joint_lateral(0.00125, workdir, "t_joint_lateral_coarse")
    for k in fine:
        rows.append(("t_joint_lateral", k, fine[k], coarse[k]))
    n_theta = 720  # 0.5 deg elements: the 10 deg patch is 20 elements
    fine = ring(4, n_theta, workdir, "ring_fine")
    coarse = ring(2, n_theta // 2, workdir, "ring_coarse")
    for k in fine:
        rows.append(("ring", k, fine[k], coarse[k]))
    for layers in (2, 4):
        # Each particle cell in 8/L x 8/L elements (0.375 mm; coarse: 0.75 mm).
        fine = stiffened_ring(layers, 8 // layers, workdir, f"stiffened_{layers}_fine")
        coarse = stiffened_ring(layers, 4 // layers, workdir, f"stiffened_{layers}_coarse")
        for k in fine:
            rows.append((f"stiffened_ring_{layers}", k, fine[k], coarse[k]))
    dh, dv = thin_ring_diameters()
    with open(out, "w") as f:
        f.write("# scripts/calculix/static_cases.py: plane strain, CPE8; t_joint 0.625 mm elements "
                "(coarse 1.25 mm), ring 4 x 720 (coarse 2 x 360), stiffened rings 0.375 mm "
                "(coarse 0.75 mm)\n")
        f.write(f"# thin ring, point loads: horizontal {dh:.6e} m, vertical {dv:.6e} m\n")
        f.write("case,quantity,value,coarse\n")
        for r in rows:
            f.write(f"{r[0]},{r[1]},{r[2]:.9e},{r[3]:.9e}\n")
    for r in rows:
        print(f"{r[0]} {r[1]}: {r[2]:.6e} m (coarse {r[3]:.6e}, {100 * (r[3] / r[2] - 1):+.3f} %)")
    print(f"thin ring (point loads): horizontal {dh:.6e}, vertical {dv:.6e}")


if __name__ == "__main__":
    main()
