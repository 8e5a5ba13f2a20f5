#include "core/kernel.h"

#include <stdexcept>

namespace slamsph {

Kernel::Kernel(KernelType type, double h) : type_(type), h_(h), inv_h_(1.0 / h) {
  const double pi = std::numbers::pi;
  // 2D normalisations: Wendland C2 7/(4 pi h^2); cubic B-spline 10/(7 pi h^2).
  norm_ = type == KernelType::WendlandC2 ? 7.0 / (4.0 * pi * h * h) : 10.0 / (7.0 * pi * h * h);
  norm_h_ = norm_ * inv_h_;
  norm_h2_ = norm_ * inv_h_ * inv_h_;
  norm_h2_5_ = norm_ * inv_h_ * inv_h_ * (-5.0);
}

KernelType kernel_type_from_name(const std::string& name) {
  if (name == "wendland_c2") return KernelType::WendlandC2;
  if (name == "cubic_spline") return KernelType::CubicSpline;
  throw std::invalid_argument("unknown kernel '" + name + "'");
}

std::string kernel_name(KernelType t) {
  return t == KernelType::WendlandC2 ? "wendland_c2" : "cubic_spline";
}

}  // namespace slamsph
