// Output fields of a solid body (declared in solid/body_dynamics.h). Equivalent strain is
// the von Mises equivalent of the Green–Lagrange strain (plane strain, E_zz = 0):
// sqrt(2/3 dev(E):dev(E)). Cauchy stress and pressure include the plane-strain σ_zz of the
// material law (solid/stress_update.h); the law's history fields marked for output follow
// under their own names and units. Symmetric tensors have 6 components in VTK's order
// (xx, yy, zz, xy, yz, xz) so that ParaView shows them as tensors; plane strain makes
// E_zz = 0 and yz = xz = 0.
#include "solid/body_dynamics.h"
#include "solid/materials/st_venant_kirchhoff.h"
#include "solid/stress_update.h"

namespace slamsph {

std::vector<SolidField> solid_output_fields(const SolidBody& body) {
  const std::size_t n = body.size();
  std::vector<SolidField> out;
  SolidField disp{"displacement", "m", 2, {}}, vel{"velocity", "m/s", 2, {}};
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 u = body.x[i] - body.X[i];
    disp.values.insert(disp.values.end(), {u.x, u.y});
    vel.values.insert(vel.values.end(), {body.v[i].x, body.v[i].y});
  }
  out.push_back(std::move(disp));
  out.push_back(std::move(vel));
  if (!body.is_elastic() || body.F.size() != n) return out;

  SolidField F{"deformation_gradient", "-", 4, {}}, E{"green_lagrange_strain", "-", 6, {}};
  SolidField eq{"equivalent_strain", "-", 1, {}}, P{"pk1_stress", "Pa", 4, {}};
  SolidField sig{"cauchy_stress", "Pa", 6, {}}, vm{"von_mises_stress", "Pa", 1, {}};
  SolidField pr{"pressure", "Pa", 1, {}};
  for (std::size_t i = 0; i < n; ++i) {
    const Mat2& f = body.F[i];
    const Mat2& p = body.P[i];
    const Mat2 e = green_lagrange(f);
    const CauchyStress s = cauchy_from_pk1(p, f, cauchy_zz(body, i));
    F.values.insert(F.values.end(), {f.xx, f.xy, f.yx, f.yy});
    E.values.insert(E.values.end(), {e.xx, e.yy, 0.0, e.xy, 0.0, 0.0});
    eq.values.push_back(equivalent_strain(e));
    P.values.insert(P.values.end(), {p.xx, p.xy, p.yx, p.yy});
    sig.values.insert(sig.values.end(), {s.xx, s.yy, s.zz, s.xy, 0.0, 0.0});
    vm.values.push_back(von_mises_stress(s));
    pr.values.push_back(pressure(s));
  }
  for (SolidField* f : {&F, &E, &eq, &P, &sig, &vm, &pr}) out.push_back(std::move(*f));
  const MaterialHistory& h = body.history;
  for (std::size_t k = 0; k < h.fields.size(); ++k)
    if (h.fields[k].output)
      out.push_back({std::string(h.fields[k].name), std::string(h.fields[k].unit), 1, h.values[k]});
  return out;
}

}  // namespace slamsph
