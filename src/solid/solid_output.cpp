// Output fields of a solid body (declared in solid/body_dynamics.h). Equivalent strain is
// the von Mises equivalent of the Green–Lagrange strain (plane strain, E_zz = 0):
// sqrt(2/3 dev(E):dev(E)). Cauchy stress and pressure include the plane-strain σ_zz of the
// material law (solid/stress_update.h). Stored fields (velocity, F, P, the fluid force and
// the law's history fields marked for output) are not listed here: they are flagged for
// VTK in SolidBody::visit_fields (core/field_registry.h). Symmetric tensors have 6 components in
// VTK's order (xx, yy, zz, xy, yz, xz) so that ParaView shows them as tensors; plane strain makes
// E_zz = 0 and yz = xz = 0.
#include "solid/body_dynamics.h"
#include "solid/materials/st_venant_kirchhoff.h"
#include "solid/stress_update.h"

namespace slamsph {

std::vector<SolidField> solid_output_fields(const SolidBody& body) {
  const std::size_t n = body.size();
  std::vector<SolidField> out;
  SolidField disp{"displacement", "m", 2, {}};
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 u = body.x[i] - body.X[i];
    disp.values.insert(disp.values.end(), {u.x, u.y});
  }
  out.push_back(std::move(disp));
  if (!body.is_elastic() || body.F.size() != n) return out;

  SolidField E{"green_lagrange_strain", "-", 6, {}}, eq{"equivalent_strain", "-", 1, {}};
  SolidField sig{"cauchy_stress", "Pa", 6, {}}, vm{"von_mises_stress", "Pa", 1, {}};
  SolidField pr{"pressure", "Pa", 1, {}};
  for (std::size_t i = 0; i < n; ++i) {
    const Mat2& f = body.F[i];
    const Mat2& p = body.P[i];
    const Mat2 e = green_lagrange(f);
    const CauchyStress s = cauchy_from_pk1(p, f, cauchy_zz(body, i));
    E.values.insert(E.values.end(), {e.xx, e.yy, 0.0, e.xy, 0.0, 0.0});
    eq.values.push_back(equivalent_strain(e));
    sig.values.insert(sig.values.end(), {s.xx, s.yy, s.zz, s.xy, 0.0, 0.0});
    vm.values.push_back(von_mises_stress(s));
    pr.values.push_back(pressure(s));
  }
  for (SolidField* f : {&E, &eq, &sig, &vm, &pr}) out.push_back(std::move(*f));
  return out;
}

}  // namespace slamsph
