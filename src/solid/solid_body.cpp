#include "solid/solid_body.h"

namespace slamsph {

double SolidBody::volume(std::size_t i) const {
  if (kind == BodyKind::Elastic && i < F.size()) return V0[i] * det(F[i]);
  return V0[i];
}

}  // namespace slamsph
